package org.parpe.core.run;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.EvalContext;
import org.parpe.core.expr.EvalException;
import org.parpe.core.expr.Expression;
import org.parpe.core.model.Conditional;
import org.parpe.core.model.MainDef;
import org.parpe.core.model.MainEntry;
import org.parpe.core.model.Program;
import org.parpe.core.sensor.Channel;
import org.parpe.core.sensor.SensorTable;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;

/**
 * The PARSL scheduler (PARSL.md §7, §11, §13). Stepped one tick at a time by whoever owns the
 * clock (normally a {@link Run}); reads a {@link SensorSource} at the start of each tick and at
 * its end hands the setpoints first to every <em>plant</em> (simulator, hardware), then to every
 * <em>observer</em> (trace, plots, recorders), so observers always see the plants' state of the
 * same tick whatever the order of registration. Confined to one thread, except for {@link #setControl},
 * {@link #setControlWord} and {@link #requestStop}, which queue commands drained at the next
 * tick boundary. Ticks do not allocate once the run has started.
 */
public final class Engine implements ExpressionEvaluator {
    private static final double EPS = 1e-9;

    private final Program program;
    private final double dt;
    private final int[] ids;
    private final double[] commanded;
    private final double[] next;
    private final boolean[] driven;
    private final int[] driverOf;
    /** The module's position in the group of the instance that drove it. */
    private final int[] driverPos;
    private final SensorTable sensors;
    private final EvalContext ctx = new EvalContext();
    private final TickInputs inputs;
    private final List<JointSink> plants = new ArrayList<>();
    private final List<JointSink> observers = new ArrayList<>();
    private final List<PlateSink> plateSinks = new ArrayList<>();
    /** The plate actions of the tick, per module index and plate (PARSL.md §14), and the states that made them. */
    private final byte[] plateActs;
    private final SourcePos[] plateWhere;
    private final EntryPlan[] plans;
    private final long mainCycles;
    private final Set<Long> warnedPairs = new HashSet<>();
    private SensorSource source;
    private DiagnosticSink warnings = d -> { };
    private int entry = -1;
    private long mainCycle;
    private long entryStart;
    private long tick = -1;
    private boolean ended;
    private volatile boolean stopRequested;

    /** Prepares a run of {@code program}; nothing happens until {@link #step()}. */
    public Engine(Program program, RunOptions options) {
        this.program = program;
        this.dt = options.dt();
        this.ids = program.moduleIds();
        this.commanded = new double[ids.length];
        this.next = new double[ids.length];
        this.driven = new boolean[ids.length];
        this.driverOf = new int[ids.length];
        this.driverPos = new int[ids.length];
        this.sensors = new SensorTable(ids);
        this.plateActs = new byte[2 * ids.length];
        this.plateWhere = new SourcePos[2 * ids.length];
        ctx.sensors = sensors;
        ctx.random = new SplittableRandom(options.seed());
        this.inputs = new TickInputs(program, ctx, sensors, options.stimuli());
        MainDef main = program.main();
        this.mainCycles = main == null ? 0 : main.cycles();
        this.plans = main == null ? new EntryPlan[0]
                : main.entries().stream().map(e -> new EntryPlan(e, ids)).toArray(EntryPlan[]::new);
    }

    /**
     * Adds a plant: a sink that acts on the robot (simulator, serial bus). Plants receive each
     * tick's setpoints before any observer; call before {@link #start()}.
     */
    public void addPlant(JointSink plant) {
        plants.add(plant);
    }

    /**
     * Adds an observer: a sink that only records (trace, plots). Observers receive each tick's
     * setpoints after every plant has, so what they read of a plant belongs to the same tick;
     * call before {@link #start()}.
     */
    public void addObserver(JointSink observer) {
        observers.add(observer);
    }

    /**
     * Adds a receiver of plate actions (PARSL.md §14): the simulator latches, a target without
     * latches tells the user. A plain run has none, so plate actions change nothing in it.
     */
    public void addPlateSink(PlateSink sink) {
        plateSinks.add(sink);
    }

