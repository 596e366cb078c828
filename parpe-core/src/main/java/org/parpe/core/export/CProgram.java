package org.parpe.core.export;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.math.RoundingMode;
import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.export.CLayout.AutCol;
import org.parpe.core.export.CLayout.EntryCol;
import org.parpe.core.export.CLayout.InstCol;
import org.parpe.core.export.CLayout.StateCol;
import org.parpe.core.export.CLayout.VargCol;
import org.parpe.core.expr.Expression;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.Conditional;
import org.parpe.core.model.Instance;
import org.parpe.core.model.MainEntry;
import org.parpe.core.model.Program;
import org.parpe.core.model.StateDef;
import org.parpe.core.model.Timing;
import org.parpe.core.sensor.Channel;

/**
 * A loaded program as the C tables of the embedded runtime ({@code parsl_rt.h}): one C function
 * per expression, and the main entries, instances (groups resolved as the interpreter's
 * {@code EntryPlan} does), automata and states as constant {@code int16_t} tables. Per-module
 * state is pooled: only one {@code <main>} entry runs at a time, so the RAM is sized by the
 * largest entry. {@link CExport} builds it once the program has passed its checks.
 */
public final class CProgram {
    private final Program program;
    private final double dt;
    private final Map<Expression, Integer> exprIds = new IdentityHashMap<>();
    /** Expressions that are a state's angle, and those used otherwise: only the first alone keep values per module. */
    private final java.util.Set<Integer> angles = new java.util.HashSet<>();
    private final java.util.Set<Integer> notAngles = new java.util.HashSet<>();
    private int keptValues = -1;
    private final List<Expression> exprs = new ArrayList<>();
    private final List<SourcePos> places = new ArrayList<>();
    private final Map<String, Integer> files = new LinkedHashMap<>();
    /** The {@code group} attribute of every instance row, as written (for the overlap warning). */
    private final List<String> instGroups = new ArrayList<>();
    private final int[] ids;
    private final int[] sensorSlot;
    private int sensorCount;
    private final Tables t = new Tables();
    /** Sizes of the pooled state, taken over all entries. */
    private int maxInstances;
    private int maxPool;
    private int maxDurations;
    private int maxMacros;

    private CProgram(Program program, double dt) {
        this.program = program;
        this.dt = dt;
        this.ids = program.moduleIds();
        this.sensorSlot = new int[ids.length * Channel.count()];
    }

    /** Builds the tables of {@code program} run with tick {@code dt}. */
    public static CProgram of(Program program, double dt) {
        CProgram c = new CProgram(program, dt);
        c.build();
        return c;
    }

    /** The number of modules. */
    public int modules() {
        return ids.length;
    }

    /** The number of sensor readings kept in RAM (carried channels only). */
    public int sensorReadings() {
        return sensorCount;
    }

    /** Largest number of instances of one entry. */
    public int instances() {
        return Math.max(1, maxInstances);
    }

    /** Largest number of module states of one entry (one per module of each instance). */
    public int moduleStates() {
        return Math.max(1, maxPool);
    }

    /** Largest number of state durations kept for one entry. */
    public int durations() {
        return Math.max(1, maxDurations);
    }

    /** The expressions the program evaluates, each once, in the order of their C functions. */
    public List<Expression> expressions() {
        return Collections.unmodifiableList(exprs);
    }

    /**
     * Values of sub-expressions kept per module ({@link ModuleConstants}), one per position of
     * every instance's group, where {@code PARSL_KEEP} is defined (boards with 64-bit doubles).
     */
    public long keptValues() {
        if (keptValues < 0) {
            source();
        }
        return keptValues == 0 ? 0 : (long) keptValues * Math.max(1, t.mod.size());
    }

    /** Number of controls. */
    public int controls() {
        return program.controls().size();
    }

    /** Largest number of macros of a behavior. */
    public int macros() {
        return Math.max(1, maxMacros);
    }

