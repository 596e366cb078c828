package org.parpe.sim.grade;

import java.util.List;
import java.util.Locale;
import org.parpe.core.io.CsvCells;
import org.parpe.sim.world.Challenge;
import org.parpe.sim.text.SimMsg;

/**
 * The report's table as CSV: one line per student in rank order, text cells quoted and made safe
 * for spreadsheets ({@link CsvCells}), numbers with fixed decimals so that the same runs give the
 * same bytes. The HTML page is {@link ReportPage}.
 */
public final class Report {
    public static final String HEADER = "rank,student,script,score,parts,forward_m,distance_m,fell,time_s,trace,problem";

    private Report() {
    }

    /** The CSV of {@code rows} (already in rank order). */
    public static String csv(List<Row> rows) {
        StringBuilder b = new StringBuilder(HEADER).append('\n');
        for (Row r : rows) {
            Outcome o = r.outcome();
            b.append(r.rank() > 0 ? Integer.toString(r.rank()) : "").append(',');
            b.append(CsvCells.quoted(r.student().name())).append(',');
            b.append(CsvCells.quoted(r.student().script() == null ? "" : r.student().script().toString())).append(',');
            if (o.ranked()) {
                b.append(String.format(Locale.ROOT, "%.1f,%s,%.3f,%.3f,%d,%.2f,", o.score(), CsvCells.quoted(o.parts()),
                        o.dx(), o.distance(), o.fell() ? 1 : 0, o.time()));
            } else {
                b.append(",,,,,,");
            }
            b.append(CsvCells.quoted(r.trace())).append(',').append(CsvCells.quoted(o.reason())).append('\n');
        }
        return b.toString();
    }

    /** A one-line summary for the terminal: how many were ranked and how many failed. */
    public static String summary(List<Row> rows, Challenge c) {
        long ranked = rows.stream().filter(r -> r.rank() > 0).count();
        return SimMsg.GRADE_SUMMARY.text(rows.size(), ranked, rows.size() - ranked, c.file().getFileName(), c.robot(),
                String.format(Locale.ROOT, "%.0f", c.duration()));
    }
}
