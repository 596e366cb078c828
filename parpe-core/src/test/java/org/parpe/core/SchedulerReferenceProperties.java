package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.StringWriter;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import org.parpe.core.run.Engine;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.TraceWriter;

/**
 * Differential test of the scheduler: random single-instance programs (states, `times` that may
 * read {@code $phase}/{@code $cycle}, targets that do, zero durations, `cycles` ≤ 0, fractional
 * and unlimited, phases, offsets, periods, {@code <main cycles>}) run on the {@link Engine} and
 * on {@link Reference}, a slow re-implementation written from PARSL.md §7.1 and §13 rules 6–9
 * and 18–22. Every traced angle must agree within 1e−9; besides, a finished module is never
 * driven again within its entry, and the same program gives the same trace twice.
 */
class SchedulerReferenceProperties {
    static final double DT = 0.05;
    static final int MAX_TICKS = 400;

    /** One state: target {@code a + b·$phase + c·$cycle}, duration {@code t + tc·$cycle + tp·$phase}. */
    record State(double a, double b, double c, boolean step, double t, double tc, double tp) {
        double target(double phase, double cycle) {
            return a + b * phase + c * cycle;
        }

        double time(double phase, double cycle) {
            return t + tc * cycle + tp * phase;
        }
    }

    /** A random program: one behavior with one instance on modules 0..n-1, run by one entry. */
    record Prog(int n, List<State> states, double phase, double offset, Double period, Double cycles,
                int mainCycles, Double entryTime) {

        /** {@code dependent}: targets and `times` may read {@code $phase} and {@code $cycle}. */
        static Prog random(long seed, boolean dependent) {
            Random r = new Random(seed);
            double d = dependent ? 1 : 0;
            int ns = 1 + r.nextInt(4);
            List<State> states = new ArrayList<>();
            boolean positive = false;
            for (int i = 0; i < ns; i++) {
                double t = r.nextInt(6) == 0 ? 0 : round2(0.05 + 1.5 * r.nextDouble());
                positive |= t > 0;
                states.add(new State(round2(-90 + 180 * r.nextDouble()), r.nextInt(3) == 0 ? d * round2(-50 + 100 * r.nextDouble()) : 0,
                        r.nextInt(3) == 0 ? d * round2(-20 + 40 * r.nextDouble()) : 0, r.nextInt(5) == 0, t,
                        r.nextInt(4) == 0 ? d * round2(r.nextDouble()) : 0, r.nextInt(5) == 0 ? d * round2(r.nextDouble()) : 0));
            }
            if (!positive) {
                State s = states.get(0);
                states.set(0, new State(s.a, s.b, s.c, s.step, 0.5, s.tc, s.tp));
            }
            double[] cyc = {-1, 0, 0.25, 0.5, 1, 1.5, 2, round2(0.01 + 2.5 * r.nextDouble()), round2(0.01 + 0.5 * r.nextDouble())};
            Double cycles = r.nextInt(6) == 0 ? null : cyc[r.nextInt(cyc.length)];
            Double period = r.nextBoolean() ? null : round2(0.3 + 2 * r.nextDouble());
            Double time = cycles == null || r.nextInt(4) == 0 ? round2(0.4 + 4 * r.nextDouble()) : null;
            if (cycles != null && cycles <= 0 && r.nextBoolean()) {
                // durations that would be an error if evaluated: cycles <= 0 must not evaluate them (rule 19)
                states.replaceAll(s -> new State(s.a, s.b, s.c, s.step, 0, 0, 0));
            }
            return new Prog(1 + r.nextInt(3), states, round2(-1 + 2 * r.nextDouble()), round2(r.nextDouble()), period, cycles,
                    1 + r.nextInt(3), time);
        }

        static double round2(double v) {
            return Math.round(v * 100) / 100.0;
        }

        String script() {
            StringBuilder st = new StringBuilder();
            StringBuilder names = new StringBuilder();
            StringBuilder times = new StringBuilder();
            for (int i = 0; i < states.size(); i++) {
                State s = states.get(i);
                st.append(f("<s%d angles=\"%s + %s*$phase + %s*$cycle\"%s/>", i, num(s.a), num(s.b), num(s.c),
                        s.step ? " interp=\"step\"" : ""));
                names.append(i == 0 ? "" : ", ").append('s').append(i);
                times.append(i == 0 ? "" : ", ").append(f("%s + %s*$cycle + %s*$phase", num(s.t), num(s.tc), num(s.tp)));
            }
            String attrs = f(" phase=\"%s\" offset=\"%s\"", num(phase), num(offset)) + (period == null ? "" : f(" period=\"%s\"", num(period)))
                    + (cycles == null ? "" : f(" cycles=\"%s\"", num(cycles)));
            return f("<program><robot><structure><g elements=\"0..%d\"/></structure></robot>"
                    + "<main cycles=\"%d\"><b%s/></main><behaviors><b><a group=\"g\"%s/></b></behaviors>"
                    + "<automata><a states=\"%s\" times=\"%s\"/></automata><states>%s</states></program>",
                    n - 1, mainCycles, entryTime == null ? "" : f(" time=\"%s\"", num(entryTime)), attrs, names, times, st);
        }

        private static String num(double v) {
            return v < 0 ? "(" + f("%s", v) + ")" : f("%s", v);
        }

        private static String f(String format, Object... args) {
            return String.format(Locale.ROOT, format, args);
        }
    }

