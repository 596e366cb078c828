package org.parpe.core.run;

import java.io.Writer;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.model.Program;

/**
 * One run of a program, assembled the same way by the command line and the IDE: the engine,
 * its plants (simulator, hardware) and observers (trace, plots, recorders), the sensor source,
 * a fixed-step loop with one cancellation flag ({@link Engine#requestStop}), and pacing
 * supplied by the caller. Build it with {@link #builder}, attach {@link RunTarget}s, then
 * {@link #execute()} it on the thread that owns the clock.
 *
 * <p>Plants always receive a tick's setpoints before observers (see {@link Engine}), so the
 * order in which targets and observers are added cannot change a trace. Warnings and the
 * run-time error of the script reach the {@link DiagnosticSink} given to the builder.
 */
public final class Run {
    private static final double EPS = 1e-9;

    private final Engine engine;
    private final double duration;
    private final Pacer pacer;
    private final DiagnosticSink diagnostics;
    private final List<Consumer<RunOutcome>> finishers;
    private final List<AutoCloseable> resources;

    private Run(Builder b) {
        this.engine = b.engine;
        this.duration = b.duration;
        this.pacer = b.pacer;
        this.diagnostics = b.diagnostics;
        this.finishers = List.copyOf(b.finishers);
        this.resources = List.copyOf(b.resources);
    }

    /**
     * Starts assembling a run of {@code program}; warnings and run-time errors go to
     * {@code diagnostics}.
     */
    public static Builder builder(Program program, RunOptions options, DiagnosticSink diagnostics) {
        return new Builder(program, options, diagnostics);
    }

    /** The engine: controls ({@link Engine#setControl}) and status are reached through it. */
    public Engine engine() {
        return engine;
    }

    /** Asks the run to stop at the next tick boundary; safe from any thread. */
    public void requestStop() {
        engine.requestStop();
    }

    /** Whether a stop was requested. */
    public boolean stopRequested() {
        return engine.stopRequested();
    }

    /**
     * Runs on the calling thread until {@code <main>} ends, the duration is reached (PARSL.md
     * §13 rule 1), a stop is requested, or the script fails at run time; then tells the sinks
     * and the finishers how it ended and closes the resources (in reverse order of
     * registration). A run-time error of the script is reported to the diagnostics and ends
     * the run with {@link RunOutcome.Status#ERROR}; any other exception of a plant or observer
     * propagates after the resources are closed.
     */
    public RunOutcome execute() {
        try {
            RunOutcome outcome;
            try {
                engine.start();
                outcome = loop();
            } catch (ScriptRuntimeError e) {
                diagnostics.report(e.diagnostic());
                outcome = new RunOutcome(RunOutcome.Status.ERROR, engine.time(), e.getMessage());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                outcome = new RunOutcome(RunOutcome.Status.STOPPED, engine.time(), "");
            }
            engine.finish(outcome);
            for (Consumer<RunOutcome> f : finishers) {
                f.accept(outcome);
            }
            return outcome;
        } finally {
            closeResources(resources, diagnostics);
        }
    }

    private RunOutcome loop() throws InterruptedException {
        double dt = engine.dt();
        for (long k = 0; ; k++) {
            double t = k * dt;
            if (t > duration + EPS) {
                return new RunOutcome(RunOutcome.Status.COMPLETED, engine.time(), "");
            }
            pacer.beforeTick(this, t);
            if (engine.stopRequested()) {
                return new RunOutcome(RunOutcome.Status.STOPPED, engine.time(), "");
            }
            if (!engine.step()) {
                return new RunOutcome(RunOutcome.Status.COMPLETED, engine.time(), "");
            }
        }
    }

    /** Closes {@code list} in reverse order, reporting (not throwing) failures as warnings. */
    static void closeResources(List<AutoCloseable> list, DiagnosticSink diagnostics) {
        for (int i = list.size() - 1; i >= 0; i--) {
            try {
                list.get(i).close();
            } catch (Exception e) {
                diagnostics.warning(org.parpe.core.diag.SourcePos.origin("parpe"), org.parpe.core.text.Msg.WHILE_CLOSING,
                        list.get(i), e.getMessage() == null ? e : e.getMessage());
            }
        }
    }

    /**
     * Assembles a {@link Run}: targets add plants, sensor sources, trace columns and resources;
     * the caller adds observers, the trace, the duration and the pacing.
     */
    public static final class Builder {
        private final Engine engine;
        private final Program program;
        private final RunOptions options;
        private final DiagnosticSink diagnostics;
        private final List<TraceColumns> columns = new ArrayList<>();
        private final List<JointSink> observers = new ArrayList<>();
        private final List<SensorSource> readingObservers = new ArrayList<>();
        private final List<Consumer<RunOutcome>> finishers = new ArrayList<>();
        private final List<AutoCloseable> resources = new ArrayList<>();
        private final Map<SourceKind, SensorSource> offered = new LinkedHashMap<>();
        private SensorSource source;
        private int sourcePriority = Integer.MIN_VALUE;
        private Writer trace;
        private double duration = Double.POSITIVE_INFINITY;
        private Pacer pacer = Pacer.NONE;
        private boolean realtimeRequired;
        private boolean built;

