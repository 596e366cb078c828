package org.parpe.core.run;

import java.util.Arrays;
import org.parpe.core.expr.EvalContext;
import org.parpe.core.expr.Expression;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.Conditional;
import org.parpe.core.model.Instance;
import org.parpe.core.model.Interp;
import org.parpe.core.lang.Numbers;
import org.parpe.core.model.StateDef;
import org.parpe.core.text.Msg;

/**
 * The run-time state of one automaton instance of one {@code <main>} entry: per module the
 * state index, progress, entry angle and progress, cycle position (PARSL.md §7.1, §13 rules
 * 6–9). Allocated when the engine is built and reset whenever its entry starts, so ticks do
 * not allocate.
 */
final class InstanceRun {
    private static final double EPS = 1e-9;
    /** More transitions than this in one tick means the states are far shorter than the tick. */
    static final int MAX_TRANSITIONS_PER_TICK = 10_000;

    final Instance model;
    final Conditional[] conditions;
    final int docIndex;
    final int[] mod;
    final int[] ids;
    final boolean mirror;
    final int n;
    private final String automaton;
    private final Expression[] angles0;
    private final Expression[][] angles;
    private final Interp[] interp;
    private final Expression[] times;
    private final String[] stateNames;
    private final Expression[] exits;
    private final boolean timesPerModule;
    private final int ns;
    /** Per state and plate, its action ({@link PlateSink#ARM}, …), and the states' places. */
    private final byte[] stateActs;
    private final org.parpe.core.diag.SourcePos[] statePos;
    /** Whether a state of the automaton acts on plates (PARSL.md §14). */
    final boolean plates;
    /** Per module and plate, the action of the states entered this tick, and the state. */
    final byte[] entered;
    final int[] enteredState;
    /** Whether {@link #entered} holds an action. */
    boolean anyEntered;

    // per module
    final int[] st;
    final double[] p;
    final double[] p0;
    final double[] a0;
    final double[] u;
    final double[] uk;
    final double[] ph;
    final double[] cyc;
    final boolean[] fin;
    final double[] out;
    /** Per module, the state it left at its last advance because that state's exit condition was true, or −1. */
    final int[] exitedFrom;

    private final double[] tBuf;
    /**
     * Per state, derived from {@link #tBuf}, {@link #sumT} and {@link #scale} whenever they
     * change ({@link #derive}): its length this tick, the progress and the cycle position a
     * whole tick inside it adds, and the durations of the states before it. The same
     * operations in the same order as computed per module before, so traces stay bit for bit.
     */
    private final double[] dBuf;
    private final double[] tickProgress;
    private final double[] tickU;
    private final double[] cumBuf;
    private double sumT;
    private double scale;
    private double limit;
    boolean started;
    boolean wasActive;
    int finishedCount;

    InstanceRun(Instance model, Automaton a, Conditional[] conditions, int docIndex, int[] mod, int[] ids, boolean mirror) {
        this.model = model;
        this.conditions = conditions;
        this.docIndex = docIndex;
        this.mod = mod;
        this.ids = ids;
        this.mirror = mirror;
        this.n = mod.length;
        this.automaton = a.name();
        this.ns = a.states().size();
        this.angles = new Expression[ns][];
        this.angles0 = new Expression[ns];
        this.interp = new Interp[ns];
        this.times = new Expression[ns];
        this.stateNames = new String[ns];
        this.exits = new Expression[ns];
        boolean perModule = false;
        this.stateActs = new byte[2 * ns];
        this.statePos = new org.parpe.core.diag.SourcePos[ns];
        boolean acts = false;
        for (int i = 0; i < ns; i++) {
            StateDef s = a.states().get(i);
            statePos[i] = s.pos();
            for (int plate : s.latch()) {
                stateActs[2 * i + plate] = PlateSink.ARM;
            }
            for (int plate : s.unlatch()) {
                stateActs[2 * i + plate] = PlateSink.RELEASE;
            }
            acts |= s.hasPlateActions();
            angles[i] = bindTargets(s.angles().toArray(new Expression[0]));
            angles0[i] = angles[i][0];
            interp[i] = s.interp();
            stateNames[i] = s.name();
            times[i] = a.times().get(i).duration();
            exits[i] = a.times().get(i).exit();
            perModule |= times[i].perModule();
        }
        this.timesPerModule = perModule;
        this.plates = acts;
        this.entered = new byte[acts ? 2 * n : 0];
        this.enteredState = new int[acts ? 2 * n : 0];
        st = new int[n];
        p = new double[n];
        p0 = new double[n];
        a0 = new double[n];
        u = new double[n];
        uk = new double[n];
        ph = new double[n];
        cyc = new double[n];
        fin = new boolean[n];
        out = new double[n];
        exitedFrom = new int[n];
        Arrays.fill(exitedFrom, -1);
        tBuf = new double[ns];
        dBuf = new double[ns];
        tickProgress = new double[ns];
        tickU = new double[ns];
        cumBuf = new double[ns];
    }

