package org.parpe.sim.build;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.parpe.sim.config.Connection;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RootPose;

/**
 * How the parts of a configuration hang together: the connection each part hangs on, reached
 * breadth first from its robot's root along the connections in file order (the order in which
 * the simulator places them), so a connection that closes a loop attaches nothing. Chain order
 * is depth first over that tree, each part's children in file order: a tail is numbered before
 * the arms of the node it hangs on.
 */
final class DraftTree {
    private final RobotConfig config;
    private final Map<String, Integer> index = new HashMap<>();
    private final Connection[] parent;
    private final int[] parentPart;
    private final int[] robot;
    private final List<List<Integer>> children = new ArrayList<>();
    private final List<Integer> chain = new ArrayList<>();
    private final List<List<Connection>> byPart;

    DraftTree(RobotConfig config) {
        this.config = config;
        int n = config.parts().size();
        for (int i = 0; i < n; i++) {
            index.putIfAbsent(config.parts().get(i).name(), i);
            children.add(new ArrayList<>());
        }
        parent = new Connection[n];
        parentPart = new int[n];
        robot = new int[n];
        java.util.Arrays.fill(parentPart, -1);
        java.util.Arrays.fill(robot, -1);
        byPart = byPart();
        for (int k = 0; k < config.roots().size(); k++) {
            Integer root = index.get(config.roots().get(k).part());
            if (root != null && robot[root] < 0) {
                reach(root, k);
            }
        }
        for (int k = 0; k < config.roots().size(); k++) {
            Integer root = index.get(config.roots().get(k).part());
            if (root != null && parentPart[root] < 0 && robot[root] == k) {
                order(root);
            }
        }
    }

    private List<List<Connection>> byPart() {
        List<List<Connection>> out = new ArrayList<>();
        config.parts().forEach(p -> out.add(new ArrayList<>()));
        for (Connection c : config.connections()) {
            Integer a = index.get(c.from());
            Integer b = index.get(c.to());
            if (a != null && b != null) {
                out.get(a).add(c);
                if (!b.equals(a)) {
                    out.get(b).add(c);
                }
            }
        }
        return out;
    }

    /** Breadth first from {@code root}: each part reached gets its parent connection. */
    private void reach(int root, int k) {
        Deque<Integer> queue = new ArrayDeque<>();
        robot[root] = k;
        queue.add(root);
        while (!queue.isEmpty()) {
            int part = queue.poll();
            for (Connection c : byPart.get(part)) {
                int a = index.get(c.from());
                int other = a == part ? index.get(c.to()) : a;
                if (robot[other] < 0) {
                    robot[other] = k;
                    parent[other] = c;
                    parentPart[other] = part;
                    children.get(part).add(other);
                    queue.add(other);
                }
            }
        }
    }

    /** Depth first from {@code root}, children in the order they were reached. */
    private void order(int root) {
        Deque<Integer> stack = new ArrayDeque<>();
        stack.push(root);
        while (!stack.isEmpty()) {
            int part = stack.pop();
            chain.add(part);
            List<Integer> kids = children.get(part);
            for (int i = kids.size() - 1; i >= 0; i--) {
                stack.push(kids.get(i));
            }
        }
    }

    /** The index of the part called {@code name}, or −1. */
    int index(String name) {
        return index.getOrDefault(name, -1);
    }

    /** The connection part {@code i} hangs on, or null for a root or a part no root reaches. */
    Connection parent(int i) {
        return parent[i];
    }

    /** The part that part {@code i} hangs on, or −1. */
    int parentPart(int i) {
        return parentPart[i];
    }

    /** Which root's robot part {@code i} belongs to (an index into the roots), or −1 when none reaches it. */
    int robot(int i) {
        return robot[i];
    }

    /** The root pose of the robot part {@code i} belongs to, or null. */
    RootPose rootOf(int i) {
        return robot[i] < 0 ? null : config.roots().get(robot[i]);
    }

    /** Part indices in chain order: each robot depth first from its root; parts no root reaches are left out. */
    List<Integer> chain() {
        return chain;
    }

    /**
     * Part {@code i} and every part that hangs on it away from its robot's root: those its robot
     * no longer reaches without {@code i} (in a loop, parts still held by the other way round stay).
     */
    List<Integer> hangingOn(int i) {
        List<Integer> out = new ArrayList<>(List.of(i));
        if (robot[i] < 0) {
            return out;
        }
        int root = index.get(config.roots().get(robot[i]).part());
        boolean[] kept = new boolean[robot.length];
        if (root != i) {
            Deque<Integer> queue = new ArrayDeque<>(List.of(root));
            kept[root] = true;
            while (!queue.isEmpty()) {
                int p = queue.poll();
                for (Connection c : byPart.get(p)) {
                    int other = index.get(c.from()) == p ? index.get(c.to()) : index.get(c.from());
                    if (other != i && !kept[other]) {
                        kept[other] = true;
                        queue.add(other);
                    }
                }
            }
        }
        for (int p = 0; p < robot.length; p++) {
            if (p != i && robot[p] == robot[i] && !kept[p]) {
                out.add(p);
            }
        }
        return out;
    }
}
