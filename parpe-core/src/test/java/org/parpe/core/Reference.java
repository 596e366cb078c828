package org.parpe.core;

import java.util.ArrayList;
import java.util.List;
import org.parpe.core.SchedulerReferenceProperties.Prog;
import org.parpe.core.SchedulerReferenceProperties.State;

/**
 * A slow, literal reading of PARSL.md §7.1, §8, §11 and §13 rules 1–2, 6–9 and 18–22 for
 * programs with one {@code <main>} entry whose behavior has one unconditional instance (no exit
 * conditions, no {@code start}). Written for the differential test, independently of the engine:
 * it keeps one plain object per module and allocates freely.
 */
final class Reference {
    private static final double EPS = 1e-9;

    /** Per module: [module, tick it finished, last tick of that entry run]. */
    final List<int[]> finishedSpans = new ArrayList<>();

    private final Prog prog;
    private final int ns;

    /** One module's automaton state (§7.1). */
    private static final class Mod {
        int i;
        double p;
        double p0;
        double a0;
        double uStart;
        double big;
        double phaseVar;
        double cycleVar;
        boolean done;
        int doneTick = -1;
    }

    Reference(Prog prog) {
        this.prog = prog;
        this.ns = prog.states().size();
    }

    /** The commanded angles of every emitted tick. */
    List<double[]> run() {
        double[] commanded = new double[prog.n()];
        List<double[]> rows = new ArrayList<>();
        Mod[] mods = place(commanded, 0);
        int entryStart = 0;
        int mainCycle = 0;
        rows.add(commanded.clone());
        for (int tick = 1; tick < SchedulerReferenceProperties.MAX_TICKS; tick++) {
            double[] next = commanded.clone();
            double btime = tick * SchedulerReferenceProperties.DT - entryStart * SchedulerReferenceProperties.DT;
            boolean allDone = true;
            for (Mod m : mods) {
                allDone &= m.done;
            }
            boolean ends = (prog.entryTime() != null && btime >= prog.entryTime() - EPS) || allDone;
            if (ends) {
                recordSpans(mods, tick - 1);
                mainCycle++;
                if (mainCycle >= prog.mainCycles()) {
                    rows.add(next);
                    return rows;
                }
                entryStart = tick;
                mods = place(commanded, tick);
                rows.add(commanded.clone());
                continue;
            }
            for (int k = 0; k < mods.length; k++) {
                if (!mods[k].done) {
                    next[k] = advance(mods[k], commanded[k], tick);
                }
            }
            commanded = next;
            rows.add(commanded.clone());
        }
        recordSpans(mods, SchedulerReferenceProperties.MAX_TICKS - 1);
        return rows;
    }

    private void recordSpans(Mod[] mods, int lastTick) {
        for (int k = 0; k < mods.length; k++) {
            if (mods[k].doneTick >= 0) {
                finishedSpans.add(new int[] {k, mods[k].doneTick, lastTick});
            }
        }
    }

    /**
     * Starts the entry: places every module (rule 6) with $phase = u_k, $cycle = 0 (rule 18),
     * or nothing at all for cycles ≤ 0 (rule 19); writes the placement setpoints into {@code commanded}.
     */
    private Mod[] place(double[] commanded, int tick) {
        Mod[] mods = new Mod[prog.n()];
        double cycles = prog.cycles() == null ? Double.POSITIVE_INFINITY : prog.cycles();
        for (int k = 0; k < mods.length; k++) {
            Mod m = new Mod();
            mods[k] = m;
            if (cycles <= 0) {
                m.done = true;
                continue;
            }
            double x = -(prog.offset() + k * prog.phase());
            double uk = x - Math.floor(x);
            double[] t = times(uk, 0);
            double sum = sum(t);
            double at = uk * sum;
            double before = 0;
            m.i = -1;
            for (int j = 0; j < ns && m.i < 0; j++) {
                if (t[j] > 0 && at < before + t[j] - EPS) {
                    m.i = j;
                    m.p = Math.max(0, (at - before) / t[j]);
                } else {
                    before += t[j];
                }
            }
            if (m.i < 0) {
                m.i = 0;
                m.p = 0;
                uk = 0;
            }
            m.uStart = uk;
            m.big = uk;
            m.p0 = m.p;
            m.a0 = commanded[k];
            m.phaseVar = uk;
            m.cycleVar = 0;
            commanded[k] = setpoint(m);
        }
        return mods;
    }

