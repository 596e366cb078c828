package org.parpe.core.load;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.parpe.core.diag.Diagnostic;

/**
 * A script as read from disk: its main text, its includes and its robot file parsed, before any
 * parameter value is known. {@link ScriptLoader#bind} makes a program of it for one set of values
 * without reading a file again, so that many runs with different values (a sweep) read the script
 * once, and a file changed or deleted after the read does not change them. Immutable: runs may
 * bind one on several threads at once.
 */
public final class ParsedScript {
    final Path file;
    final Includes.Assembled assembled;
    final List<Diagnostic> readDiagnostics;
    final RobotResolver.FileRead robotFile;

    ParsedScript(Path file, Includes.Assembled assembled, List<Diagnostic> readDiagnostics,
                 RobotResolver.FileRead robotFile) {
        this.file = file;
        this.assembled = assembled;
        this.readDiagnostics = List.copyOf(readDiagnostics);
        this.robotFile = robotFile;
    }

    /** The main file (includes and the robot file are found next to it). */
    public Path file() {
        return file;
    }

    /** Every file that was read: the script, its includes and its robot file. */
    public List<Path> files() {
        List<Path> files = new ArrayList<>(assembled.files());
        if (robotFile != null) {
            files.add(robotFile.path());
        }
        return List.copyOf(files);
    }
}
