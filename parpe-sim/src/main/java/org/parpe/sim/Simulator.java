package org.parpe.sim;

import java.util.Arrays;
import java.util.concurrent.atomic.AtomicIntegerArray;
import java.util.stream.Collectors;
import org.ode4j.math.DMatrix3C;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.run.SourceKind;
import org.parpe.core.sensor.Channel;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.run.JointSink;
import org.parpe.core.run.PlateSink;
import org.parpe.core.run.RunInfo;
import org.parpe.core.run.SensorSource;
import org.parpe.core.sensor.SensorTable;
import org.parpe.core.run.TraceColumns;
import org.parpe.core.text.Message;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.internal.Assembly;
import org.parpe.sim.internal.Docking;
import org.parpe.sim.internal.PhysicsParams;
import org.parpe.sim.internal.PhysicsWorld;
import org.parpe.sim.internal.SnapshotBuffer;
import org.parpe.sim.snapshot.SimSnapshot;
import org.parpe.sim.text.SimMsg;
import org.parpe.sim.world.World;

/**
 * A PolyBot simulated with rigid-body physics (ODE4j) on a flat floor. As a {@link JointSink}
 * it takes each tick's commanded angles and advances the physics by one tick (in fixed
 * sub-steps), so that the next {@link SensorSource#read} sees the plant one tick later; as a
 * sensor source it fills the measured {@code angle}, {@code accel}, {@code touch} and
 * {@code dock} readings of PARSL.md §10 and §14; as a plate sink it arms and releases the latches
 * of connection plates (§14, {@link Docking}). Runs are deterministic: the same configuration and commands give the same
 * motion, bit for bit.
 *
 * <p>Threads: the engine thread calls the sink and source methods and {@link #step(int)};
 * {@link #snapshot()}, {@link #setLimp(boolean)} and {@link #setLimp(int, boolean)} may be
 * called from any thread (limp changes take effect at the next tick).
 */
public final class Simulator implements JointSink, SensorSource, PlateSink, AutoCloseable {
    /** Tick length used by {@link #step(int)} before a run has started, s. */
    public static final double DEFAULT_TICK = 0.01;

    private static final int NO_REQUEST = 0;
    private static final int REQUEST_LIMP = 1;
    private static final int REQUEST_HOLD = 2;

    private final RobotConfig config;
    private final PhysicsWorld world;
    private final SnapshotBuffer snapshots;
    private final int[] hingeIds;
    private final AtomicIntegerArray limpRequests;
    private final MotionTracker progress;
    private int[] programHinge = new int[0];
    private int[] programIds = new int[0];
    private double dt = DEFAULT_TICK;
    private final double[] traceValues;
    private final World scene;
    private final double[] objectCentre = new double[3];
    private volatile double liveScore = Double.NaN;
    private final Referee referee;
    private final Docking docking;
    /** Per program module index and plate, its docking site (−1: not simulated). */
    private int[] plateSite = new int[0];
    /** Program module indices whose dock sensor is read (PARSL.md §14), ascending. */
    private int[] dockModules = new int[0];
    private final double[] dockValues;

    /** A simulator of {@code config}; throws {@link IllegalArgumentException} if it is not valid. */
    public Simulator(RobotConfig config) {
        this(config, assemble(config));
    }

    /**
     * A simulator of {@code config} in {@code scene}, the robot at the world's start (null: on
     * the flat floor); throws {@link IllegalArgumentException} if the configuration is not valid.
     */
    public Simulator(RobotConfig config, World scene) {
        this(config, assemble(config), scene);
    }

    /** {@code config}'s pieces placed in their initial pose; throws {@link IllegalArgumentException} if it is not valid. */
    static Assembly assemble(RobotConfig config) {
        DiagnosticList diags = new DiagnosticList();
        Assembly assembly = Assembly.build(config, diags);
        if (assembly == null) {
            throw new IllegalArgumentException("invalid robot configuration '" + config.name() + "':\n"
                    + diags.all().stream().map(Object::toString).collect(Collectors.joining("\n")));
        }
        return assembly;
    }

    /** A simulator of {@code config}, already assembled (immutable, shared by many simulators). */
    Simulator(RobotConfig config, Assembly assembly) {
        this(config, assembly, null);
    }

