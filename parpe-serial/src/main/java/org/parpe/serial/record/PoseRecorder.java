package org.parpe.serial.record;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.parpe.serial.bus.BusMaster;
import org.parpe.serial.bus.Reply;
import org.parpe.serial.protocol.Protocol;

/**
 * Captures poses of a group from the bus: {@link #begin} makes the group's modules limp so they
 * can be posed by hand, {@link #capture} reads every angle, {@link #end} makes them hold the last
 * pose.
 */
public final class PoseRecorder {
    private static final int CAPTURE_ATTEMPTS = 6;

    private final BusMaster bus;
    private final int[] modules;
    private final Reply reply = new Reply();

    /** A recorder of {@code modules} (group order) on {@code bus}. */
    public PoseRecorder(BusMaster bus, int[] modules) {
        this.bus = bus;
        this.modules = modules.clone();
    }

    /** Pings every module; returns those that do not answer (nothing is made limp then). */
    public List<Integer> missing() throws IOException {
        List<Integer> out = new ArrayList<>();
        for (int id : modules) {
            if (!bus.ping(id, reply, 3)) {
                out.add(id);
            }
        }
        return out;
    }

    /** Makes every module of the group limp (twice: LIMP has no reply). */
    public void begin() throws IOException {
        for (int pass = 0; pass < 2; pass++) {
            for (int id : modules) {
                bus.send(id, Protocol.LIMP);
            }
        }
    }

    /**
     * Reads the angle of every module into {@code out} (group order); returns the ID of the first
     * module that did not answer, or −1 when the pose is complete.
     */
    public int capture(double[] out) throws IOException {
        for (int i = 0; i < modules.length; i++) {
            // Posing is not time-critical: more attempts than a run's reads.
            if (!bus.read(modules[i], reply, CAPTURE_ATTEMPTS)) {
                return modules[i];
            }
            out[i] = reply.angle;
        }
        return -1;
    }

    /** Makes every module hold where it is (twice, as for {@link #begin}). */
    public void end() throws IOException {
        for (int pass = 0; pass < 2; pass++) {
            for (int id : modules) {
                bus.sendHold(id, false);
            }
        }
    }
}