    /** Sets where measured sensor readings come from (none: a plain headless run). */
    public void setSensorSource(SensorSource s) {
        this.source = s;
    }

    /** Where run-time warnings go (overlapping instances under {@code <if>}). */
    public void setWarningSink(DiagnosticSink sink) {
        this.warnings = sink;
    }

    /** The program being run. */
    public Program program() {
        return program;
    }

    /** Module IDs, ascending: the order of setpoint arrays. */
    public int[] moduleIds() {
        return ids.clone();
    }

    /** The tick length, seconds. */
    public double dt() {
        return dt;
    }

    /** The last tick run (−1 before the first). */
    public long tick() {
        return tick;
    }

    /** The time of the last tick run. */
    public double time() {
        return Math.max(0, tick) * dt;
    }

    /** Whether {@code <main>} has ended (or the program has none). */
    public boolean ended() {
        return ended;
    }

    /** Whether a stop was requested: the one cancellation flag of a run, checked at every tick. */
    public boolean stopRequested() {
        return stopRequested;
    }

    /** Asks the run to stop at the next tick boundary; safe from any thread. */
    public void requestStop() {
        stopRequested = true;
    }

    /** Tells every plant, then every observer, that the run starts. */
    public void start() {
        RunInfo info = new RunInfo(program, ids.clone(), dt);
        for (JointSink s : plants) {
            s.start(info);
        }
        for (JointSink s : observers) {
            s.start(info);
        }
    }

    /** Tells every plant, then every observer, that the run ended. */
    public void finish(RunOutcome outcome) {
        for (JointSink s : plants) {
            s.finish(outcome);
        }
        for (JointSink s : observers) {
            s.finish(outcome);
        }
    }

    /**
     * Sets a slider or text control (any thread; applied at the next tick).
     *
     * @throws IllegalArgumentException for an unknown control or a slider value out of range
     */
    public void setControl(String name, double value) {
        inputs.setControl(name, value);
    }

    /** Selects a word of a radio control (any thread; applied at the next tick). */
    public void setControlWord(String name, String word) {
        inputs.setControlWord(name, word);
    }

    /** The current value of a control (engine thread). */
    public double control(String name) {
        return inputs.control(name);
    }

    /** A snapshot of what the engine is doing (engine thread). */
    public EngineStatus status() {
        int count = 0;
        for (boolean b : driven) {
            count += b ? 1 : 0;
        }
        int[] d = new int[count];
        for (int i = 0, j = 0; i < ids.length; i++) {
            if (driven[i]) {
                d[j++] = ids[i];
            }
        }
        String name = entry >= 0 && entry < plans.length ? plans[entry].behavior.name() : "";
        return new EngineStatus(tick, time(), name, entry, mainCycle, d, ended);
    }

    /**
     * Which automaton state each module was in at the last tick (engine thread; fills the
     * caller's arrays and allocates nothing, so a live view may call it at every tick). For the
     * module at index {@code m} of {@link #moduleIds()}: {@code instanceOut[m]} is the document
     * position, within the current {@code <main>} entry's behavior, of the instance that drove
     * it, and {@code stateOut[m]} that instance's state index; both are −1 for a module not
     * driven at the last tick.
     */
    public void moduleStates(int[] instanceOut, int[] stateOut) {
        for (int m = 0; m < ids.length; m++) {
            if (driven[m] && entry >= 0 && entry < plans.length) {
                instanceOut[m] = driverOf[m];
                stateOut[m] = plans[entry].runs[driverOf[m]].st[driverPos[m]];
            } else {
                instanceOut[m] = -1;
                stateOut[m] = -1;
            }
        }
    }

    /**
     * Which state each module left at the last tick because its exit condition was true
     * (engine thread; allocates nothing): for the module at index {@code m} of
     * {@link #moduleIds()}, the state index within the instance {@link #moduleStates} names,
     * or −1 when it took no exit transition at the last tick (or was not driven).
     */
    public void moduleExits(int[] stateOut) {
        for (int m = 0; m < ids.length; m++) {
            stateOut[m] = driven[m] && entry >= 0 && entry < plans.length
                    ? plans[entry].runs[driverOf[m]].exitedFrom[driverPos[m]] : -1;
        }
    }

