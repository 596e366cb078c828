package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.DoubleRange;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.constraints.LongRange;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.Engine;
import org.parpe.core.run.JointSink;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.TraceWriter;

/** Properties of the scheduler (PARSL.md §7.1): continuity, phase relations, determinism. */
class SchedulerProperties {

    /** A random time-driven automaton with linear states. */
    record Gait(int modules, List<Double> targets, List<Double> times, double period, double phase, double offset) {
        String script() {
            StringBuilder states = new StringBuilder();
            StringBuilder names = new StringBuilder();
            for (int i = 0; i < targets.size(); i++) {
                states.append(String.format(Locale.ROOT, "<s%d angles=\"%.4f\"/>", i, targets.get(i)));
                names.append(i == 0 ? "" : ", ").append("s").append(i);
            }
            StringBuilder t = new StringBuilder();
            for (int i = 0; i < times.size(); i++) {
                t.append(i == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.4f", times.get(i)));
            }
            return String.format(Locale.ROOT, "<program><robot><structure><g elements=\"0..%d\"/></structure></robot>"
                    + "<main><b/></main><behaviors><b><a group=\"g\" period=\"%.4f\" phase=\"%.4f\" offset=\"%.4f\"/></b></behaviors>"
                    + "<automata><a states=\"%s\" times=\"%s\"/></automata><states>%s</states></program>",
                    modules - 1, period, phase, offset, names, t, states);
        }

        double shortestState() {
            double sum = times.stream().mapToDouble(Double::doubleValue).sum();
            return times.stream().mapToDouble(Double::doubleValue).min().orElseThrow() * period / sum;
        }
    }

    @Provide
    Arbitrary<Gait> gaits() {
        Arbitrary<Integer> n = Arbitraries.integers().between(1, 6);
        Arbitrary<Integer> states = Arbitraries.integers().between(1, 4);
        return Combinators.combine(n, states, Arbitraries.doubles().between(0.5, 4),
                        Arbitraries.doubles().between(-1, 1), Arbitraries.doubles().between(0, 1))
                .flatAs((modules, count, period, phase, offset) -> Combinators.combine(
                        Arbitraries.doubles().between(-90, 90).list().ofSize(count),
                        Arbitraries.doubles().between(0.2, 3).list().ofSize(count))
                        .as((targets, times) -> new Gait(modules, targets, times, period, phase, offset)));
    }

    static Engine engine(String script, RunOptions options) {
        LoadResult r = ScriptLoader.loadText(Path.of("prop.xml"), script, Map.of());
        assertTrue(r.ok(), () -> r.diagnostics() + "\n" + script);
        return new Engine(r.program(), options);
    }

    /** Records the commanded angles of every tick. */
    static double[][] run(Engine e, int ticks) {
        double[][] rows = new double[ticks][];
        e.addObserver(new JointSink() {
            @Override
            public void accept(long tick, double time, double[] commanded) {
                rows[(int) tick] = commanded.clone();
            }
        });
        e.start();
        for (int i = 0; i < ticks; i++) {
            e.step();
        }
        return rows;
    }

    @Property(tries = 150)
    void linearStatesWithoutExitsAreContinuous(@ForAll("gaits") Gait g) {
        double dt = 0.01;
        double[][] rows = run(engine(g.script(), RunOptions.defaults()), (int) Math.ceil(3 * g.period() / dt) + 10);
        // Once every module has made its first transition, no step is steeper than a full
        // 180-degree swing over the shortest state.
        double bound = 180 / g.shortestState() * dt + 1e-9;
        int from = (int) Math.ceil(g.period() / dt) + 2;
        for (int k = from; k < rows.length; k++) {
            for (int m = 0; m < g.modules(); m++) {
                double step = Math.abs(rows[k][m] - rows[k - 1][m]);
                assertTrue(step <= bound, "module " + m + " jumps " + step + " at tick " + k + " (bound " + bound + ")");
            }
        }
    }

    @Property(tries = 80)
    void eachModuleOfAWaveLagsThePreviousByPhaseTimesPeriod(@ForAll @IntRange(min = 2, max = 8) int modules,
            @ForAll @IntRange(min = 1, max = 19) int phaseTwentieths, @ForAll @IntRange(min = 1, max = 4) int period,
            @ForAll @DoubleRange(min = 5, max = 60) double amplitude) {
        double phase = phaseTwentieths / 20.0;
        String script = String.format(Locale.ROOT, "<program><robot><structure><g elements=\"0..%d\"/></structure></robot>"
                + "<main><b/></main><behaviors><b><wave group=\"g\" phase=\"%s\" period=\"%d\"/></b></behaviors>"
                + "<automata><wave states=\"up, down\"/></automata>"
                + "<states><up angles=\"%.3f\"/><down angles=\"-%.3f\"/></states></program>",
                modules - 1, phase, period, amplitude, amplitude);
        double dt = 0.01;
        int lagTicks = (int) Math.round(phase * period / dt);
        double[][] rows = run(engine(script, RunOptions.defaults()), (int) (4 * period / dt));
        for (int k = (int) (2 * period / dt); k < rows.length; k++) {
            for (int m = 0; m + 1 < modules; m++) {
                assertEquals(rows[k - lagTicks][m], rows[k][m + 1], 1e-6,
                        "module " + (m + 1) + " at tick " + k + " should repeat module " + m + " " + lagTicks + " ticks later");
            }
        }
    }

    @Property(tries = 40)
    void identicalInputsGiveBitIdenticalTraces(@ForAll("gaits") Gait g, @ForAll @LongRange(min = 0, max = 1000) long seed) {
        String script = g.script().replace("<s0 angles=\"", "<s0 angles=\"20*rand() + ");
        String a = trace(script, seed);
        String b = trace(script, seed);
        assertEquals(a, b);
    }

    static String trace(String script, long seed) {
        Engine e = engine(script, new RunOptions(0.01, seed, List.of()));
        StringWriter out = new StringWriter();
        e.addObserver(new TraceWriter(out));
        e.start();
        for (int i = 0; i < 400; i++) {
            e.step();
        }
        return out.toString();
    }

    @Property(tries = 5)
    void theSeedChangesRand(@ForAll @LongRange(min = 0, max = 1000) long seed) {
        String script = "<program><robot><structure><g elements=\"0\"/></structure></robot><main><b/></main>"
                + "<behaviors><b><w group=\"g\"/></b></behaviors><automata><w states=\"s\"/></automata>"
                + "<states><s angles=\"90*rand()\" interp=\"step\"/></states></program>";
        assertTrue(!trace(script, seed).equals(trace(script, seed + 1)));
    }
}
