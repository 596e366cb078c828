package org.parpe.sim.config;

import java.util.ArrayList;
import java.util.List;

/**
 * The standard configurations. Module IDs are assigned in the order documented in
 * {@code docs/simulator.md}, so that the example scripts' groups drive the intended joints.
 */
final class Generators {
    private Generators() {
    }

    /** A chain of {@code n} segments, IDs 0..n−1 from the root end; axes all parallel (pitch) or alternating pitch/yaw. */
    static RobotConfig snake(String name, int n, boolean alternate) {
        Builder b = new Builder();
        for (int i = 0; i < n; i++) {
            b.segment("s" + i, i, 0);
            if (i > 0) {
                b.connect("s" + (i - 1), 1, "s" + i, 0, alternate ? (i % 2 == 1 ? 1 : 3) : 0);
            }
        }
        // Roll 90°: joint axes horizontal across the snake (pitch); positive angles lift the next module.
        return b.build(name, new RootPose("s0", 0, 0, 90, 0, 0));
    }

    /** A closed chain of {@code n} parallel segments standing upright, IDs 0..n−1 round the loop. */
    static RobotConfig loop(String name, int n) {
        Builder b = new Builder();
        double angle = 360.0 / n;
        for (int i = 0; i < n; i++) {
            b.segment("s" + i, i, angle);
            if (i > 0) {
                b.connect("s" + (i - 1), 1, "s" + i, 0, 0);
            }
        }
        b.connect("s" + (n - 1), 1, "s0", 0, 0);
        return b.build(name, new RootPose("s0", 0, 0, 90, 0, 0));
    }

    /**
     * The paper's Fig. 6 cart wheel: a hub with {@code n} spokes, each a segment with a foot. IDs
     * 0..n−1 go round the hub so that a wave whose phase lags from module to module (the Fig. 7
     * gait) rolls it forwards, toward +x.
     */
    static RobotConfig wheel(String name, int n) {
        Builder b = new Builder();
        b.part(PartSpec.hub("hub", n));
        for (int i = 0; i < n; i++) {
            b.segment("s" + i, i, 0);
            b.connect("hub", (n - i) % n, "s" + i, 0, 0);
            b.passive("f" + i, PartType.FOOT);
            b.connect("s" + i, 1, "f" + i, 0, 0);
        }
        // Roll 90°: the axle (hub z) is horizontal, the wheel stands in the x-z plane; yaw 180°:
        // it faces +x, the way the Fig. 7 gait rolls it (forwards, as every standard robot goes).
        return b.build(name, new RootPose("hub", 0, 0, 90, 0, 180));
    }

    /**
     * A centipede: a spine of segments with a node at every leg pair, legs of {@code leg} segments
     * (the first swings fore and aft about a vertical axis, the others lift) ending in feet. A
     * positive lift angle raises the foot on both sides; a positive swing angle moves a right
     * foot forwards and a left foot backwards (so scripts mirror the left swing with "!"). IDs:
     * left legs from the head, each from the body outwards; then right legs likewise; then the
     * spine from the head. The defaults (7 pairs, 2-segment legs, 4 segments between pairs,
     * 2 before the first pair, 1 after the last) give the paper's 55-module, 14-leg centipede.
     */
    static RobotConfig centipede(String name, int pairs, int leg, int between, int head, int tail) {
        Builder b = new Builder();
        int legIds = pairs * leg;
        int spineId = 2 * legIds;
        String prev = null;
        int prevPlate = 0;
        for (int p = 0; p < pairs; p++) {
            int count = p == 0 ? head : between;
            for (int i = 0; i < count; i++) {
                String s = "spine" + (spineId - 2 * legIds);
                b.segment(s, spineId++, 0);
                prevPlate = b.chain(prev, prevPlate, s, 0, 1);
                prev = s;
            }
            String node = "node" + p;
            b.passive(node, PartType.NODE);
            prevPlate = b.chain(prev, prevPlate, node, 0, 1);
            prev = node;
            leg(b, node, 2, "L" + p, p * leg, leg, 1);
            leg(b, node, 3, "R" + p, legIds + p * leg, leg, 1);
        }
        for (int i = 0; i < tail; i++) {
            String s = "spine" + (spineId - 2 * legIds);
            b.segment(s, spineId++, 0);
            prevPlate = b.chain(prev, prevPlate, s, 0, 1);
            prev = s;
        }
        boolean segmentRoot = head > 0;
        // Spine segments point from head to tail (−x), joint axes vertical; nodes face +x.
        return b.build(name, new RootPose(segmentRoot ? "spine0" : "node0", 0, 0, 0, 0, segmentRoot ? 180 : 0));
    }