    /** A simulator of {@code config}, already assembled, in {@code scene} (null: the flat floor). */
    Simulator(RobotConfig config, Assembly assembly, World scene) {
        this.config = config;
        World.Start s = scene == null ? null : scene.start();
        world = new PhysicsWorld(s == null ? assembly : assembly.startingAt(s.x(), s.y(), s.z(), s.yaw(), s.pitch()),
                PhysicsParams.defaults(), scene);
        this.scene = scene;
        hingeIds = assembly.hinges().stream().mapToInt(Assembly.Hinge::moduleId).toArray();
        limpRequests = new AtomicIntegerArray(hingeIds.length);
        progress = new MotionTracker(world);
        snapshots = new SnapshotBuffer(world);
        traceValues = new double[hingeIds.length + 3 + 2 * world.objectCount()];
        docking = world.docking();
        dockValues = new double[2 * hingeIds.length];
        referee = scene == null ? null : new Referee(world, scene);
        if (referee != null) {
            referee.reset(progress.com());
        }
    }

    /** The world the robot is in, or null on the flat floor. */
    public World world() {
        return scene;
    }

    /** How deep a robot may rest in a world's scenery at its start and still fit (rubble is uneven), m. */
    private static final double FIT_DEPTH = 0.005;

    /**
     * Why the robot does not fit its world at the start, to follow the robot's name ("does not fit
     * the world W.xml: …", {@link SimMsg#ROBOT_MISFIT}), or empty when it fits (or on the flat
     * floor): it starts inside the world's walls, ramps, rubble or objects, or outside its arena.
     */
    public java.util.Optional<Message> misfit() {
        if (scene == null) {
            return java.util.Optional.empty();
        }
        String name = scene.name().substring(Math.max(scene.name().lastIndexOf('/'), scene.name().lastIndexOf('\\')) + 1);
        double[] com = progress.com();
        World.Region arena = scene.arena();
        if (arena != null && !arena.contains(com[0], com[1])) {
            return java.util.Optional.of(Message.of(SimMsg.MISFIT_ARENA, name, m2(com[0]), m2(com[1]), m2(arena.x0()),
                    m2(arena.x1()), m2(arena.y0()), m2(arena.y1())));
        }
        double depth = world.sceneryOverlap();
        if (depth > FIT_DEPTH) {
            return java.util.Optional.of(Message.of(SimMsg.MISFIT_INSIDE, name,
                    String.format(java.util.Locale.ROOT, "%.0f", depth * 1000)));
        }
        return java.util.Optional.empty();
    }

    /** Metres with two decimals and a point, for messages. */
    private static String m2(double v) {
        return String.format(java.util.Locale.ROOT, "%.2f", v);
    }

    /** How far lever {@code i} of the world is turned from rest, degrees. */
    public double leverAngle(int i) {
        return Math.toDegrees(world.leverAngle(i));
    }

    /** The score so far in the world, after the last tick (any thread; NaN on the flat floor). */
    public double liveScore() {
        return liveScore;
    }

    /** Writes the centre of mass of the world's movable object {@code i} into {@code out[0..2]} (tests). */
    public void objectCentre(int i, double[] out) {
        world.objectCentre(i, out);
    }

    /** The configuration simulated. */
    public RobotConfig config() {
        return config;
    }

    /** The logical IDs of the simulated segments, ascending. */
    public int[] moduleIds() {
        return hingeIds.clone();
    }

    @Override
    public void start(RunInfo info) {
        dt = info.dt();
        bind(info.moduleIds());
        if (dockModules.length > 0) {
            docking.update(true);
            captureDock();
        }
        progress.reset();
        if (referee != null) {
            referee.reset(progress.com());
        }
    }

    /** Maps the program's module order onto the simulated hinges (−1 where the robot has no such module). */
    private void bind(int[] ids) {
        programIds = ids.clone();
        programHinge = new int[ids.length];
        for (int i = 0; i < ids.length; i++) {
            programHinge[i] = Arrays.binarySearch(hingeIds, ids[i]);
            programHinge[i] = programHinge[i] < 0 ? -1 : programHinge[i];
        }
        plateSite = new int[2 * ids.length];
        for (int i = 0; i < ids.length; i++) {
            plateSite[2 * i] = programHinge[i] < 0 ? -1 : docking.site(ids[i], 0);
            plateSite[2 * i + 1] = programHinge[i] < 0 ? -1 : docking.site(ids[i], 1);
        }
    }

