package org.parpe.sim.sweep;

import org.parpe.sim.text.SimMsg;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.run.SourceKind;
import org.parpe.sim.world.World;
import org.parpe.sim.world.WorldReader;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.Severity;
import org.parpe.core.text.Message;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Parameter;
import org.parpe.core.model.Program;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.TargetException;
import org.parpe.sim.SimMetrics;
import org.parpe.sim.SimTarget;
import org.parpe.sim.Simulator;

/**
 * Runs one script on fresh simulated robots with given parameter values and measures each run.
 * The script and its includes are read once, when the evaluator is loaded; every run binds them
 * to its values (a value can change the robot's modules) and builds its own simulator, so runs
 * may go on several threads at once and a run's result depends only on its values and seed.
 */
public final class Evaluator implements PointRunner {
    private final RunSetup setup;
    private final World world;
    private final Program base;
    /** The robot of the last run, built once for all runs with the same modules. */
    private volatile Robot robotBuilt;

    /** A robot assembled for a script's modules. */
    private record Robot(int[] moduleIds, SimTarget.Blueprint blueprint) {
    }

    private Evaluator(RunSetup setup, World world, Program base, Robot robot) {
        this.setup = setup;
        this.world = world;
        this.base = base;
        this.robotBuilt = robot;
    }

    /**
     * What to run.
     *
     * @param script      the script's file (includes and robot files are found next to it)
     * @param text        its text (an editor's buffer may differ from the file)
     * @param fixed       parameter values that stay the same in every run ({@code --param})
     * @param robot       the simulated robot: {@code GENERATOR[:key=value,...]}, a configuration
     *                    file, or {@link SimTarget#AUTO} to pick it from the script
     * @param duration    simulated seconds per run, > 0
     * @param tick        the scheduler's tick, s
     * @param fallTiltDeg the tilt beyond which the robot counts as fallen over, degrees
     * @param world       the world file every run is in and scored by, or null for the flat floor
     */
    public record Settings(Path script, String text, Map<String, Double> fixed, String robot, double duration,
                           double tick, double fallTiltDeg, Path world) {

        /** Settings for runs on the flat floor. */
        public Settings(Path script, String text, Map<String, Double> fixed, String robot, double duration,
                        double tick, double fallTiltDeg) {
            this(script, text, fixed, robot, duration, tick, fallTiltDeg, null);
        }
    }

    /** Whether the runs are in a world, so that their rows have a score. */
    public boolean scored() {
        return world != null;
    }

    /**
     * Reads the script and its includes, loads it once with its defaults and the fixed values and
     * checks the robot, so that problems shared by every run are reported once, before any run.
     */
    public static Evaluator load(Settings s) throws SweepException {
        return of(new RunSetup(ScriptLoader.read(s.script(), s.text()), s.text(), s.fixed(), s.robot(), s.duration(),
                s.tick(), s.fallTiltDeg(), s.world()));
    }

    /**
     * An evaluator of the script {@code setup} has already read, checked as {@link #load} does;
     * a {@link Lanes lane} makes its own copy with it.
     */
    public static Evaluator of(RunSetup s) throws SweepException {
        if (!(s.duration() > 0) || !Double.isFinite(s.duration())) {
            throw new SweepException(SimMsg.DURATION_NOT_POSITIVE, s.duration());
        }
        if (!(s.tick() > 0) || s.tick() > s.duration()) {
            throw new SweepException(SimMsg.TICK_RANGE, s.tick());
        }
        LoadResult r = ScriptLoader.bind(s.script(), s.fixed());
        if (!r.ok()) {
            List<Diagnostic> problems = r.parameterErrors().isEmpty() ? r.errors() : r.parameterErrors();
            throw problems.isEmpty() ? new SweepException(SimMsg.SCRIPT_DOES_NOT_LOAD, s.script().file()) : first(problems);
        }
        if (r.program().main() == null) {
            throw new SweepException(SimMsg.NO_MAIN, s.script().file());
        }
        World world = null;
        if (s.world() != null) {
            DiagnosticList found = new DiagnosticList();
            world = WorldReader.read(s.world(), found);
            if (world == null) {
                throw first(found.all());
            }
        }
        String spec = SimTarget.AUTO.equals(s.robot()) ? SimTarget.autoSpec(r.program()) : s.robot();
        Robot robot;
        try {
            robot = new Robot(r.program().moduleIds(), SimTarget.blueprint(spec, r.program().moduleIds(), world));
            robot.blueprint().simulator().close();
        } catch (TargetException e) {
            throw new SweepException(e.diagnostics().isEmpty() ? e.getMessage() : e.diagnostics().get(0).format());
        }
        return new Evaluator(s, world, r.program(), robot);
    }

    /** The script's parameters (with their bounds), in file order. */
    public List<Parameter> parameters() {
        return base.parameters();
    }

    /** The parameter values that stay the same in every run. */
    public Map<String, Double> fixed() {
        return setup.fixed();
    }

    /** The script's file. */
    public Path script() {
        return setup.script().file();
    }

    /** The script's text. */
    public String text() {
        return setup.text();
    }