    /**
     * How far each module is through its state at the last tick (engine thread; allocates
     * nothing): for the module at index {@code m} of {@link #moduleIds()}, the fraction of the
     * state {@link #moduleStates} names that it has covered, in [0, 1], or −1 when it was not
     * driven.
     */
    public void moduleProgress(double[] out) {
        for (int m = 0; m < ids.length; m++) {
            out[m] = driven[m] && entry >= 0 && entry < plans.length ? plans[entry].runs[driverOf[m]].p[driverPos[m]] : -1;
        }
    }

    /** The {@code <main>} entry that ran at the last tick, or −1 before the first (engine thread; allocates nothing). */
    public int entryIndex() {
        return entry;
    }

    /**
     * Runs the next tick (the first call runs tick 0) and emits its setpoints.
     *
     * @return whether the program goes on after this tick
     * @throws ScriptRuntimeError on a run-time error of the script (nothing is emitted)
     */
    public boolean step() {
        if (ended) {
            return false;
        }
        tick++;
        ctx.time = tick * dt;
        inputs.read(source, commanded);
        Arrays.fill(driven, false);
        if (tick == 0 && source != null) {
            for (int i = 0; i < ids.length; i++) {
                commanded[i] = sensors.get(i, Channel.ANGLE);
            }
        }
        System.arraycopy(commanded, 0, next, 0, ids.length);
        if (tick == 0) {
            if (plans.length == 0 || mainCycles == 0) {
                ended = true;
            } else {
                startEntry(0);
            }
        } else if (entryEnds()) {
            nextEntry();
        } else {
            runInstances(true);
        }
        emit();
        return !ended;
    }

    private boolean entryEnds() {
        EntryPlan plan = plans[entry];
        ctx.btime = tick * dt - entryStart * dt;
        MainEntry e = plan.entry;
        // Both are evaluated on every tick (PARSL.md §13 rule 4), even when the first decides.
        boolean timeUp = e.time() != null && ctx.btime >= eval(e.time()) - EPS;
        boolean exit = e.exit() != null && eval(e.exit()) != 0;
        if (timeUp || exit) {
            return true;
        }
        if (plan.runs.length == 0) {
            return false;
        }
        for (InstanceRun r : plan.runs) {
            if (!r.finished()) {
                return false;
            }
        }
        return true;
    }

    private void nextEntry() {
        int next = entry + 1;
        if (next >= plans.length) {
            mainCycle++;
            if (mainCycles != MainDef.FOREVER && mainCycle >= mainCycles) {
                ended = true;
                return;
            }
            next = 0;
        }
        startEntry(next);
    }

    private void startEntry(int index) {
        entry = index;
        entryStart = tick;
        ctx.btime = 0;
        EntryPlan plan = plans[index];
        for (int i = 0; i < plan.valueArgs.length; i++) {
            plan.macros[plan.valueSlots[i]] = eval(plan.valueArgs[i].value());
        }
        for (InstanceRun r : plan.runs) {
            r.started = false;
            r.wasActive = false;
        }
        runInstances(false);
    }

