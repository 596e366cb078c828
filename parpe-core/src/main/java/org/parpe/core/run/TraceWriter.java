package org.parpe.core.run;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.ArrayList;
import java.util.List;

/**
 * Writes the CSV trace of PARSL.md §11: header {@code time,m<ID>,…} plus any extra columns,
 * then one row per tick, every number as C's {@code %.6f} (exact, half-even, §13 rule 23) with
 * {@code .} as the decimal separator.
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

    /** Above this the integer part no longer fits a {@code long}: such values take the exact slow path. */
    private static final double LONG_LIMIT = 0x1p63;

    /**
     * Appends {@code v} as C's {@code printf("%.6f")} does (PARSL.md §13 rule 23): the exact
     * decimal value of the double, rounded half-even to six decimals; {@code -0} (and anything
     * that rounds to zero) prints as {@code 0.000000}. Exact and allocation-free below 2^63:
     * the fraction {@code f} of a double is exact, and {@link Math#fma} gives the exact sign of
     * {@code f·10^6 − m} and {@code f·10^6 − (m + ½)}, so ties are recognised exactly
     * ({@code String.format} would round the shortest decimal representation half-up instead).
     */
    static void format(StringBuilder sb, double v) {
        double a = Math.abs(v);
        if (!(a < LONG_LIMIT)) {
            slow(sb, v);
            return;
        }
        long ip = (long) a;
        double f = a - ip;
        long m = (long) (f * 1e6);
        if (Math.fma(f, 1e6, -m) < 0) {
            m--; // f·10^6 rounded up to the integer m
        }
        double tie = Math.fma(f, 1e6, -(m + 0.5));
        if (tie > 0 || (tie == 0 && (m & 1) == 1)) {
            m++;
        }
        if (m == 1_000_000) {
            ip++;
            m = 0;
        }
        if (v < 0 && (ip != 0 || m != 0)) {
            sb.append('-');
        }
        sb.append(ip).append('.');
        for (long d = 100_000; d > 0; d /= 10) {
            sb.append((char) ('0' + m / d % 10));
        }
    }

    private static void slow(StringBuilder sb, double v) {
        if (!Double.isFinite(v)) {
            // only extra columns can hold these (a module that sent no reading is NaN); as before
            sb.append(Double.isNaN(v) ? "NaN" : v > 0 ? "Infinity" : "-Infinity");
        } else {
            sb.append(new BigDecimal(v).setScale(6, RoundingMode.HALF_EVEN).toPlainString());
        }
    }
}
