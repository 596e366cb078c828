package org.parpe.cli.export;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Map;
import org.parpe.cli.options.UsageException;
import org.parpe.serial.export.ProgramExport;
import org.parpe.sim.bridge.Export;

/**
 * Writes an export's files into a folder by the output rules (docs/cli.md). Only files of the
 * export's own names are replaced, and a sketch ({@code .ino}) only if it is still the one PARPE
 * generated: board code a user added to it is never overwritten. The folder changes as one:
 * every file is written in full to a random temporary name before any replaces its old version
 * ({@link Export#write}), so a full disk leaves the old export whole, never a new header
 * with old tables.
 */
final class ExportFiles {
    private ExportFiles() {
    }

    static void write(Path dir, Map<String, String> files) throws IOException, UsageException {
        String refused = Export.refusal(dir, files.keySet());
        if (refused != null) {
            throw new UsageException("--out: " + refused);
        }
        String edited = ProgramExport.editedSketch(dir, files.keySet());
        if (edited != null) {
            throw new UsageException(edited);
        }
        Export.write(dir, files);
    }
}