    /** Bytes of the constant tables, for {@code int16_t} entries and {@code doubleBytes} per double. */
    public long tableBytes(int doubleBytes) {
        return 2L * t.cells() + (long) doubleBytes * 3 * Math.max(1, controls()) + 6L * places.size();
    }

    private void build() {
        for (int i = 0; i < ids.length; i++) {
            for (Channel c : Channel.values()) {
                int slot = i * Channel.count() + c.ordinal();
                sensorSlot[slot] = program.robot().carries(ids[i], c.sensor()) ? sensorCount++ : -1;
            }
        }
        for (Automaton a : program.automata()) {
            t.aut.add(new CLayout.Row<>(AutCol.class).set(AutCol.NS, a.states().size())
                    .set(AutCol.STATES, t.state.size()).set(AutCol.PERMODULE, perModule(a) ? 1 : 0).done());
            for (int s = 0; s < a.states().size(); s++) {
                StateDef st = a.states().get(s);
                Timing tm = a.times().get(s);
                t.state.add(new CLayout.Row<>(StateCol.class).set(StateCol.INTERP, st.interp().ordinal())
                        .set(StateCol.NANGLES, st.angles().size()).set(StateCol.ANGLES, t.angle.size())
                        .set(StateCol.TIME, id(tm.duration())).set(StateCol.EXIT, tm.exit() == null ? -1 : id(tm.exit()))
                        .done());
                st.angles().forEach(e -> {
                    t.angle.add(index(e));
                    angles.add(index(e));
                });
            }
        }
        if (program.main() != null) {
            for (MainEntry e : program.main().entries()) {
                entry(e);
            }
        }
    }

    private static boolean perModule(Automaton a) {
        return a.times().stream().anyMatch(tm -> tm.duration().perModule());
    }

    private void entry(MainEntry e) {
        Behavior b = e.definition();
        int first = t.inst.size();
        int vargs = t.varg.size();
        for (MainEntry.MacroArg a : e.macros()) {
            if (a.value() != null) {
                t.varg.add(new CLayout.Row<>(VargCol.class).set(VargCol.SLOT, b.macros().indexOf(a.name()))
                        .set(VargCol.EXPR, id(a.value())).done());
            }
        }
        int[] pool = {0, 0};
        for (MainEntry.Binding binding : e.bindings()) {
            instance(binding, pool);
        }
        int n = t.inst.size() - first;
        t.entry.add(new CLayout.Row<>(EntryCol.class).set(EntryCol.FIRST, first).set(EntryCol.NINST, n)
                .set(EntryCol.TIME, e.time() == null ? -1 : id(e.time()))
                .set(EntryCol.EXIT, e.exit() == null ? -1 : id(e.exit()))
                .set(EntryCol.VARGS, vargs).set(EntryCol.NVARGS, t.varg.size() - vargs).done());
        maxInstances = Math.max(maxInstances, n);
        maxPool = Math.max(maxPool, pool[0]);
        maxDurations = Math.max(maxDurations, pool[1]);
        maxMacros = Math.max(maxMacros, b.macros().size());
    }

    private void instance(MainEntry.Binding binding, int[] pool) {
        Instance i = binding.instance();
        boolean mirror = binding.mirrored();
        List<Integer> group = binding.group().modules();
        int automaton = program.automata().indexOf(binding.automaton());
        List<Conditional> conds = binding.conditions();
        int mod = t.mod.size();
        for (int id : group) {
            t.mod.add(java.util.Arrays.binarySearch(ids, id));
        }
        int cond = t.cond.size();
        conds.forEach(c -> t.cond.add(id(c.condition())));
        int ns = t.aut.get(automaton)[AutCol.NS.ordinal()];
        t.inst.add(new CLayout.Row<>(InstCol.class).set(InstCol.AUT, automaton).set(InstCol.MIRROR, mirror ? 1 : 0)
                .set(InstCol.N, group.size()).set(InstCol.MOD, mod).set(InstCol.COND, cond)
                .set(InstCol.NCOND, conds.size()).set(InstCol.PHASE, opt(i.phase()))
                .set(InstCol.OFFSET, opt(i.offset())).set(InstCol.PERIOD, opt(i.period()))
                .set(InstCol.START, opt(i.start())).set(InstCol.CYCLES, opt(i.cycles()))
                .set(InstCol.POOL, pool[0]).set(InstCol.TBUF, pool[1]).set(InstCol.POS, place(i.pos())).done());
        instGroups.add(i.group());
        pool[0] += group.size();
        pool[1] += ns;
    }

