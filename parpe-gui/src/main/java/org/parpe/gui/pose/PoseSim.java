package org.parpe.gui.pose;

import java.util.Arrays;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.run.TargetException;
import org.parpe.gui.text.PanelMsg;
import org.parpe.sim.snapshot.SimSnapshot;
import org.parpe.sim.SimTarget;
import org.parpe.sim.Simulator;

/**
 * The simulated robot being posed: a {@link Simulator} stepped on its own thread
 * ("parpe-pose-sim") about in real time while posing is active, its servos holding the angles
 * the sliders (or a drag in the 3D view) ask for, so that the 3D view follows live. The UI sets
 * targets and reads snapshots; both are safe from any thread. The physics never runs on the UI
 * thread.
 */
final class PoseSim implements AutoCloseable {
    private static final long TICK_MS = 10;

    private final ScheduledExecutorService thread = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "parpe-pose-sim");
        t.setDaemon(true);
        return t;
    });
    private final Consumer<String> problems;
    // Written by the UI thread, read by the sim thread: whole arrays are swapped, never changed in place.
    private volatile int[] ids = new int[0];
    private volatile double[] targets = new double[0];
    private volatile Simulator sim;
    private volatile String key = "";
    private ScheduledFuture<?> stepping;
    private long tick;

    /** A posing simulator that reports problems (a robot that cannot be built) to {@code problems}, any thread. */
    PoseSim(Consumer<String> problems) {
        this.problems = problems;
    }

    /**
     * Builds the robot {@code spec} for the script's modules {@code moduleIds} in the background,
     * unless it is the one already built; the joints start straight.
     */
    void build(String spec, int[] moduleIds) {
        String k = spec + Arrays.toString(moduleIds);
        if (k.equals(key)) {
            return;
        }
        key = k;
        thread.execute(() -> {
            Simulator old = sim;
            sim = null;
            if (old != null) {
                old.close();
            }
            try {
                Simulator s = SimTarget.create(spec, moduleIds, new DiagnosticList());
                s.readings(); // binds the commands to the robot's own modules, in ascending ID
                int[] own = s.moduleIds();
                targets = new double[own.length];
                ids = own;
                tick = 0;
                sim = s;
            } catch (TargetException | RuntimeException e) {
                problems.accept(PanelMsg.POSE_CANNOT_POSE_ROBOT.text(spec, e.getMessage()));
            }
        });
    }

    /** Steps the physics in real time (posing) or leaves it still (a run has the 3D view). */
    synchronized void setActive(boolean on) {
        if (on && stepping == null && !thread.isShutdown()) {
            stepping = thread.scheduleWithFixedDelay(this::step, TICK_MS, TICK_MS, TimeUnit.MILLISECONDS);
        } else if (!on && stepping != null) {
            stepping.cancel(false);
            stepping = null;
        }
    }

    private void step() {
        Simulator s = sim;
        if (s == null) {
            return;
        }
        try {
            s.accept(tick, tick * Simulator.DEFAULT_TICK, targets);
            tick++;
        } catch (RuntimeException e) {
            problems.accept(PanelMsg.POSE_SIM_FAILED.text(e));
            sim = null;
        }
    }

    /** Asks module {@code id}'s joint to hold {@code degrees}; ignored for a module the robot lacks. */
    void set(int id, double degrees) {
        int[] own = ids;
        int h = Arrays.binarySearch(own, id);
        double[] now = targets;
        if (h >= 0 && h < now.length) {
            double[] next = now.clone();
            next[h] = degrees;
            targets = next;
        }
    }

    /** The angle module {@code id} is asked to hold, or 0. */
    double target(int id) {
        int h = Arrays.binarySearch(ids, id);
        double[] now = targets;
        return h >= 0 && h < now.length ? now[h] : 0;
    }

    /** Whether the robot is built. */
    boolean ready() {
        return sim != null;
    }

    /** The latest picture of the posed robot, or null before it is built. */
    SimSnapshot snapshot() {
        Simulator s = sim;
        return s == null ? null : s.snapshot();
    }

    @Override
    public void close() {
        setActive(false);
        thread.execute(() -> {
            Simulator s = sim;
            sim = null;
            if (s != null) {
                s.close();
            }
        });
        thread.shutdown();
    }
}
