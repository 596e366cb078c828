package org.parpe.gui.grid;

import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.parpe.gui.grid.TableEdits.At;

/**
 * What the grid writes into a selection: a travelling wave, or cells pasted from a spreadsheet.
 * A selection is the rectangle of rows {@code r0..r1} and columns {@code c0..c1} (inclusive).
 */
public final class Fill {
    private Fill() {
    }

    /** A rectangle of cells, rows {@code r0..r1} and columns {@code c0..c1}, inclusive. */
    public record Selection(int r0, int c0, int r1, int c1) {

        /** The number of rows. */
        public int rows() {
            return r1 - r0 + 1;
        }

        /** The number of columns. */
        public int columns() {
            return c1 - c0 + 1;
        }

        /** Whether it holds row {@code r}, column {@code c}. */
        public boolean contains(int r, int c) {
            return r >= r0 && r <= r1 && c >= c0 && c <= c1;
        }
    }

    /**
     * The travelling wave over {@code s}: the cell at row {@code r}, column {@code c}, both counted
     * from the selection's top-left cell, gets {@code A·sin(2π(r/rows + c·φ))} degrees, where
     * {@code rows} is the number of selected rows, rounded to a tenth of a degree.
     */
    public static Map<At, String> wave(Selection s, double amplitude, double phaseStep) {
        Map<At, String> out = new LinkedHashMap<>();
        for (int r = 0; r < s.rows(); r++) {
            for (int c = 0; c < s.columns(); c++) {
                double v = amplitude * Math.sin(2 * Math.PI * ((double) r / s.rows() + c * phaseStep));
                out.put(new At(s.r0() + r, s.c0() + c), number(v));
            }
        }
        return out;
    }

    /** {@code v} rounded half-up to a tenth, without a trailing {@code .0}; never {@code -0}. */
    static String number(double v) {
        BigDecimal d = BigDecimal.valueOf(v).setScale(1, RoundingMode.HALF_UP).stripTrailingZeros();
        if (d.signum() == 0) {
            return "0";
        }
        return d.scale() < 0 ? d.setScale(0).toPlainString() : d.toPlainString();
    }

    /**
     * The cells of {@code clip} (lines of tab-separated cells, as spreadsheets copy them; a line
     * without a tab is split at top-level commas) placed from the selection's top-left cell. A
     * single cell fills the whole selection. Cells that would fall outside the table
     * ({@code rows} by {@code columns}) are left out; {@code outside} counts them. Empty
     * cells leave the cell under them as it is.
     */
    public static Map<At, String> paste(String clip, Selection s, int rows, int columns, int[] outside) {
        List<List<String>> cells = parse(clip);
        Map<At, String> out = new LinkedHashMap<>();
        if (cells.size() == 1 && cells.get(0).size() == 1) {
            for (int r = s.r0(); r <= s.r1(); r++) {
                for (int c = s.c0(); c <= s.c1(); c++) {
                    out.put(new At(r, c), cells.get(0).get(0));
                }
            }
            return out;
        }
        for (int r = 0; r < cells.size(); r++) {
            for (int c = 0; c < cells.get(r).size(); c++) {
                int rr = s.r0() + r;
                int cc = s.c0() + c;
                String v = cells.get(r).get(c);
                if (v.isEmpty()) {
                    continue;
                }
                if (rr < rows && cc < columns) {
                    out.put(new At(rr, cc), v);
                } else {
                    outside[0]++;
                }
            }
        }
        return out;
    }

    /** The rows of cells in {@code clip}; blank lines and empty cells at the end of a line are dropped. */
    static List<List<String>> parse(String clip) {
        List<List<String>> out = new ArrayList<>();
        for (String line : clip.replace("\r\n", "\n").replace('\r', '\n').split("\n")) {
            if (line.isBlank()) {
                continue;
            }
            List<String> cells = new ArrayList<>(line.indexOf('\t') >= 0
                    ? List.of(line.split("\t", -1)).stream().map(String::trim).toList()
                    : Split.texts(line, ','));
            while (cells.size() > 1 && cells.get(cells.size() - 1).isEmpty()) {
                cells.remove(cells.size() - 1);
            }
            out.add(cells);
        }
        return out;
    }
}