    /** The engine's trace as numbers, and its text. */
    static List<double[]> engineRows(String script, StringBuilder text) {
        Engine e = SchedulerProperties.engine(script, new RunOptions(DT, 0, List.of()));
        StringWriter out = new StringWriter();
        e.addObserver(new TraceWriter(out));
        List<double[]> rows = new ArrayList<>();
        e.addObserver((tick, time, commanded) -> rows.add(commanded.clone()));
        e.start();
        for (int k = 0; k < MAX_TICKS && e.step(); k++) {
            // until <main> ends
        }
        text.append(out);
        return rows;
    }

    @Property(tries = 300)
    void theEngineAgreesWithTheReference(@ForAll long seed) {
        check(Prog.random(seed, true));
    }

    /** Constant targets and durations: isolates rules 19, 20 and 22 from rule 18. */
    @Property(tries = 300)
    void withConstantStatesTheEngineAgreesWithTheReference(@ForAll long seed) {
        check(Prog.random(seed, false));
    }

    private static void check(Prog prog) {
        String script = prog.script();
        StringBuilder text = new StringBuilder();
        List<double[]> got = engineRows(script, text);
        Reference ref = new Reference(prog);
        List<double[]> want = ref.run();
        String where = "\n" + script;
        assertEquals(want.size(), got.size(), "number of ticks" + where);
        for (int k = 0; k < want.size(); k++) {
            for (int m = 0; m < prog.n(); m++) {
                double w = want.get(k)[m];
                double g = got.get(k)[m];
                if (!(Math.abs(w - g) <= 1e-9 * Math.max(1, Math.abs(w)))) {
                    fail("tick " + k + " (t=" + k * DT + "), module " + m + ": reference " + w + ", engine " + g
                            + "\nreference " + Arrays.toString(want.get(k)) + "\nengine    " + Arrays.toString(got.get(k)) + where);
                }
            }
        }
        // a module is not driven after its cycles limit: it holds until its entry ends
        for (int[] span : ref.finishedSpans) {
            for (int k = span[1] + 1; k <= span[2] && k < got.size(); k++) {
                assertEquals(got.get(span[1])[span[0]], got.get(k)[span[0]], 0.0,
                        "module " + span[0] + " moved at tick " + k + " after finishing at tick " + span[1] + where);
            }
        }
        StringBuilder again = new StringBuilder();
        engineRows(script, again);
        assertEquals(text.toString(), again.toString(), "the same program gave two traces" + where);
        assertTrue(got.size() <= MAX_TICKS);
    }
}
