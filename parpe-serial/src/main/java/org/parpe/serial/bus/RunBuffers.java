package org.parpe.serial.bus;

import java.util.function.Consumer;
import org.parpe.core.sensor.Channel;
import org.parpe.core.sensor.SensorTable;
import org.parpe.serial.protocol.Protocol;

/**
 * The hand-over between the engine thread and the bus thread: the newest setpoints (clamped to
 * the joint range) and the newest readings. Every method locks this object; nothing allocates
 * after construction.
 */
final class RunBuffers {
    private static final int FIELDS = 6;

    final int[] ids;
    final boolean[] driven;
    private final double[] pending;
    private final double[] measured;
    private final boolean[] have;
    private final boolean[] clampWarned;
    private int seq;
    private boolean fresh;
    private boolean hasSetpoints;
    private long clamps;

    RunBuffers(int[] ids) {
        this.ids = ids.clone();
        driven = new boolean[ids.length];
        pending = new double[ids.length];
        measured = new double[ids.length * FIELDS];
        have = new boolean[ids.length];
        clampWarned = new boolean[ids.length];
    }

    /** Index of module {@code id}, or −1. */
    int indexOf(int id) {
        int i = java.util.Arrays.binarySearch(ids, id);
        return i >= 0 ? i : -1;
    }

    /**
     * Takes the setpoints of one tick. A value beyond ±90° is clamped (warned once per module,
     * counted always); a non-finite one keeps the previous setpoint.
     */
    synchronized void accept(long tick, double[] commanded, Consumer<String> warn) {
        for (int i = 0; i < ids.length; i++) {
            double v = commanded[i];
            if (!Double.isFinite(v)) {
                continue;
            }
            if (Math.abs(v) > Protocol.JOINT_LIMIT_DEG) {
                double c = Math.copySign(Protocol.JOINT_LIMIT_DEG, v);
                clamps++;
                if (!clampWarned[i]) {
                    clampWarned[i] = true;
                    warn.accept(String.format(java.util.Locale.ROOT, "warning: module %d commanded %.2f° at tick %d, "
                            + "outside the joint range ±%.0f°; sending %.0f° (further clamps are counted)",
                            ids[i], v, tick, Protocol.JOINT_LIMIT_DEG, c));
                }
                v = c;
            }
            pending[i] = v;
        }
        seq = (int) (tick & 0xFFFF);
        fresh = true;
        hasSetpoints = true;
        notifyAll();
    }

    /**
     * Writes the setpoints into {@code wire} (slot = ID − {@code first}) if new ones came or
     * {@code keepalive} is set; returns the sequence number, or −1 when there is nothing to send.
     */
    synchronized int take(short[] wire, int first, boolean keepalive) {
        if (!hasSetpoints || !(fresh || keepalive)) {
            return -1;
        }
        for (int i = 0; i < ids.length; i++) {
            if (ids[i] <= Protocol.MAX_MODULE_ID) {
                // A module that is not (or no longer) driven gets "no change", never a stale value.
                wire[ids[i] - first] = driven[i] ? Protocol.toWire(pending[i]) : Protocol.NO_CHANGE;
            }
        }
        fresh = false;
        return seq;
    }

    /** Waits up to {@code millis} for new setpoints. */
    synchronized void awaitFresh(long millis) throws InterruptedException {
        if (!fresh) {
            wait(millis);
        }
    }

    /** Stores a module's reading (a STATUS, or a PONG's angle when {@code full} is false). */
    synchronized void store(int index, Reply r, boolean full) {
        int b = index * FIELDS;
        measured[b] = r.angle;
        if (full) {
            for (int a = 0; a < 3; a++) {
                measured[b + 1 + a] = r.accel[a];
            }
            measured[b + 4] = (r.touch & Protocol.Touch.LEFT.bit()) != 0 ? 1 : 0;
            measured[b + 5] = (r.touch & Protocol.Touch.RIGHT.bit()) != 0 ? 1 : 0;
        }
        if (!hasSetpoints) {
            pending[index] = r.angle;
        }
        have[index] = true;
    }

    /**
     * Copies readings into {@code table}; a module never read shows its last setpoint as its
     * angle, as without hardware.
     */
    synchronized void copyTo(SensorTable table) {
        for (int i = 0; i < ids.length; i++) {
            int b = i * FIELDS;
            if (!have[i]) {
                table.set(i, Channel.ANGLE, pending[i]);
                continue;
            }
            table.set(i, Channel.ANGLE, measured[b]);
            table.set(i, Channel.ACCEL_X, measured[b + 1]);
            table.set(i, Channel.ACCEL_Y, measured[b + 2]);
            table.set(i, Channel.ACCEL_Z, measured[b + 3]);
            table.set(i, Channel.TOUCH_LEFT, measured[b + 4]);
            table.set(i, Channel.TOUCH_RIGHT, measured[b + 5]);
        }
    }

    /** The measured angle of the module at {@code index}, or NaN before any reading. */
    synchronized double measuredAngle(int index) {
        return have[index] ? measured[index * FIELDS] : Double.NaN;
    }

    /** Setpoints clamped so far. */
    synchronized long clamps() {
        return clamps;
    }
}