    @Override
    public SweepRow run(Point point, Cancellation cancellation) {
        Map<String, Double> values = new LinkedHashMap<>(setup.fixed());
        values.putAll(point.values());
        LoadResult r = ScriptLoader.bind(setup.script(), values);
        if (!r.ok()) {
            List<Diagnostic> problems = r.parameterErrors().isEmpty() ? r.errors() : r.parameterErrors();
            return failed(point, problems.isEmpty() ? Message.of(SimMsg.NOT_LOADING) : SweepRow.error(problems.get(0)));
        }
        Program program = r.program();
        // the run-time error, kept as a diagnostic so the row shows it in the user's language
        Diagnostic[] runError = new Diagnostic[1];
        DiagnosticSink quiet = d -> {
            if (d.severity() == Severity.ERROR && runError[0] == null) {
                runError[0] = d;
            }
        };
        Simulator sim;
        try {
            sim = robotFor(program).simulator();
        } catch (TargetException e) {
            return failed(point, e.diagnostics().isEmpty() ? Message.verbatim(e.getMessage()) : SweepRow.error(e.diagnostics().get(0)));
        }
        JointTravel travel = new JointTravel();
        SimMetrics[] measured = new SimMetrics[1];
        Run run = Run.builder(program, new RunOptions(setup.tick(), point.seed(), List.of()), quiet)
                .plant(sim)
                .sensorSource(SourceKind.SIMULATOR, sim)
                .observeReadings(travel)
                .onFinish(o -> measured[0] = sim.metrics())
                .closeAtEnd(sim)
                .duration(setup.duration())
                .pacer((self, t) -> {
                    if (cancellation.cancelled()) {
                        self.requestStop();
                    }
                })
                .build();
        RunOutcome outcome = run.execute();
        if (outcome.status() == RunOutcome.Status.STOPPED) {
            return null;
        }
        SimMetrics m = measured[0];
        double time = m.duration();
        return new SweepRow(point, time, m.distance(), m.dx(), time > 0 ? m.dx() / time : 0, m.speed(),
                m.maxTiltDeg(), travel.total(), m.maxTiltDeg() > setup.fallTiltDeg(),
                outcome.status() != RunOutcome.Status.ERROR ? Message.EMPTY
                        : runError[0] != null ? SweepRow.error(runError[0]) : Message.verbatim(outcome.message()),
                m.score() == null ? Double.NaN : m.score().score(), m.score());
    }

    /**
     * The robot for {@code program}'s modules: the last one when they are the same (parameter
     * values rarely change which modules a script has), so that a run builds only its physics
     * world and not the robot's configuration and initial pose again.
     */
    private SimTarget.Blueprint robotFor(Program program) throws TargetException {
        int[] ids = program.moduleIds();
        Robot built = robotBuilt;
        if (built == null || !java.util.Arrays.equals(built.moduleIds(), ids)) {
            String spec = SimTarget.AUTO.equals(setup.robot()) ? SimTarget.autoSpec(program) : setup.robot();
            built = new Robot(ids, SimTarget.blueprint(spec, ids, world));
            robotBuilt = built;
        }
        return built.blueprint();
    }

    /**
     * Runs of this evaluator's script for one worker thread, safe alongside other workers and
     * other simulations in this program: each worker simulates with its own copy of the physics
     * library ({@link Lanes}), which binds the script this evaluator read. Close it to give the
     * copy back.
     */
    Worker worker() {
        ClassLoader loader = Lanes.acquire();
        PointRunner lane;
        try {
            lane = Lanes.runnerIn(loader, setup);
        } catch (RuntimeException | Error e) {
            Lanes.release(loader);
            throw e;
        }
        if (lane == null) {
            // No class path to copy the simulator from (a custom runtime image): one run at a time.
            Lanes.release(loader);
            return new Worker() {
                @Override
                public SweepRow run(Point point, Cancellation cancellation) {
                    synchronized (Evaluator.class) {
                        return Evaluator.this.run(point, cancellation);
                    }
                }

                @Override
                public void close() {
                }
            };
        }
        return new Worker() {
            @Override
            public SweepRow run(Point point, Cancellation cancellation) {
                return lane.run(point, cancellation);
            }

            @Override
            public void close() {
                Lanes.release(loader);
            }
        };
    }

    /** Runs for one thread; see {@link #worker()}. */
    interface Worker extends PointRunner, AutoCloseable {
        @Override
        void close();
    }

    /** The first of {@code problems} as one line: {@code FILE:LINE:COL: error: MESSAGE (and N more)}. */
    private static SweepException first(List<Diagnostic> problems) {
        Diagnostic d = problems.get(0);
        return new SweepException(problems.size() > 1 ? SimMsg.LOAD_ERRORS : SimMsg.LOAD_ERROR, d.pos(),
                d.severity().word(), d.text(), problems.size() - 1);
    }

    private static SweepRow failed(Point point, Message why) {
        double nan = Double.NaN;
        return new SweepRow(point, nan, nan, nan, nan, nan, nan, nan, false, why);
    }
}