    /**
     * Reads the {@code dock} sensors of the script's modules {@code ids} (PARSL.md §14) and adds
     * their trace columns {@code d<ID>_<P>}; call before the run starts.
     */
    public TraceColumns dockSensors(int[] ids) {
        int[] sorted = ids.clone();
        Arrays.sort(sorted);
        dockModules = Arrays.stream(sorted).filter(id -> Arrays.binarySearch(hingeIds, id) >= 0).toArray();
        int[] shown = dockModules.clone();
        return new TraceColumns() {
            @Override
            public String[] names() {
                String[] names = new String[2 * shown.length];
                for (int i = 0; i < shown.length; i++) {
                    names[2 * i] = "d" + shown[i] + "_0";
                    names[2 * i + 1] = "d" + shown[i] + "_1";
                }
                return names;
            }

            @Override
            public void values(double[] out) {
                System.arraycopy(dockValues, 0, out, 0, 2 * shown.length);
            }
        };
    }

    @Override
    public void plates(long tick, double time, byte[] actions, SourcePos[] where) {
        for (int j = 0; j < actions.length && j < plateSite.length; j++) {
            int site = plateSite[j];
            if (site < 0 || actions[j] == NONE) {
                continue;
            }
            if (actions[j] == ARM) {
                docking.arm(site);
                progress.mayRoll();
            } else {
                docking.release(site);
            }
        }
    }

    /** The dock reading of plate {@code plate} of module {@code id}: 0 free, 1 in reach, 2 latched (−1: no such module). */
    public int dock(int id, int plate) {
        int site = docking.site(id, plate);
        return site < 0 ? -1 : docking.reading(site);
    }

    @Override
    public void accept(long tick, double time, double[] commanded) {
        for (int i = 0; i < programHinge.length && i < commanded.length; i++) {
            if (programHinge[i] >= 0) {
                world.setTarget(programHinge[i], Math.toRadians(commanded[i]));
            }
        }
        captureTrace();
        progress.mark();
        if (referee != null) {
            referee.mark();
        }
        advance(1);
    }

    /** Advances {@code ticks} ticks holding the current targets (posing, tests). */
    public void step(int ticks) {
        advance(ticks);
    }

    private void advance(int ticks) {
        for (int t = 0; t < ticks; t++) {
            applyLimpRequests();
            world.advance(dt);
            if (docking.update(dockModules.length > 0)) {
                captureDock();
            }
            progress.update();
            if (referee != null) {
                referee.update(progress.com(), progress.maxTilt());
                liveScore = referee.livePoints();
            }
            snapshots.publish();
        }
    }

    /** Makes every servo limp (back-drivable, for posing) or holding. */
    public void setLimp(boolean limp) {
        for (int h = 0; h < hingeIds.length; h++) {
            limpRequests.set(h, limp ? REQUEST_LIMP : REQUEST_HOLD);
        }
    }

    /** Makes the servo of module {@code id} limp or holding; unknown IDs are ignored. */
    public void setLimp(int id, boolean limp) {
        int h = Arrays.binarySearch(hingeIds, id);
        if (h >= 0) {
            limpRequests.set(h, limp ? REQUEST_LIMP : REQUEST_HOLD);
        }
    }

    private void applyLimpRequests() {
        for (int h = 0; h < hingeIds.length; h++) {
            int r = limpRequests.getAndSet(h, NO_REQUEST);
            if (r != NO_REQUEST) {
                world.setLimp(h, r == REQUEST_LIMP);
                if (r == REQUEST_HOLD) {
                    world.setTarget(h, world.angle(h));
                }
            }
        }
    }

