package org.parpe.serial.record;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.parpe.serial.servo.ServoBus;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.profile.ServoMapping;

/**
 * Captures poses of a group from a servo bus of any protocol: {@link #begin} turns the group's
 * torque off so it can be posed by hand, {@link #capture} reads every present position as a joint
 * angle (through the profile's zero and direction), {@link #end} makes the group hold the last pose.
 */
public final class PoseRecorder {
    private static final int CAPTURE_ATTEMPTS = 6;

    private final ServoBus bus;
    private final ServoMapping[] group;
    private final int[] ids;
    private final ServoModel[] models;
    private final double[] degrees;
    private final int[] errors;

    /** A recorder of {@code group} (group order) on {@code bus}. */
    public PoseRecorder(ServoBus bus, List<ServoMapping> group) {
        this.bus = bus;
        this.group = group.toArray(new ServoMapping[0]);
        int n = this.group.length;
        ids = new int[n];
        models = new ServoModel[n];
        for (int i = 0; i < n; i++) {
            ids[i] = this.group[i].servo();
            models[i] = this.group[i].model();
        }
        degrees = new double[n];
        errors = new int[n];
    }

    /** Pings every servo; returns the modules whose servo does not answer (nothing is made limp then). */
    public List<Integer> missing() throws IOException {
        List<Integer> out = new ArrayList<>();
        for (ServoMapping m : group) {
            if (bus.ping(m.servo(), 3) < 0) {
                out.add(m.module());
            }
        }
        return out;
    }

    /** Turns the torque of the group off (twice: it has no reply). */
    public void begin() throws IOException {
        for (int pass = 0; pass < 2; pass++) {
            bus.torque(ids, models, ids.length, false);
        }
    }

    /**
     * Reads the joint angle of every module into {@code out} (group order); returns the module ID
     * of the first servo that did not answer, or −1 when the pose is complete.
     */
    public int capture(double[] out) throws IOException {
        int silent = captureServoAngles(out);
        for (int i = 0; silent < 0 && i < group.length; i++) {
            out[i] = group[i].jointAngle(out[i]);
        }
        return silent;
    }

    /**
     * Reads the servo angle (before zero and direction) of every module into {@code out} (group
     * order); returns the module ID of the first servo that did not answer, or −1.
     */
    public int captureServoAngles(double[] out) throws IOException {
        boolean[] have = new boolean[group.length];
        // Posing is not time-critical: more attempts than a run's reads.
        for (int attempt = 0; attempt < CAPTURE_ATTEMPTS; attempt++) {
            bus.readPositions(ids, models, ids.length, degrees, errors);
            boolean all = true;
            for (int i = 0; i < group.length; i++) {
                if (errors[i] != ServoBus.NO_REPLY && !have[i]) {
                    have[i] = true;
                    out[i] = degrees[i];
                }
                all &= have[i];
            }
            if (all) {
                return -1;
            }
        }
        for (int i = 0; i < group.length; i++) {
            if (!have[i]) {
                return group[i].module();
            }
        }
        return -1;
    }

    /** Makes every servo of the group hold where it is. */
    public void end() throws IOException {
        bus.holdHere(ids, models, ids.length);
    }
}