    private static void leg(Builder b, String node, int plate, String prefix, int firstId, int count, int liftTurns) {
        String prev = node;
        int prevPlate = plate;
        for (int j = 0; j < count; j++) {
            String s = prefix + "_" + j;
            b.segment(s, firstId + j, 0);
            b.connect(prev, prevPlate, s, 0, j == 1 ? liftTurns : 0);
            prev = s;
            prevPlate = 1;
        }
        b.passive(prefix + "_foot", PartType.FOOT);
        b.connect(prev, 1, prefix + "_foot", 0, 0);
    }

    /**
     * A 15-module humanoid: pelvis node, legs (hip roll, hip pitch, knee, ankle, foot; IDs 0–3 left,
     * 4–7 right), a waist segment (8) to the chest node, arms (shoulder roll, shoulder pitch,
     * elbow; IDs 9–11 left, 12–14 right) and a head pad. It starts standing, arms half raised.
     */
    static RobotConfig humanoid(String name) {
        Builder b = new Builder();
        b.passive("pelvis", PartType.NODE);
        b.segment("waist", 8, 0);
        b.connect("pelvis", 4, "waist", 0, 1);
        b.passive("chest", PartType.NODE);
        b.connect("waist", 1, "chest", 5, 3);
        b.passive("head", PartType.FOOT);
        b.connect("chest", 4, "head", 0, 0);
        limb(b, "pelvis", 2, "Lleg", 0, new double[] {-90, 0, 0, 0}, true);
        limb(b, "pelvis", 3, "Rleg", 4, new double[] {-90, 0, 0, 0}, true);
        limb(b, "chest", 2, "Larm", 9, new double[] {-45, 0, 0}, false);
        limb(b, "chest", 3, "Rarm", 12, new double[] {-45, 0, 0}, false);
        return b.build(name, new RootPose("pelvis", 0, 0, 0, 0, 0));
    }

    private static void limb(Builder b, String node, int plate, String prefix, int firstId, double[] angles,
                             boolean foot) {
        String prev = node;
        int prevPlate = plate;
        for (int j = 0; j < angles.length; j++) {
            String s = prefix + j;
            b.segment(s, firstId + j, angles[j]);
            b.connect(prev, prevPlate, s, 0, j <= 1 ? 1 : 0);
            prev = s;
            prevPlate = 1;
        }
        if (foot) {
            b.passive(prefix + "_foot", PartType.FOOT);
            b.connect(prev, 1, prefix + "_foot", 0, 1);
        }
    }

    /** Collects parts and connections in order. */
    private static final class Builder {
        private final List<PartSpec> parts = new ArrayList<>();
        private final List<Connection> connections = new ArrayList<>();

        void part(PartSpec p) {
            parts.add(p);
        }

        void segment(String name, int id, double angle) {
            parts.add(PartSpec.segment(name, id, angle));
        }

        void passive(String name, PartType type) {
            parts.add(PartSpec.passive(name, type));
        }

        void connect(String from, int fromPlate, String to, int toPlate, int turns) {
            connections.add(Connection.of(from, fromPlate, to, toPlate, turns));
        }

        /** Connects {@code to} after {@code prev} in a chain (nothing if first); returns {@code to}'s outgoing plate. */
        int chain(String prev, int prevPlate, String to, int inPlate, int outPlate) {
            if (prev != null) {
                connect(prev, prevPlate, to, inPlate, 0);
            }
            return outPlate;
        }

        RobotConfig build(String name, RootPose root) {
            return new RobotConfig(name, parts, connections, root);
        }
    }
}
