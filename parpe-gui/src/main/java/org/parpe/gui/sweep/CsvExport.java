package org.parpe.gui.sweep;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.parpe.sim.sweep.Axis;
import org.parpe.sim.sweep.SweepCsv;
import org.parpe.sim.sweep.SweepRow;

/**
 * "Save CSV…": the rows in the engine's CSV form ({@link SweepCsv}, the same columns as
 * {@code parpe sweep --out}), written to a temporary file beside the target and moved over it,
 * so that a failed write never leaves half a file.
 */
final class CsvExport {
    private CsvExport() {
    }

    /** The header's parameter columns for {@code names} (the CSV shows only their names). */
    static List<Axis> axes(List<String> names) {
        List<Axis> axes = new ArrayList<>();
        for (String n : names) {
            axes.add(Axis.continuous(n, 0, 0));
        }
        return axes;
    }

    /** Writes {@code rows} (of a sweep of {@code runs} runs over {@code axes}) to {@code file}. */
    static void write(Path file, List<Axis> axes, List<SweepRow> rows, int runs) throws IOException {
        Path dir = file.toAbsolutePath().getParent();
        Path tmp = Files.createTempFile(dir, "." + file.getFileName(), ".tmp");
        try {
            try (BufferedWriter w = Files.newBufferedWriter(tmp, StandardCharsets.UTF_8)) {
                w.write(SweepCsv.header(axes));
                w.write('\n');
                for (SweepRow r : rows) {
                    w.write(SweepCsv.line(r, runs));
                    w.write('\n');
                }
            }
            Files.move(tmp, file, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        } finally {
            Files.deleteIfExists(tmp);
        }
    }
}