    /**
     * The targets of a state, bound to each module of the group ({@link Expression#bind}) when
     * they read {@code $index}, {@code $count} or {@code $id}, so that what depends only on the
     * module is computed once per run instead of per tick: one expression for every module, or
     * one per module. {@code bindTargets} runs before the modules' arrays exist; it reads only
     * {@link #ids} and {@link #n}.
     */
    private Expression[] bindTargets(Expression[] written) {
        Expression[] bound = new Expression[written.length == 1 ? n : written.length];
        boolean changed = false;
        for (int k = 0; k < bound.length; k++) {
            Expression e = written[written.length == 1 ? 0 : k];
            bound[k] = k < n ? e.bind(k, n, ids[k]) : e;
            changed |= bound[k] != e;
        }
        return changed ? bound : written;
    }

    /** Whether every module has finished its cycles. */
    boolean finished() {
        return started && finishedCount == n;
    }

    /** Forgets the plate actions of the last tick. */
    void clearPlates() {
        if (anyEntered) {
            Arrays.fill(entered, PlateSink.NONE);
            anyEntered = false;
        }
    }

    /** Module {@code k} enters state {@code s}: its plate actions replace those of states entered before this tick. */
    private void entering(int k, int s) {
        if (!plates) {
            return;
        }
        for (int plate = 0; plate < 2; plate++) {
            byte act = stateActs[2 * s + plate];
            if (act != PlateSink.NONE) {
                entered[2 * k + plate] = act;
                enteredState[2 * k + plate] = s;
                anyEntered = true;
            }
        }
    }

    /** Where state {@code s} is written. */
    org.parpe.core.diag.SourcePos statePos(int s) {
        return statePos[s];
    }

    /** Sets the context to module {@code k} with its start-of-tick $phase and $cycle. */
    void enter(EvalContext c, int k) {
        c.index = k;
        c.id = ids[k];
        c.count = n;
        c.group = mod;
        c.phase = ph[k];
        c.cycle = cyc[k];
    }

    /**
     * Places every module (§7.1, §13 rules 6, 18, 19); {@code commanded} holds the angles
     * emitted last tick. {@code times} and the targets see the placement values
     * {@code $phase = u_k}, {@code $cycle = 0}, never those of an earlier run of the entry.
     * With {@code cycles ≤ 0} nothing is placed or evaluated: the modules are never driven.
     */
    void init(ExpressionEvaluator ev, double phase, double offset, double cycles, double[] commanded) {
        started = true;
        limit = cycles;
        Arrays.fill(exitedFrom, -1);
        if (cycles <= 0) {
            Arrays.fill(fin, true);
            finishedCount = n;
            return;
        }
        finishedCount = 0;
        EvalContext c = ev.ctx();
        for (int k = 0; k < n; k++) {
            double x = -(offset + k * phase);
            double start = x - Math.floor(x);
            enter(c, k);
            c.phase = start;
            c.cycle = 0;
            if (k == 0 || timesPerModule) {
                evalTimes(ev);
            }
            double pos = start * sumT;
            double cum = 0;
            int found = -1;
            for (int j = 0; j < ns; j++) {
                if (tBuf[j] > 0 && pos < cum + tBuf[j] - EPS) {
                    found = j;
                    break;
                }
                cum += tBuf[j];
            }
            if (found < 0) {
                st[k] = 0;
                p[k] = 0;
                start = 0;
            } else {
                st[k] = found;
                p[k] = Math.max(0, (pos - cum) / tBuf[found]);
            }
            entering(k, st[k]);
            uk[k] = start;
            u[k] = start;
            p0[k] = p[k];
            a0[k] = commanded[mod[k]];
            cyc[k] = 0;
            ph[k] = start;
            fin[k] = false;
        }
    }