    /** One tick of §7.1 step 2 for one module; returns its setpoint. */
    private double advance(Mod m, double current, int tick) {
        double[] t = times(m.phaseVar, m.cycleVar);
        double sum = sum(t);
        double limit = prog.cycles() == null ? Double.POSITIVE_INFINITY : m.uStart + prog.cycles();
        double r = SchedulerReferenceProperties.DT;
        int skipped = 0;
        while (true) {
            State s = prog.states().get(m.i);
            double d = prog.period() == null ? t[m.i] : (t[m.i] * prog.period()) / sum;
            if (d <= 0) {
                if (++skipped > ns) {
                    throw new IllegalStateException("every state has D <= 0");
                }
                m.a0 = s.target(m.phaseVar, m.cycleVar);
                m.i = (m.i + 1) % ns;
                m.p = 0;
                m.p0 = 0;
                continue;
            }
            double need = (1 - m.p) * d;
            if (r < need - EPS) {
                double piece = r / d * t[m.i] / sum;
                if (m.big + piece >= limit - EPS) {
                    return stop(m, t, sum, limit, false, tick);
                }
                m.p += r / d;
                m.big += piece;
                break;
            }
            double rest = (1 - m.p) * t[m.i] / sum;
            r -= need;
            skipped = 0;
            if (m.big + rest >= limit - EPS) {
                return stop(m, t, sum, limit, m.big + rest <= limit + EPS, tick);
            }
            m.big += rest;
            m.a0 = s.target(m.phaseVar, m.cycleVar);
            m.i = (m.i + 1) % ns;
            m.p = 0;
            m.p0 = 0;
        }
        m.phaseVar = position(t, sum, m.i, m.p);
        m.cycleVar = Math.floor(m.big - m.uStart + EPS);
        return setpoint(m);
    }

    /** Rule 20: stop at the limit; inside a state the interpolated angle, at its end the target. */
    private double stop(Mod m, double[] t, double sum, double limit, boolean atEnd, int tick) {
        m.p = atEnd ? 1 : Math.min(1, m.p + (limit - m.big) * sum / t[m.i]);
        m.phaseVar = position(t, sum, m.i, m.p);
        m.cycleVar = Math.floor(prog.cycles() + EPS);
        m.done = true;
        m.doneTick = tick;
        return atEnd ? target(m) : setpoint(m);
    }

    private double target(Mod m) {
        return prog.states().get(m.i).target(m.phaseVar, m.cycleVar);
    }

    private double setpoint(Mod m) {
        State s = prog.states().get(m.i);
        double g = target(m);
        if (s.step()) {
            return g;
        }
        double q = (m.p - m.p0) / (1 - m.p0);
        return m.a0 + (g - m.a0) * q;
    }

    private double[] times(double phase, double cycle) {
        double[] t = new double[ns];
        for (int j = 0; j < ns; j++) {
            t[j] = prog.states().get(j).time(phase, cycle);
        }
        return t;
    }

    private static double sum(double[] t) {
        double s = 0;
        for (double v : t) {
            s += v;
        }
        return s;
    }

    /** The cycle position u of (i, p) (§7.1). */
    private static double position(double[] t, double sum, int i, double p) {
        double before = 0;
        for (int j = 0; j < i; j++) {
            before += t[j];
        }
        return (before + p * t[i]) / sum;
    }
}
