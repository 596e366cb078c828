package org.parpe.sim.grade;

import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/** The centre-of-mass path of a run, read from the {@code com_x}, {@code com_y} columns of its trace. */
final class TracePath {
    /** The most points a path keeps: enough for a map, small enough for a page of thirty paths. */
    static final int MAX_POINTS = 300;

    private TracePath() {
    }

    /** x, y pairs of at most {@link #MAX_POINTS} rows spread evenly over the trace (the last one kept); none without the columns. */
    static double[] read(Path trace) throws IOException {
        List<double[]> all = new ArrayList<>();
        try (BufferedReader r = Files.newBufferedReader(trace, StandardCharsets.UTF_8)) {
            String header = r.readLine();
            List<String> names = header == null ? List.of() : Arrays.asList(header.split(","));
            int x = names.indexOf("com_x");
            int y = names.indexOf("com_y");
            if (x < 0 || y < 0) {
                return new double[0];
            }
            for (String line = r.readLine(); line != null; line = r.readLine()) {
                String[] cells = line.split(",");
                if (cells.length > Math.max(x, y)) {
                    double px = parse(cells[x]);
                    double py = parse(cells[y]);
                    if (Double.isFinite(px) && Double.isFinite(py)) {
                        all.add(new double[] {px, py});
                    }
                }
            }
        }
        int n = Math.min(all.size(), MAX_POINTS);
        double[] out = new double[2 * n];
        for (int k = 0; k < n; k++) {
            double[] p = all.get(n == 1 ? 0 : (int) ((long) k * (all.size() - 1) / (n - 1)));
            out[2 * k] = p[0];
            out[2 * k + 1] = p[1];
        }
        return out;
    }

    private static double parse(String s) {
        try {
            return Double.parseDouble(s);
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }
}
