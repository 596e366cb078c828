package org.parpe.core.io;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;

/**
 * CSV cells a spreadsheet would not evaluate. A cell that begins with {@code =}, {@code +},
 * {@code -}, {@code @}, a tab or a carriage return is taken for a formula by Excel and
 * LibreOffice Calc (OWASP, "CSV Injection"); such a cell gets a leading apostrophe, which the
 * spreadsheet shows as text. A number ({@code -1.5}, {@code +2}, {@code -3e-4}) is left as it
 * is, so numeric columns stay numeric. Every CSV PARPE writes passes its text cells through
 * {@link #safe}, and {@code merge} passes every cell of the lines it copies through
 * {@link #safeLine}.
 */
public final class CsvCells {
    private static final Pattern NUMBER = Pattern.compile("[+-]?(\\d+(\\.\\d*)?|\\.\\d+)([eE][+-]?\\d+)?");

    private CsvCells() {
    }

    /** Whether a spreadsheet would evaluate {@code cell} (its text, unquoted). */
    public static boolean formula(String cell) {
        if (cell.isEmpty()) {
            return false;
        }
        char c = cell.charAt(0);
        boolean trigger = c == '=' || c == '+' || c == '-' || c == '@' || c == '\t' || c == '\r';
        return trigger && !NUMBER.matcher(cell).matches();
    }

    /** {@code cell} (its text, unquoted) made safe: with a leading apostrophe if it would be evaluated. */
    public static String safe(String cell) {
        return formula(cell) ? "'" + cell : cell;
    }

    /** {@code cell} made {@link #safe} and quoted, its quotes doubled: any text, commas and newlines included. */
    public static String quoted(String cell) {
        return '"' + safe(cell).replace("\"", "\"\"") + '"';
    }

    /**
     * A CSV line with every cell made {@link #safe}; quoted cells stay quoted (and cells that
     * need quotes get them), so a line that is already safe comes back unchanged.
     */
    public static String safeLine(String line) {
        List<String> cells = new ArrayList<>();
        List<Boolean> quoted = new ArrayList<>();
        StringBuilder cell = new StringBuilder();
        boolean inQuotes = false;
        boolean wasQuoted = false;
        for (int i = 0; i < line.length(); i++) {
            char c = line.charAt(i);
            if (inQuotes) {
                if (c == '"' && i + 1 < line.length() && line.charAt(i + 1) == '"') {
                    cell.append('"');
                    i++;
                } else if (c == '"') {
                    inQuotes = false;
                } else {
                    cell.append(c);
                }
            } else if (c == '"') {
                inQuotes = true;
                wasQuoted = true;
            } else if (c == ',') {
                cells.add(cell.toString());
                quoted.add(wasQuoted);
                cell.setLength(0);
                wasQuoted = false;
            } else {
                cell.append(c);
            }
        }
        cells.add(cell.toString());
        quoted.add(wasQuoted);
        StringBuilder out = new StringBuilder();
        for (int i = 0; i < cells.size(); i++) {
            if (i > 0) {
                out.append(',');
            }
            String s = safe(cells.get(i));
            if (quoted.get(i) || s.indexOf(',') >= 0 || s.indexOf('"') >= 0 || s.indexOf('\n') >= 0 || s.indexOf('\r') >= 0) {
                out.append('"').append(s.replace("\"", "\"\"")).append('"');
            } else {
                out.append(s);
            }
        }
        return out.toString();
    }
}
