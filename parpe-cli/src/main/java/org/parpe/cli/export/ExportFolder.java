package org.parpe.cli.export;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.export.Board;
import org.parpe.core.model.Program;
import org.parpe.serial.export.ProgramExport;

/** Writes a complete host export (runtime, tables, trace program) for tools such as the benchmark. */
public final class ExportFolder {
    private ExportFolder() {
    }

    /**
     * Writes {@code program} as C for the host into the existing folder {@code dir}.
     *
     * @throws IllegalArgumentException if the program cannot be exported (the message lists why)
     */
    public static void writeHost(Program program, double dt, Path dir) throws IOException {
        DiagnosticList d = new DiagnosticList();
        ProgramExport.Result r = ProgramExport.export(program,
                new ProgramExport.Request(ProgramExport.Target.C, Board.HOST, dt, null), d);
        if (r == null) {
            throw new IllegalArgumentException(ExportCommand.lines(d.all()));
        }
        for (Map.Entry<String, String> f : r.files().entrySet()) {
            Files.writeString(dir.resolve(f.getKey()), f.getValue(), StandardCharsets.UTF_8);
        }
    }
}
