package org.parpe.gui.pose;

import java.util.ArrayList;
import java.util.List;
import org.parpe.gui.text.PanelMsg;
import org.parpe.serial.record.PoseRecording;

/**
 * The poses of one group being recorded: each pose has an angle per module (group order) and
 * the seconds since the previous pose. Mutable, UI thread only; every edit keeps the list valid
 * (angles in −90…90°, intervals in 0.01…600 s).
 */
public final class PoseList {
    /** Shortest interval between poses, s (the default tick). */
    public static final double MIN_INTERVAL = 0.01;
    /** Longest interval between poses, s. */
    public static final double MAX_INTERVAL = 600;

    /** One pose: angles in group order (degrees) and seconds since the previous pose. */
    public record Pose(double[] angles, double interval) {
        public Pose {
            angles = angles.clone();
        }

        @Override
        public double[] angles() {
            return angles.clone();
        }
    }

    private final String group;
    private final int[] modules;
    private final List<Pose> poses = new ArrayList<>();

    /** An empty list for {@code group}, whose modules are {@code modules} in group order. */
    public PoseList(String group, int[] modules) {
        this.group = group;
        this.modules = modules.clone();
    }

    /** The group's name. */
    public String group() {
        return group;
    }

    /** The group's modules in group order. */
    public int[] modules() {
        return modules.clone();
    }

    /** Number of poses. */
    public int size() {
        return poses.size();
    }

    /** Pose {@code i}. */
    public Pose get(int i) {
        return poses.get(i);
    }

    /** Appends a pose; returns its index. */
    public int add(double[] angles, double interval) {
        poses.add(check(angles, interval));
        return poses.size() - 1;
    }

    /** Inserts a copy of pose {@code i} after it; returns the copy's index. */
    public int duplicate(int i) {
        poses.add(i + 1, poses.get(i));
        return i + 1;
    }

    /** Removes pose {@code i}. */
    public void remove(int i) {
        poses.remove(i);
    }

    /** Moves pose {@code i} by {@code by} places (−1 up, +1 down), if it stays in the list; returns its new index. */
    public int move(int i, int by) {
        int j = i + by;
        if (j < 0 || j >= poses.size()) {
            return i;
        }
        poses.add(j, poses.remove(i));
        return j;
    }

    /** Sets the seconds between pose {@code i − 1} and pose {@code i}. */
    public void retime(int i, double interval) {
        poses.set(i, check(poses.get(i).angles(), interval));
    }

    /** Replaces the angles of pose {@code i}. */
    public void set(int i, double[] angles) {
        poses.set(i, check(angles, poses.get(i).interval()));
    }

    /**
     * Mirrors pose {@code i}: the angles of positions {@code k} and {@code swap[k]} trade places
     * (left and right modules); a position that is its own partner is negated when
     * {@code negateUnpaired} (a group with no left/right partner turns the other way, like {@code !}).
     */
    public void mirror(int i, int[] swap, boolean negateUnpaired) {
        double[] a = poses.get(i).angles();
        double[] m = new double[a.length];
        for (int k = 0; k < a.length; k++) {
            m[k] = swap[k] == k ? (negateUnpaired ? -a[k] : a[k]) : a[swap[k]];
            m[k] = m[k] == 0 ? 0 : m[k];
        }
        poses.set(i, check(m, poses.get(i).interval()));
    }

    /** The total of the intervals after the first pose, s. */
    public double duration() {
        double sum = 0;
        for (int i = 1; i < poses.size(); i++) {
            sum += poses.get(i).interval();
        }
        return sum;
    }

    /** The poses as a recording for {@link org.parpe.serial.record.RecordingWriter}. */
    public PoseRecording toRecording() {
        PoseRecording r = new PoseRecording(group, modules);
        for (Pose p : poses) {
            r.add(p.angles(), p.interval());
        }
        return r;
    }

    private Pose check(double[] angles, double interval) {
        if (angles.length != modules.length) {
            throw new IllegalArgumentException(PanelMsg.POSE_ANGLE_COUNT.text(group, modules.length, angles.length));
        }
        for (double a : angles) {
            if (!(a >= -90 && a <= 90)) {
                throw new IllegalArgumentException(PanelMsg.POSE_ANGLE_RANGE.text(a));
            }
        }
        if (!(interval >= MIN_INTERVAL && interval <= MAX_INTERVAL)) {
            throw new IllegalArgumentException(PanelMsg.POSE_INTERVAL_RANGE.text(MIN_INTERVAL, (int) MAX_INTERVAL, interval));
        }
        return new Pose(angles, interval);
    }

    /** Parses a time typed by the user; null if it is not a number in range. */
    public static Double parseInterval(String text) {
        Double v = org.parpe.core.lang.Numbers.parsePlain(text.trim().replaceFirst("\\s*s$", ""));
        return v != null && v >= MIN_INTERVAL && v <= MAX_INTERVAL ? v : null;
    }

    /** A copy of every pose, for comparing and undoing. */
    public List<Pose> poses() {
        return List.copyOf(poses);
    }
}