    /** Re-anchors after a suspension (§7.2): motion resumes from the current angle. */
    void reanchor(double[] commanded) {
        for (int k = 0; k < n; k++) {
            if (!fin[k]) {
                a0[k] = commanded[mod[k]];
                p0[k] = p[k];
            }
        }
    }

    private void evalTimes(ExpressionEvaluator ev) {
        double s = 0;
        for (int j = 0; j < ns; j++) {
            double t = ev.eval(times[j]);
            if (t < 0) {
                // §13 rule 21: a negative duration is an error, not a skipped state
                throw ev.error(times[j].pos(), Msg.NEGATIVE_DURATION, stateNames[j], automaton, Numbers.brief(t));
            }
            tBuf[j] = t;
            s += t;
        }
        sumT = s;
        if (!(s > 0)) {
            throw ev.error(model.pos(), Msg.TOTAL_DURATION, automaton, Numbers.brief(s));
        }
    }

    /** Evaluates the period for this tick (instance scope) and, unless they are per module, the durations. */
    void prepareTick(ExpressionEvaluator ev, Expression period, double dt) {
        double per = period == null ? Double.NaN : ev.eval(period);
        if (period != null && !(per > 0)) {
            throw ev.error(period.pos(), Msg.PERIOD_NOT_POSITIVE, automaton, Numbers.brief(per));
        }
        scale = per;
        if (!timesPerModule) {
            enter(ev.ctx(), 0);
            evalTimes(ev);
            derive(dt);
        }
    }

    /** Fills the per-state values derived from the durations, the period and the tick {@code dt}. */
    private void derive(double dt) {
        double cum = 0;
        for (int j = 0; j < ns; j++) {
            double t = tBuf[j];
            // §13 rule 22: (T · period) / ΣT, in that order
            double d = Double.isNaN(scale) ? t : t * scale / sumT;
            dBuf[j] = d;
            tickProgress[j] = dt / d;
            tickU[j] = dt / d * t / sumT;
            cumBuf[j] = cum;
            cum += t;
        }
    }

    /**
     * Advances module {@code k} by {@code dt} (§7.1, §13 rules 7–9, 20, 22) and computes its
     * setpoint into {@code out}.
     */
    void advance(ExpressionEvaluator ev, int k, double dt, double[] commanded) {
        EvalContext c = ev.ctx();
        enter(c, k);
        if (timesPerModule) {
            evalTimes(ev);
            derive(dt);
        }
        double lim = uk[k] + limit;
        if (!takeExit(ev, k, lim, commanded)) {
            return;
        }
        int s = st[k];
        double r = dt;
        boolean wholeTick = true;
        int skips = 0;
        int transitions = 0;
        while (true) {
            double t = tBuf[s];
            double d = dBuf[s];
            if (d <= 0) {
                if (++skips > ns) {
                    throw ev.error(model.pos(), Msg.NO_POSITIVE_DURATION, automaton);
                }
                a0[k] = target(ev, s, k);
                s = next(k, s);
                continue;
            }
            double need = (1 - p[k]) * d;
            if (r < need - EPS) {
                // a whole tick inside the state (the common case) was worked out for every module at once
                double du = wholeTick ? tickU[s] : r / d * t / sumT;
                if (u[k] + du >= lim - EPS) {
                    finishInside(ev, k, s, lim);
                    return;
                }
                p[k] += wholeTick ? tickProgress[s] : r / d;
                u[k] += du;
                break;
            }
            double du = (1 - p[k]) * t / sumT;
            r -= need;
            wholeTick = false;
            skips = 0;
            if (++transitions > MAX_TRANSITIONS_PER_TICK) {
                throw ev.error(model.pos(), Msg.TOO_MANY_TRANSITIONS, automaton, MAX_TRANSITIONS_PER_TICK, Numbers.brief(dt));
            }
            if (u[k] + du >= lim - EPS) {
                finishInState(ev, k, s, lim, u[k] + du);
                return;
            }
            u[k] += du;
            a0[k] = target(ev, s, k);
            s = next(k, s);
        }
        ph[k] = phaseOf(s, p[k]);
        cyc[k] = Math.floor(u[k] - uk[k] + EPS);
        c.phase = ph[k];
        c.cycle = cyc[k];
        out[k] = setpoint(ev, k, s);
    }