    @Override
    public void read(double time, SensorTable table) {
        for (int i = 0; i < programHinge.length && i < table.moduleCount(); i++) {
            int h = programHinge[i];
            if (h < 0) {
                continue;
            }
            table.set(i, Channel.ANGLE, Math.toDegrees(world.angle(h)));
            DMatrix3C r = world.pieceRotation(world.assembly().hinges().get(h).base());
            // Gravity points down (−z), so axis·ĝ is minus the axis's z component.
            table.set(i, Channel.ACCEL_X, -100 * r.get(2, 0));
            table.set(i, Channel.ACCEL_Y, -100 * r.get(2, 1));
            table.set(i, Channel.ACCEL_Z, -100 * r.get(2, 2));
            int touch = world.touch(h);
            table.set(i, Channel.TOUCH_LEFT, (touch & 1) != 0 ? 1 : 0);
            table.set(i, Channel.TOUCH_RIGHT, (touch & 2) != 0 ? 1 : 0);
            int d = Arrays.binarySearch(dockModules, programIds[i]);
            if (d >= 0) {
                table.set(i, Channel.DOCK_0, dockValues[2 * d]);
                table.set(i, Channel.DOCK_1, dockValues[2 * d + 1]);
            }
        }
    }

    /** A sensor table for the simulator's own modules, filled with the current readings (tests, IDE). */
    public SensorTable readings() {
        if (programIds.length == 0) {
            bind(hingeIds);
        }
        SensorTable t = new SensorTable(programIds);
        read(world.time(), t);
        return t;
    }

    /**
     * Trace columns {@code a<ID>} for the program's simulated modules, {@code com_x,com_y,com_z},
     * and in a world {@code NAME_x,NAME_y} for each movable object.
     */
    public TraceColumns traceColumns() {
        return new TraceColumns() {
            @Override
            public String[] names() {
                String[] names = new String[measuredCount() + 3 + 2 * world.objectCount()];
                int k = 0;
                for (int i = 0; i < programHinge.length; i++) {
                    if (programHinge[i] >= 0) {
                        names[k++] = SourceKind.SIMULATOR.column(programIds[i]);
                    }
                }
                names[k++] = "com_x";
                names[k++] = "com_y";
                names[k++] = "com_z";
                for (int i = 0; i < world.objectCount(); i++) {
                    names[k++] = scene.objects().get(i).name() + "_x";
                    names[k++] = scene.objects().get(i).name() + "_y";
                }
                return names;
            }

            @Override
            public void values(double[] out) {
                System.arraycopy(traceValues, 0, out, 0, measuredCount() + 3 + 2 * world.objectCount());
            }
        };
    }

    private int measuredCount() {
        int n = 0;
        for (int h : programHinge) {
            n += h >= 0 ? 1 : 0;
        }
        return n;
    }

    /** Keeps the measured angles and centre of mass of the current tick, before the plant moves on. */
    private void captureTrace() {
        int k = 0;
        for (int h : programHinge) {
            if (h >= 0) {
                traceValues[k++] = Math.toDegrees(world.angle(h));
            }
        }
        progress.centerOfMass(traceValues, k);
        k += 3;
        for (int i = 0; i < world.objectCount(); i++) {
            world.objectCentre(i, objectCentre);
            traceValues[k++] = objectCentre[0];
            traceValues[k++] = objectCentre[1];
        }
    }

    /** Keeps the dock readings the next tick's sensors read (and its trace row shows), after the physics moved. */
    private void captureDock() {
        for (int d = 0; d < dockModules.length; d++) {
            int i = Arrays.binarySearch(programIds, dockModules[d]);
            dockValues[2 * d] = i < 0 ? 0 : docking.reading(plateSite[2 * i]);
            dockValues[2 * d + 1] = i < 0 ? 0 : docking.reading(plateSite[2 * i + 1]);
        }
    }

    /** The latest published snapshot; safe from any thread. */
    public SimSnapshot snapshot() {
        return snapshots.snapshot();
    }

    /**
     * Distance, speed and tilt from the start of the run (or construction) to the last tick the
     * simulator was given, so a run of {@code --duration D} measures exactly {@code D} seconds;
     * after {@link #step} without a run, to the current state.
     */
    public SimMetrics metrics() {
        return referee == null ? progress.metrics() : progress.metrics().withScore(referee.score());
    }

    /** Simulated time, s. */
    public double time() {
        return world.time();
    }

    /** Whether any body's state has become non-finite. */
    public boolean hasNaN() {
        return world.hasNaN();
    }

    /** Kinetic plus potential energy of the robot, J. */
    public double energy() {
        return world.energy();
    }

    /** Total mass, kg. */
    public double totalMass() {
        return world.totalMass();
    }

    @Override
    public void close() {
        world.close();
    }
}
