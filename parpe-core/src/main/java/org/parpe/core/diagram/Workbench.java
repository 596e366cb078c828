package org.parpe.core.diagram;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.Instance;
import org.parpe.core.model.MainEntry;
import org.parpe.core.model.Program;
import org.parpe.core.text.DiagramMsg;

/**
 * The workbench under a view, as in Scratch or Choregraphe: the script's parts that the view's
 * drawing does not use, as free nodes the user puts anywhere on it (the program view: the
 * behaviors {@code <main>} does not run; the lanes: the automata and gait tables no behavior
 * plays). Their places are layout only ({@link NodePlaces}); a node without one gets the first
 * free slot of a grid that overlaps no other node.
 */
public final class Workbench {
    /** Room between the drawing above and the workbench, and between slots. */
    static final double GAP = 24;
    /** The workbench's title line. */
    static final double TITLE = 30;
    /** The width of a slot of the default grid. */
    static final double SLOT_W = 220;
    /** At least this wide and this tall. */
    static final double MIN_W = 720;
    static final double MIN_H = 140;

    private Workbench() {
    }

    /**
     * A free node.
     *
     * @param name  the element's name (what its place is kept under)
     * @param lines its box's text, the name first
     * @param pos   its element
     */
    public record Node(String name, List<String> lines, SourcePos pos) {
        public Node {
            lines = List.copyOf(lines);
        }
    }

    /** A free node where it is drawn: {@code x, y} in the workbench, {@code sceneX, sceneY} in the scene. */
    public record Placed(Node node, double x, double y, double w, double h, double sceneX, double sceneY) {
        /** Whether scene point {@code px, py} is on the node. */
        public boolean contains(double px, double py) {
            return px >= sceneX && px <= sceneX + w && py >= sceneY && py <= sceneY + h;
        }
    }

    /**
     * A drawing with its workbench under it.
     *
     * @param scene  the drawing above and the workbench
     * @param top    where the workbench starts, in scene units (its origin is {@code 0, top})
     * @param placed the free nodes as drawn
     */
    public record Bench(Scene scene, double top, List<Placed> placed) {
        public Bench {
            placed = List.copyOf(placed);
        }

        /** The free node at scene point {@code x, y}, topmost first, or {@code null}. */
        public Placed at(double x, double y) {
            for (int i = placed.size() - 1; i >= 0; i--) {
                if (placed.get(i).contains(x, y)) {
                    return placed.get(i);
                }
            }
            return null;
        }

        /**
         * The workbench point of scene point {@code x, y} for a node {@code w × h}: kept within
         * the drawing's width, under the title, and at most at the bottom of the workbench (so a
         * drag grows it by one node at a time, not the whole drawing smaller at once).
         */
        public double[] clamp(double x, double y, double w, double h) {
            return new double[] {Math.max(0, Math.min(scene.width() - w, x)),
                    Math.max(TITLE, Math.min(scene.height() - top, y - top))};
        }
    }

    /** The behaviors {@code <main>} does not run, in document order. */
    public static List<Node> freeBehaviors(Program p) {
        Set<String> run = new HashSet<>();
        if (p.main() != null) {
            p.main().entries().stream().map(MainEntry::behavior).forEach(run::add);
        }
        List<Node> out = new ArrayList<>();
        for (Behavior b : p.behaviors()) {
            if (!run.contains(b.name())) {
                List<String> lines = new ArrayList<>(List.of(b.name(), DiagramMsg.NOT_RUN_BY_MAIN.text()));
                b.instances().stream().limit(3).forEach(in -> lines.add(DiagramMsg.ON.text(in.name(), in.group())));
                if (b.instances().size() > 3) {
                    lines.add(DiagramMsg.MORE.text(b.instances().size() - 3));
                }
                out.add(new Node(b.name(), lines, b.pos()));
            }
        }
        return out;
    }