    private int opt(Expression e) {
        return e == null ? -1 : id(e);
    }

    /** The number of {@code e}, not (only) a state's angle. */
    private int id(Expression e) {
        int i = index(e);
        notAngles.add(i);
        return i;
    }

    private int index(Expression e) {
        Integer i = exprIds.get(e);
        if (i == null) {
            i = exprs.size();
            exprIds.put(e, i);
            exprs.add(e);
            places.add(e.pos());
        }
        return i;
    }

    private int place(SourcePos pos) {
        places.add(pos);
        return places.size() - 1;
    }

    /** {@code parsl_program.h}: the sizes the runtime's state is declared with. */
    public String header() {
        StringBuilder h = new StringBuilder();
        h.append("/* Generated by parpe export from ").append(CText.comment(program.file())).append(". */\n");
        h.append("#ifndef PARSL_PROGRAM_H\n#define PARSL_PROGRAM_H\n\n");
        h.append("#define PARSL_FILE ").append(CText.literal(program.file())).append("\n");
        define(h, "PARSL_N", ids.length, "modules");
        define(h, "PARSL_NC", controls(), "controls");
        define(h, "PARSL_NC1", Math.max(1, controls()), "");
        define(h, "PARSL_NS", sensorCount, "sensor readings (carried channels)");
        define(h, "PARSL_NS1", Math.max(1, sensorCount), "");
        define(h, "PARSL_NE", t.entry.size(), "main entries");
        define(h, "PARSL_NA", t.aut.size(), "automata");
        define(h, "PARSL_NI1", instances(), "instances of the largest entry");
        define(h, "PARSL_POOL1", moduleStates(), "module states of the largest entry");
        define(h, "PARSL_TPOOL1", durations(), "state durations of the largest entry");
        define(h, "PARSL_NM1", macros(), "macros of the largest behavior");
        long cycles = program.main() == null ? 0 : program.main().cycles();
        h.append("#define PARSL_MAIN_CYCLES (").append(cycles).append("L) /* -1: forever */\n");
        h.append("#define PARSL_DT ").append(CExpressions.literal(dt)).append(" /* the tick, ")
                .append(String.format(Locale.ROOT, "%s", dt)).append(" s */\n");
        long[] exact = exactTick(dt);
        h.append("/* the tick as PARSL_DT_S + PARSL_DT_F / PARSL_DT_DEN s, for boards that keep time in integers */\n");
        h.append("#define PARSL_DT_S ").append(exact[0]).append("UL\n");
        h.append("#define PARSL_DT_F ").append(exact[1]).append("UL\n");
        h.append("#define PARSL_DT_DEN ").append(exact[2]).append("UL\n");
        CLayout.appendC(h);
        h.append("\n#endif\n");
        return h.toString();
    }

    /**
     * The tick {@code dt} as whole seconds, a numerator and a power-of-ten denominator of at most
     * 10^9 (lowest terms): the decimal the user wrote (Java's shortest decimal of {@code dt}),
     * rounded to the nanosecond if it has more digits.
     */
    static long[] exactTick(double dt) {
        BigDecimal d = new BigDecimal(Double.toString(dt));
        if (d.scale() > 9) {
            d = d.setScale(9, RoundingMode.HALF_EVEN).max(BigDecimal.ONE.movePointLeft(9));
        }
        BigInteger whole = d.toBigInteger();
        int scale = Math.max(0, d.scale());
        BigInteger den = BigInteger.TEN.pow(scale);
        BigInteger num = d.subtract(new BigDecimal(whole)).movePointRight(scale).toBigIntegerExact();
        BigInteger g = num.gcd(den);
        return new long[] {whole.longValueExact(), num.divide(g).longValueExact(), den.divide(g).longValueExact()};
    }