        private Builder(Program program, RunOptions options, DiagnosticSink diagnostics) {
            this.program = program;
            this.options = options;
            this.diagnostics = diagnostics;
            this.engine = new Engine(program, options);
            engine.setWarningSink(diagnostics);
        }

        public Program program() {
            return program;
        }

        public RunOptions options() {
            return options;
        }

        /** Where targets report warnings and problems found while attaching. */
        public DiagnosticSink diagnostics() {
            return diagnostics;
        }

        /**
         * The engine being assembled: its stop flag is the run's, so a stop requested while
         * targets are still attaching (e.g. during a bus scan) ends the run before its first tick.
         */
        public Engine engine() {
            return engine;
        }

        /** Attaches a target. */
        public Builder attach(RunTarget target) throws TargetException {
            target.attach(this);
            return this;
        }

        /** Adds a plant (it acts on the robot); plants see each tick before observers. */
        public Builder plant(JointSink plant) {
            engine.addPlant(plant);
            return this;
        }

        /** Adds a receiver of plate actions (PARSL.md §14): a target that latches, or one that tells the user. */
        public Builder plates(PlateSink sink) {
            engine.addPlateSink(sink);
            return this;
        }

        /** Adds an observer (it records); observers see each tick after every plant. */
        public Builder observer(JointSink observer) {
            observers.add(observer);
            return this;
        }

        /**
         * Offers a sensor source of a kind; the one of the highest {@link SourceKind#priority()}
         * is read (the hardware over the simulator), whatever the order of offering. Every
         * offered source stays reachable through {@link #sensorSource(SourceKind)}.
         */
        public Builder sensorSource(SourceKind kind, SensorSource s) {
            offered.put(kind, s);
            if (kind.priority() > sourcePriority) {
                source = s;
                sourcePriority = kind.priority();
            }
            return this;
        }

        /** The source offered as {@code kind}, or null. */
        public SensorSource sensorSource(SourceKind kind) {
            return offered.get(kind);
        }

        /** The kinds of the offered sensor sources, in the order offered. */
        public List<SourceKind> sensorSourceKinds() {
            return Collections.unmodifiableList(new ArrayList<>(offered.keySet()));
        }

        /**
         * Adds an observer of the readings: called each tick with the table the scheduler is
         * about to use (after the chosen source has filled it), e.g. for plots of measured angles.
         * Without a sensor source it is never called: the table then holds no measurement.
         */
        public Builder observeReadings(SensorSource observer) {
            readingObservers.add(observer);
            return this;
        }

        /** Adds columns to the trace, after the module columns. */
        public Builder traceColumns(TraceColumns c) {
            columns.add(c);
            return this;
        }

        /** Writes the CSV trace (PARSL.md §11) to {@code out}; flushed, not closed, at the end. */
        public Builder trace(Writer out) {
            this.trace = out;
            return this;
        }

        /** Stops after {@code seconds} of simulated time (default: when {@code <main>} ends). */
        public Builder duration(double seconds) {
            if (!(seconds >= 0)) {
                throw new IllegalArgumentException("duration must be >= 0 seconds, got " + seconds);
            }
            this.duration = seconds;
            return this;
        }

        /** How ticks are spread over wall-clock time (default: as fast as possible). */
        public Builder pacer(Pacer p) {
            this.pacer = p;
            return this;
        }

        /** Says that a target must be paced to the wall clock (hardware). */
        public Builder requireRealtime() {
            this.realtimeRequired = true;
            return this;
        }

        /** Whether some target asked for wall-clock pacing. */
        public boolean realtimeRequired() {
            return realtimeRequired;
        }

        /** Runs {@code f} after the run, before resources are closed. */
        public Builder onFinish(Consumer<RunOutcome> f) {
            finishers.add(f);
            return this;
        }

        /** Closes {@code c} when the run is over, or when assembly is abandoned ({@link #abandon}). */
        public Builder closeAtEnd(AutoCloseable c) {
            resources.add(c);
            return this;
        }

        /** Closes what the targets opened when the run will not happen (a target failed). */
        public void abandon() {
            closeResources(resources, diagnostics);
            resources.clear();
        }

        /** The run, ready to {@link Run#execute()}. */
        public Run build() {
            if (built) {
                throw new IllegalStateException("the run was already built");
            }
            built = true;
            if (trace != null) {
                TraceWriter w = new TraceWriter(trace);
                columns.forEach(w::addColumns);
                engine.addObserver(w);
            }
            observers.forEach(engine::addObserver);
            engine.setSensorSource(readings());
            return new Run(this);
        }

        private SensorSource readings() {
            if (readingObservers.isEmpty() || source == null) {
                return source;
            }
            SensorSource chosen = source;
            SensorSource[] taps = readingObservers.toArray(new SensorSource[0]);
            return (time, table) -> {
                if (chosen != null) {
                    chosen.read(time, table);
                }
                for (SensorSource tap : taps) {
                    tap.read(time, table);
                }
            };
        }
    }
}
