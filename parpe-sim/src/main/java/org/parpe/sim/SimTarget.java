package org.parpe.sim;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.model.Group;
import org.parpe.core.model.Program;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunTarget;
import org.parpe.core.run.SourceKind;
import org.parpe.core.run.TargetException;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RobotConfigs;
import org.parpe.sim.internal.Assembly;
import org.parpe.sim.text.SimMsg;
import org.parpe.sim.world.World;

/**
 * The physics simulator as a run target: builds the robot named by a specification
 * ({@code GENERATOR[:key=value,...]} or a configuration file), warns about script modules the
 * robot lacks, and adds the simulator as a plant, a sensor source ({@link SourceKind#SIMULATOR},
 * below hardware) and trace columns {@code a<ID>}, {@code com_*}. Used by the command line's
 * {@code --sim} and the IDE's Simulator target alike.
 */
public final class SimTarget implements RunTarget {
    /** The choice that guesses the robot from the script ({@link #autoSpec}). */
    public static final String AUTO = "auto";

    private final String spec;
    private final World world;
    private Simulator simulator;

    /** The simulator for {@code spec}; {@value #AUTO} guesses from the script when attached. */
    public SimTarget(String spec) {
        this(spec, null);
    }

    /** The simulator for {@code spec} in {@code world} (null: the flat floor). */
    public SimTarget(String spec, World world) {
        this.spec = spec;
        this.world = world;
    }

    @Override
    public void attach(Run.Builder run) throws TargetException {
        Program program = run.program();
        String resolved = AUTO.equals(spec) ? autoSpec(program) : spec;
        Simulator s = create(resolved, program.moduleIds(), run.diagnostics(), world);
        run.closeAtEnd(s);
        run.plant(s);
        run.sensorSource(SourceKind.SIMULATOR, s);
        run.traceColumns(s.traceColumns());
        // docking (PARSL.md §14): the simulator works the latches and reads the dock sensors
        run.plates(s);
        int[] docks = program.robot().sensors().stream().filter(d -> d.type().equals("dock"))
                .flatMap(d -> d.modules().stream()).mapToInt(Integer::intValue).toArray();
        if (docks.length > 0) {
            run.traceColumns(s.dockSensors(docks));
        }
        simulator = s;
    }

    /** The simulator attached last (null before {@link #attach}). */
    public Simulator simulator() {
        return simulator;
    }

    /**
     * Builds the simulator for {@code spec} and the script's {@code moduleIds}. Warnings (modules
     * the robot lacks) go to {@code diags}; a specification or configuration file with errors
     * throws, carrying the located errors.
     */
    public static Simulator create(String spec, int[] moduleIds, DiagnosticSink diags) throws TargetException {
        return create(spec, moduleIds, diags, null);
    }

    /**
     * As {@link #create(String, int[], DiagnosticSink)}, the robot at the start of {@code world}
     * (null: the flat floor); a robot that does not fit the world there ({@link Simulator#misfit}) is a warning.
     */
    public static Simulator create(String spec, int[] moduleIds, DiagnosticSink diags, World world)
            throws TargetException {
        Blueprint b = blueprint(spec, moduleIds, world);
        for (Diagnostic d : b.warnings()) {
            diags.report(d);
        }
        Simulator s = b.simulator();
        s.misfit().ifPresent(misfit -> diags.warning(org.parpe.core.diag.SourcePos.origin("simulated robot " + spec),
                SimMsg.ROBOT_MISFIT, misfit));
        return s;
    }

    /**
     * The robot for {@code spec} and {@code moduleIds}, resolved, checked and assembled once, from
     * which {@link Blueprint#simulator()} builds fresh simulators: for many runs of one robot
     * (a sweep), which then build only the physics world each. Throws as {@link #create} does.
     */
    public static Blueprint blueprint(String spec, int[] moduleIds) throws TargetException {
        return blueprint(spec, moduleIds, null);
    }

    /** As {@link #blueprint(String, int[])}, for simulators in {@code world} (null: the flat floor). */
    public static Blueprint blueprint(String spec, int[] moduleIds, World world) throws TargetException {
        DiagnosticList found = new DiagnosticList();
        RobotConfig config = RobotConfigs.resolve(spec, moduleIds, found);
        Assembly assembly = config == null ? null : Assembly.build(config, found);
        if (assembly == null) {
            long n = found.errorCount();
            throw new TargetException((n == 1 ? org.parpe.core.text.Msg.CANNOT_BUILD_ROBOT_ONE
                    : org.parpe.core.text.Msg.CANNOT_BUILD_ROBOT).text(spec, n), found.all());
        }
        RobotConfigs.checkModules(config, moduleIds, found);
        return new Blueprint(config, assembly, world, List.copyOf(found.all()));
    }

    /**
     * A resolved and assembled robot (immutable, so usable from any thread), and the warnings
     * its resolution gave.
     */
    public static final class Blueprint {
        private final RobotConfig config;
        private final Assembly assembly;
        private final World world;
        private final List<Diagnostic> warnings;

        private Blueprint(RobotConfig config, Assembly assembly, World world, List<Diagnostic> warnings) {
            this.config = config;
            this.assembly = assembly;
            this.world = world;
            this.warnings = warnings;
        }

        /** Modules of the script that the robot lacks, and the like. */
        public List<Diagnostic> warnings() {
            return warnings;
        }

        /** A fresh simulator of the robot, in its initial pose. */
        public Simulator simulator() {
            return new Simulator(config, assembly, world);
        }
    }

    /**
     * The standard robot that fits {@code program}: guessed from the file name and the group
     * names (wheel, loop, centipede, humanoid), kept only if it has every module of the script
     * and the script uses at least three quarters of its modules; otherwise a snake of the
     * script's modules.
     */
    public static String autoSpec(Program program) {
        String guess = guess(program);
        if (guess.equals("snake")) {
            return guess;
        }
        int[] ids = program.moduleIds();
        DiagnosticList diags = new DiagnosticList();
        RobotConfig config = RobotConfigs.resolve(guess, ids, diags);
        if (config == null || RobotConfigs.checkModules(config, ids, diags) > 0
                || 4L * ids.length < 3L * config.moduleIds().length) {
            return "snake";
        }
        return guess;
    }

    private static String guess(Program program) {
        String file = Path.of(program.file()).getFileName().toString().toLowerCase(Locale.ROOT);
        for (String g : new String[] {"centipede", "wheel", "loop", "humanoid", "snake"}) {
            if (file.contains(g)) {
                return g;
            }
        }
        boolean left = false;
        boolean right = false;
        for (Group g : program.robot().groups()) {
            String n = g.name().toLowerCase(Locale.ROOT);
            if (n.contains("wheel")) {
                return "wheel";
            }
            if (n.contains("loop") || n.contains("ring")) {
                return "loop";
            }
            left |= n.startsWith("left");
            right |= n.startsWith("right");
            if (n.contains("leg") || n.contains("arm")) {
                left = right = true;
            }
        }
        return left && right ? "centipede" : "snake";
    }
}