    private static void define(StringBuilder h, String name, int value, String what) {
        h.append("#define ").append(name).append(' ').append(value);
        h.append(what.isEmpty() ? "\n" : " /* " + what + " */\n");
    }

    /** {@code parsl_program.c}: the expressions and the tables. */
    public String source() {
        StringBuilder c = new StringBuilder();
        c.append("/* Generated by parpe export from ").append(CText.comment(program.file())).append(". */\n");
        c.append("#include \"parsl_rt.h\"\n#include \"parsl_maths.h\"\n#include <math.h>\n#include <string.h>\n\n");
        c.append(CText.PRELUDE);
        StringBuilder functions = new StringBuilder();
        CExpressions.Kept kept = new CExpressions.Kept();
        int[] keptFirst = new int[exprs.size()];
        for (int i = 0; i < exprs.size(); i++) {
            Expression e = exprs.get(i);
            String where = e.pos().line() == 0 ? "default" : e.pos().toString();
            functions.append("/* ").append(CText.comment(where)).append(": ").append(CText.comment(e.text())).append(" */\n");
            boolean angle = angles.contains(i) && !notAngles.contains(i);
            keptFirst[i] = angle ? kept.count() : -1;
            functions.append(CExpressions.function("x" + i, e.root(), sensorSlot, angle ? kept : null)).append('\n');
        }
        keptValues = kept.count();
        if (keptValues > 0) {
            int positions = Math.max(1, t.mod.size());
            c.append(String.format(java.util.Locale.ROOT, CText.KEEP, keptValues, positions, keptValues, positions));
        }
        c.append(functions);
        c.append(CFastForm.source(program.automata(), exprIds::get, x -> keptFirst[x], sensorSlot));
        c.append("PARSL_NO_TABLE double parsl_expr(parsl_rt *r, int16_t x)\n{\n    switch (x) {\n");
        for (int i = 0; i < exprs.size(); i++) {
            c.append("    case ").append(i).append(": return x").append(i).append("(r);\n");
        }
        c.append("    default: return 0;\n    }\n}\n\n");
        new CTables(program, ids, sensorSlot, t, places, files, exprs.stream().map(Expression::text).toList(),
                instGroups).append(c);
        return c.toString();
    }

    /** The rows of the generated tables, in the column order of {@link CLayout}. */
    static final class Tables {
        final List<int[]> entry = new ArrayList<>();
        final List<int[]> varg = new ArrayList<>();
        final List<int[]> inst = new ArrayList<>();
        final List<Integer> mod = new ArrayList<>();
        final List<Integer> cond = new ArrayList<>();
        final List<int[]> aut = new ArrayList<>();
        final List<int[]> state = new ArrayList<>();
        final List<Integer> angle = new ArrayList<>();

        long cells() {
            return (long) CLayout.width(EntryCol.class) * entry.size() + (long) CLayout.width(VargCol.class) * varg.size()
                    + (long) CLayout.width(InstCol.class) * inst.size() + mod.size() + cond.size()
                    + (long) CLayout.width(AutCol.class) * aut.size() + (long) CLayout.width(StateCol.class) * state.size()
                    + angle.size();
        }

        /** The largest value in any table, which must fit an {@code int16_t}. */
        int largest() {
            int m = Math.max(mod.size(), Math.max(cond.size(), angle.size()));
            for (List<int[]> rows : List.of(entry, varg, inst, aut, state)) {
                m = Math.max(m, rows.size());
                for (int[] r : rows) {
                    for (int v : r) {
                        m = Math.max(m, v);
                    }
                }
            }
            return m;
        }
    }

    /** The largest value the tables hold (rows, offsets, expression ids). */
    public int largestTableValue() {
        return Math.max(t.largest(), Math.max(exprs.size(), places.size()));
    }
}
