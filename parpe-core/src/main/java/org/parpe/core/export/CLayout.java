package org.parpe.core.export;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.parpe.core.model.Control;
import org.parpe.core.model.Interp;
import org.parpe.core.sensor.Channel;

/**
 * The layout of the generated tables, declared once: {@link CTables} writes each row by these columns, and
 * {@code parsl_program.h} gets the runtime's column names and table widths from here (the runtime's C files
 * declare none of them), together with the codes of the Java enums the tables store by ordinal.
 */
final class CLayout {
    /** Columns of {@code parsl_control}. */
    enum ControlCol { TYPE, WORDS, NWORDS }

    /** Columns of {@code parsl_entry}: a {@code <main>} entry. */
    enum EntryCol { FIRST, NINST, TIME, EXIT, VARGS, NVARGS }

    /** Columns of {@code parsl_varg}: an expression-valued macro of an entry. */
    enum VargCol { SLOT, EXPR }

    /** Columns of {@code parsl_inst}: an automaton instance of an entry. */
    enum InstCol { AUT, MIRROR, N, MOD, COND, NCOND, PHASE, OFFSET, PERIOD, START, CYCLES, POOL, TBUF, POS }

    /** Columns of {@code parsl_aut}: an automaton. */
    enum AutCol { NS, STATES, PERMODULE }

    /** Columns of {@code parsl_state}: a state of an automaton. */
    enum StateCol { INTERP, NANGLES, ANGLES, TIME, EXIT }

    /** A table: its C width macro, the prefix of its column names, its columns. */
    record Table(String width, String prefix, Class<? extends Enum<?>> columns) {
        int cols() {
            return columns.getEnumConstants().length;
        }
    }

    static final List<Table> TABLES = List.of(
            new Table("PARSL_CONTROL_COLS", "PARSL_C_", ControlCol.class),
            new Table("PARSL_ENTRY_COLS", "PARSL_E_", EntryCol.class),
            new Table("PARSL_VARG_COLS", "PARSL_V_", VargCol.class),
            new Table("PARSL_INST_COLS", "PARSL_I_", InstCol.class),
            new Table("PARSL_AUT_COLS", "PARSL_A_", AutCol.class),
            new Table("PARSL_STATE_COLS", "PARSL_S_", StateCol.class));

    private CLayout() {
    }

    /** The width of the table whose columns are {@code cols}. */
    static <E extends Enum<E>> int width(Class<E> cols) {
        return cols.getEnumConstants().length;
    }

    /** One row under construction; {@link #done} refuses a row with a column left unset. */
    static final class Row<E extends Enum<E>> {
        private final Class<E> cols;
        private final int[] values;
        private final boolean[] set;

        Row(Class<E> cols) {
            this.cols = cols;
            this.values = new int[width(cols)];
            this.set = new boolean[values.length];
        }

        Row<E> set(E col, int value) {
            values[col.ordinal()] = value;
            set[col.ordinal()] = true;
            return this;
        }

        int[] done() {
            for (E col : cols.getEnumConstants()) {
                if (!set[col.ordinal()]) {
                    throw new IllegalStateException("column " + col + " of " + cols.getSimpleName() + " is not set");
                }
            }
            return values.clone();
        }
    }

    /** The C declarations of the layout, for {@code parsl_program.h}. */
    static void appendC(StringBuilder h) {
        h.append("\n/* The tables' layout (org.parpe.core.export.CLayout): widths and column indices. */\n");
        for (Table t : TABLES) {
            h.append("#define ").append(t.width()).append(' ').append(t.cols()).append('\n');
            enumeration(h, t.prefix(), t.columns().getEnumConstants(), null);
        }
        h.append("/* Codes stored by ordinal: sensor channels, control types, profiles. */\n");
        enumeration(h, "PARSL_", Channel.values(), "PARSL_CHANNELS");
        enumeration(h, "PARSL_CT_", Control.ControlType.values(), null);
        enumeration(h, "PARSL_", Interp.values(), null);
    }

    private static void enumeration(StringBuilder h, String prefix, Enum<?>[] values, String count) {
        h.append("enum { ");
        String[] names = Arrays.stream(values).map(v -> prefix + v.name().toUpperCase(Locale.ROOT))
                .toArray(String[]::new);
        h.append(String.join(", ", names));
        if (count != null) {
            h.append(", ").append(count);
        }
        h.append(" };\n");
    }
}