    /**
     * The {@code cycles} limit {@code lim} is reached before state {@code s} ends, at cycle
     * position {@code end}: at the state's end when that is within rounding, else inside it.
     */
    private void finishInState(ExpressionEvaluator ev, int k, int s, double lim, double end) {
        if (end <= lim + EPS) {
            finishAtEnd(ev, k, s);
        } else {
            finishInside(ev, k, s, lim);
        }
    }

    /**
     * The exit condition of module {@code k}'s state, evaluated first in its tick (§7.1): when it
     * holds, the module leaves the state from where it is, starting the next from the angle it
     * was commanded. Returns false when that reached the {@code cycles} limit {@code lim} and the
     * module finished.
     */
    private boolean takeExit(ExpressionEvaluator ev, int k, double lim, double[] commanded) {
        int s = st[k];
        exitedFrom[k] = -1;
        if (exits[s] == null || ev.eval(exits[s]) == 0) {
            return true;
        }
        exitedFrom[k] = s;
        double du = (1 - p[k]) * tBuf[s] / sumT;
        if (u[k] + du >= lim - EPS) {
            finish(k, commanded[mod[k]]);
            return false;
        }
        u[k] += du;
        a0[k] = commanded[mod[k]];
        next(k, s);
        return true;
    }

    /** Module {@code k} leaves state {@code s} for the next; returns that state. */
    private int next(int k, int s) {
        int n = (s + 1) % ns;
        st[k] = n;
        entering(k, n);
        p[k] = p0[k] = 0;
        return n;
    }

    /**
     * The {@code cycles} limit lies inside state {@code s} (§13 rule 20): the module stops at
     * that cycle position and holds the interpolated angle there, seen with the updated
     * {@code $phase} and {@code $cycle}.
     */
    private void finishInside(ExpressionEvaluator ev, int k, int s, double lim) {
        p[k] = Math.min(1, p[k] + (lim - u[k]) * sumT / tBuf[s]);
        seeFinalPosition(ev.ctx(), k, s);
        finish(k, setpoint(ev, k, s));
    }

    /** The limit is the end of state {@code s}: the module holds its target, seen with the updated values. */
    private void finishAtEnd(ExpressionEvaluator ev, int k, int s) {
        p[k] = 1;
        seeFinalPosition(ev.ctx(), k, s);
        finish(k, target(ev, s, k));
    }

    private void seeFinalPosition(EvalContext c, int k, int s) {
        ph[k] = phaseOf(s, p[k]);
        c.phase = ph[k];
        c.cycle = Math.floor(limit + EPS);
    }

    /** Computes module {@code k}'s setpoint without advancing (initialisation tick). */
    void hold(ExpressionEvaluator ev, int k) {
        enter(ev.ctx(), k);
        out[k] = setpoint(ev, k, st[k]);
    }

    private void finish(int k, double angle) {
        fin[k] = true;
        finishedCount++;
        out[k] = angle;
        u[k] = uk[k] + limit;
        cyc[k] = Math.floor(limit + EPS);
    }

    private double setpoint(ExpressionEvaluator ev, int k, int s) {
        double g = target(ev, s, k);
        if (interp[s] == Interp.STEP) {
            return g;
        }
        // from the start of the state (p0 = +0.0), (p − 0) / (1 − 0) is p exactly, −0.0 too: no division
        double q = Double.doubleToRawLongBits(p0[k]) == 0 ? p[k] : (p[k] - p0[k]) / (1 - p0[k]);
        return a0[k] + (g - a0[k]) * interp[s].shape(q);
    }

    private double target(ExpressionEvaluator ev, int s, int k) {
        Expression e = angles[s].length == 1 ? angles0[s] : angles[s][k];
        double v = ev.eval(e);
        return mirror ? -v : v;
    }

    private double phaseOf(int s, double prog) {
        return (cumBuf[s] + prog * tBuf[s]) / sumT;
    }
}