    /** The automata and gait tables no behavior plays, in document order. */
    public static List<Node> freeAutomata(Program p) {
        Set<String> played = new HashSet<>();
        for (Behavior b : p.behaviors()) {
            b.instances().stream().map(Instance::name).forEach(played::add);
        }
        List<Node> out = new ArrayList<>();
        for (Automaton a : p.automata()) {
            if (!played.contains(a.name())) {
                String states = String.join(", ", a.states().stream().map(s -> s.name()).toList());
                out.add(new Node(a.name(), List.of(a.name(), (a.table() ? DiagramMsg.CARD_GAIT_TABLE.text(a.states().size())
                        : DiagramMsg.CARD_AUTOMATON.text(states.length() > 28 ? states.substring(0, 27) + "…" : states))), a.pos()));
            }
        }
        return out;
    }

    /**
     * {@code above} with a workbench under it titled {@code title}, holding {@code nodes}: each
     * at its place in {@code places} (by name) when it has one, else in the first free slot.
     * Without nodes, {@code above} itself.
     */
    public static Bench of(Scene above, String title, List<Node> nodes, Map<String, double[]> places) {
        if (nodes.isEmpty()) {
            return new Bench(above, above.height(), List.of());
        }
        double width = Math.max(MIN_W, above.width());
        List<double[]> sizes = new ArrayList<>();
        List<double[]> taken = new ArrayList<>();
        for (Node n : nodes) {
            double w = 24;
            for (String l : n.lines()) {
                w = Math.max(w, l.length() * 13 * 0.6 + 24);
            }
            double[] size = {Math.min(w, width - 2 * GAP), 22 + n.lines().size() * 18};
            sizes.add(size);
            double[] p = places.get(n.name());
            if (p != null) {
                taken.add(new double[] {Math.max(0, Math.min(width - size[0], p[0])), Math.max(TITLE, p[1]), size[0], size[1]});
            } else {
                taken.add(null);
            }
        }
        List<double[]> fixed = new ArrayList<>(taken.stream().filter(t -> t != null).toList());
        for (int i = 0; i < nodes.size(); i++) {
            if (taken.get(i) == null) {
                double[] slot = slot(width, sizes.get(i), fixed);
                taken.set(i, slot);
                fixed.add(slot);
            }
        }
        double bottom = MIN_H;
        for (double[] t : taken) {
            bottom = Math.max(bottom, t[1] + t[3] + GAP);
        }
        double top = above.height() + GAP;
        Scene sc = new Scene((int) Math.ceil(width), (int) Math.ceil(top + bottom));
        above.shapes().forEach(sc::add);
        sc.add(new Scene.Line(10, top, width - 10, top, Layouts.GREY, 1, 6));
        sc.add(new Scene.Text(20, top + 20, title, 12, -1, Layouts.GREY, false));
        List<Placed> placed = new ArrayList<>();
        for (int i = 0; i < nodes.size(); i++) {
            double[] t = taken.get(i);
            Node n = nodes.get(i);
            double x = t[0];
            double y = top + t[1];
            sc.add(new Scene.Rect(x, y, t[2], t[3], Layouts.LIGHT, Layouts.GREY, 1.5, n.pos()));
            for (int k = 0; k < n.lines().size(); k++) {
                sc.add(new Scene.Text(x + 12, y + 24 + k * 18, n.lines().get(k), 13, -1, k == 0 ? Layouts.INK : 0x555555,
                        k == 0));
            }
            placed.add(new Placed(n, t[0], t[1], t[2], t[3], x, y));
        }
        return new Bench(sc, top, placed);
    }

    /** The first slot of the grid (left to right, then down) where {@code size} overlaps none of {@code taken}. */
    private static double[] slot(double width, double[] size, List<double[]> taken) {
        int perRow = Math.max(1, (int) ((width - GAP) / (SLOT_W + GAP)));
        for (int k = 0; ; k++) {
            double x = GAP + (k % perRow) * (SLOT_W + GAP);
            double y = TITLE + (k / perRow) * (size[1] + GAP);
            double w = Math.min(size[0], width - x);
            double[] r = {Math.min(x, width - size[0]), y, size[0], size[1]};
            boolean free = w > 0;
            for (double[] t : taken) {
                free &= r[0] + r[2] + 4 <= t[0] || t[0] + t[2] + 4 <= r[0] || r[1] + r[3] + 4 <= t[1] || t[1] + t[3] + 4 <= r[1];
            }
            if (free) {
                return r;
            }
        }
    }
}