    private void runInstances(boolean advance) {
        EntryPlan plan = plans[entry];
        ctx.macros = plan.macros;
        ctx.btime = tick * dt - entryStart * dt;
        for (InstanceRun r : plan.runs) {
            r.clearPlates();
            if (r.finished()) {
                continue;
            }
            boolean active = conditionsHold(r);
            ctx.count = r.n;
            if (!r.started) {
                if (ctx.btime < evalOr(r.model.start(), 0) - EPS) {
                    continue;
                }
                r.init(this, evalOr(r.model.phase(), 0), evalOr(r.model.offset(), 0),
                        evalOr(r.model.cycles(), Double.POSITIVE_INFINITY), commanded);
                r.wasActive = active;
                if (!active) {
                    r.clearPlates(); // frozen by its <if>, it entered nothing (§14)
                }
                if (active) {
                    for (int k = 0; k < r.n; k++) {
                        if (!r.fin[k]) {
                            r.hold(this, k);
                            drive(r, k);
                        }
                    }
                }
                continue;
            }
            if (!active) {
                r.wasActive = false;
                continue;
            }
            if (!r.wasActive) {
                r.reanchor(commanded);
                r.wasActive = true;
            }
            r.prepareTick(this, r.model.period(), dt);
            for (int k = 0; k < r.n; k++) {
                if (!r.fin[k]) {
                    r.advance(this, k, dt, commanded);
                    drive(r, k);
                }
            }
        }
    }

    private boolean conditionsHold(InstanceRun r) {
        for (Conditional c : r.conditions) {
            if (eval(c.condition()) == 0) {
                return false;
            }
        }
        return true;
    }

    private double evalOr(Expression e, double fallback) {
        return e == null ? fallback : eval(e);
    }

    private void drive(InstanceRun r, int k) {
        int m = r.mod[k];
        if (driven[m] && driverOf[m] != r.docIndex) {
            warnOverlap(driverOf[m], r, m);
        }
        driven[m] = true;
        driverOf[m] = r.docIndex;
        driverPos[m] = k;
        next[m] = r.out[k];
    }

    private void warnOverlap(int earlier, InstanceRun later, int module) {
        long key = (long) entry << 40 | (long) earlier << 20 | later.docIndex;
        if (warnedPairs.add(key)) {
            InstanceRun first = plans[entry].runs[earlier];
            warnings.warning(later.model.pos(), Msg.INSTANCES_OVERLAP, first.model.name(), first.model.group(),
                    first.model.pos().line(), later.model.name(), later.model.group(), ids[module],
                    String.format(java.util.Locale.ROOT, "%.6f", ctx.time));
        }
    }

    private void emit() {
        System.arraycopy(next, 0, commanded, 0, ids.length);
        if (!plateSinks.isEmpty() && entry >= 0) {
            emitPlates(plans[entry]);
        }
        for (int i = 0; i < plants.size(); i++) {
            plants.get(i).accept(tick, ctx.time, commanded);
        }
        for (int i = 0; i < observers.size(); i++) {
            observers.get(i).accept(tick, ctx.time, commanded);
        }
    }

    /** Hands the tick's plate actions, in document order of the instances, to the plate sinks. */
    private void emitPlates(EntryPlan plan) {
        boolean any = false;
        for (InstanceRun r : plan.runs) {
            if (!r.anyEntered) {
                continue;
            }
            for (int j = 0; j < r.entered.length; j++) {
                if (r.entered[j] != PlateSink.NONE) {
                    int slot = 2 * r.mod[j >> 1] + (j & 1);
                    plateActs[slot] = r.entered[j];
                    plateWhere[slot] = r.statePos(r.enteredState[j]);
                    any = true;
                }
            }
            r.clearPlates();
        }
        if (!any) {
            return;
        }
        for (int i = 0; i < plateSinks.size(); i++) {
            plateSinks.get(i).plates(tick, ctx.time, plateActs, plateWhere);
        }
        Arrays.fill(plateActs, PlateSink.NONE);
        Arrays.fill(plateWhere, null);
    }

    @Override
    public EvalContext ctx() {
        return ctx;
    }

    @Override
    public double eval(Expression e) {
        try {
            double v = e.eval(ctx);
            if (!Double.isFinite(v)) {
                // a reading or control can only be non-finite if a plant reported one
                throw new EvalException(Msg.VALUE_NOT_FINITE, v);
            }
            return v;
        } catch (EvalException ex) {
            throw error(e.pos(), Message.of(Msg.IN_EXPRESSION, ex.text(), e.text()));
        }
    }

    @Override
    public ScriptRuntimeError error(SourcePos pos, Message message) {
        return new ScriptRuntimeError(pos, message, ctx.time);
    }
}
