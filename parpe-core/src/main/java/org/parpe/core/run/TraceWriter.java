package org.parpe.core.run;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Writes the CSV trace of PARSL.md §11: header {@code time,m<ID>,…} plus any extra columns,
 * then one row per tick, every number as {@code %.6f} with {@code .} as the decimal separator.
 */
public final class TraceWriter implements JointSink {
    private final Writer out;
    private final List<TraceColumns> extra = new ArrayList<>();
    private final StringBuilder row = new StringBuilder(256);
    private double[][] buffers = new double[0][];

    /** A trace written to {@code out} (flushed at the end of the run, not closed). */
    public TraceWriter(Writer out) {
        this.out = out;
    }

    /** Adds columns after the module columns; call before the run starts. */
    public void addColumns(TraceColumns columns) {
        extra.add(columns);
    }

    @Override
    public void start(RunInfo info) {
        row.setLength(0);
        row.append("time");
        for (int id : info.moduleIds()) {
            row.append(",m").append(id);
        }
        buffers = new double[extra.size()][];
        for (int i = 0; i < extra.size(); i++) {
            String[] names = extra.get(i).names();
            buffers[i] = new double[names.length];
            for (String n : names) {
                row.append(',').append(n);
            }
        }
        row.append('\n');
        write();
    }

    @Override
    public void accept(long tick, double time, double[] commanded) {
        row.setLength(0);
        format(row, time);
        for (double v : commanded) {
            row.append(',');
            format(row, v);
        }
        for (int i = 0; i < buffers.length; i++) {
            extra.get(i).values(buffers[i]);
            for (double v : buffers[i]) {
                row.append(',');
                format(row, v);
            }
        }
        row.append('\n');
        write();
    }

    @Override
    public void finish(RunOutcome outcome) {
        try {
            out.flush();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private void write() {
        try {
            out.append(row);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Appends {@code v} as {@code %.6f} would, without allocating in the common case; {@code -0}
     * prints as {@code 0.000000}. Values whose rounding is a near tie, and huge values, take
     * the exact slow path.
     */
    static void format(StringBuilder sb, double v) {
        double a = Math.abs(v);
        double scaled = a * 1e6;
        double frac = scaled - Math.floor(scaled);
        if (!(a < 1e9) || Math.abs(frac - 0.5) < 1e-3) {
            String s = String.format(Locale.ROOT, "%.6f", v);
            sb.append(s.equals("-0.000000") ? "0.000000" : s);
            return;
        }
        long m = Math.round(scaled);
        if (v < 0 && m != 0) {
            sb.append('-');
        }
        sb.append(m / 1_000_000).append('.');
        long f = m % 1_000_000;
        for (long d = 100_000; d > 0; d /= 10) {
            sb.append((char) ('0' + f / d % 10));
        }
    }
}
