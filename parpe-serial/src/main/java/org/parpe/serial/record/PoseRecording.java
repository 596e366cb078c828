package org.parpe.serial.record;

import java.util.ArrayList;
import java.util.List;
import org.parpe.serial.text.SerialMsg;

/**
 * Poses captured from one group, in order, each with the seconds since the previous capture.
 * Mutable while recording; {@link RecordingWriter} turns it into PARSL.
 */
public final class PoseRecording {
    /** What a group's name must match. */
    private static final String NAME = "[A-Za-z_][A-Za-z0-9_]*";
    private final String group;
    private final int[] modules;
    private final List<double[]> poses = new ArrayList<>();
    private final List<Double> intervals = new ArrayList<>();

    /** An empty recording of {@code group}, whose modules are {@code modules} in group order. */
    public PoseRecording(String group, int[] modules) {
        if (!group.matches(NAME)) {
            throw new IllegalArgumentException(SerialMsg.REC_GROUP_NAME.text(NAME, group));
        }
        if (modules.length == 0) {
            throw new IllegalArgumentException(SerialMsg.REC_NO_MODULES.text(group));
        }
        this.group = group;
        this.modules = modules.clone();
    }

    /** Appends a pose (angles in group order) captured {@code interval} seconds after the previous one. */
    public void add(double[] angles, double interval) {
        if (angles.length != modules.length) {
            throw new IllegalArgumentException(SerialMsg.REC_POSE_ANGLES.text(group, modules.length, angles.length));
        }
        poses.add(angles.clone());
        intervals.add(interval);
    }

    /** The group's name. */
    public String group() {
        return group;
    }

    /** The group's modules, in group order. */
    public int[] modules() {
        return modules.clone();
    }

    /** Number of poses. */
    public int size() {
        return poses.size();
    }

    /** Pose {@code i} (a copy). */
    public double[] pose(int i) {
        return poses.get(i).clone();
    }

    /** Seconds between pose {@code i − 1} and pose {@code i} (for 0: since the recording started). */
    public double interval(int i) {
        return intervals.get(i);
    }
}
