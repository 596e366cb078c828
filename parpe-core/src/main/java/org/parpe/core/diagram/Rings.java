package org.parpe.core.diagram;

import static org.parpe.core.diagram.Layouts.GREY;
import static org.parpe.core.diagram.Layouts.INK;
import static org.parpe.core.diagram.Layouts.LATCH;
import static org.parpe.core.diagram.Layouts.PALETTE;
import static org.parpe.core.diagram.Layouts.RED;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.parpe.core.lang.Numbers;
import org.parpe.core.text.DiagramMsg;

/**
 * The ring and the phase wheel laid out ({@link Layouts#ring}, {@link Layouts#wheel}): wider
 * than tall, as the IDE's Diagram tab is, and with labels that never overlap ({@link Labels}).
 * The ring's states are named in two columns beside it, a leader line to each arc; the wheel
 * numbers its ticks by position in the group, as its text does.
 */
final class Rings {
    static final int WIDTH = 760;
    /** The smallest text of both drawings at text scale 1. */
    static final double SMALLEST = 12;
    private static final double CX = 380;
    private static final double CY = 290;
    /** The ring's band. */
    private static final double R0 = 100;
    private static final double R1 = 150;
    /** The wheel's circle. */
    private static final double R = 160;
    /** Where the columns of the ring's labels start, from the centre: past the live dots and breakpoints. */
    private static final double COLUMN = R1 + 40;
    private static final double GAP = 8;
    private static final int PREVIEW = 0x009e73;

    /** How many times larger than at scale 1 the text is. */
    private final double t;
    /** Where the labels start: under the title and the IDE's live line (at 50 × the text scale). */
    private final double top;
    /** The wheel's centre: under its three lines of text. */
    private final double wheelY;
    /** How wide a column of the ring's labels is: wider for larger text, so that it says more than "…". */
    private final double columnRoom;
    /** The ring's centre: the columns of labels beside it. */
    private final double ringX;

    Rings(double textScale) {
        t = Math.max(1, textScale);
        top = 64 * t;
        wheelY = 68 * t + 62 + R;
        columnRoom = 180 + 110 * (t - 1);
        ringX = COLUMN + 10 + columnRoom;
    }

    Scene ring(Ring r) {
        List<Labels.Block> left = new ArrayList<>();
        List<Labels.Block> right = new ArrayList<>();
        boolean compact = false;
        for (int pass = 0; pass < 2; pass++) {
            left.clear();
            right.clear();
            for (Ring.Arc a : r.arcs()) {
                double mid = (a.from() + a.to()) / 2;
                double[] at = Scene.onCircle(ringX, CY, R1 + 30, mid);
                (mid < 0.5 ? right : left).add(new Labels.Block(lines(a, compact), at[1], a));
            }
            double room = CY + R1 + 20 - top;
            compact = height(left) > room || height(right) > room;
            if (!compact || pass == 1) {
                break;
            }
        }
        double bottom = Math.max(Labels.stack(left, top, CY + R1 + 20, GAP * t), Labels.stack(right, top, CY + R1 + 20, GAP * t));
        double caption = Math.max(CY + R1 + 30 + 14 * t, bottom + 24 * t);
        Scene sc = new Scene(Layouts.width((int) Math.ceil(2 * ringX), r.islands()), (int) (caption + 50 + r.islands().size() * 18));
        String title = (r.table() ? DiagramMsg.RING_GAIT_TABLE : DiagramMsg.RING_AUTOMATON).text(r.automaton());
        sc.add(new Scene.Text(20, 28 * t, title, 15 * t, -1, INK, true));
        for (Ring.Arc a : r.arcs()) {
            sc.add(arc(a));
            double[] e0 = Scene.onCircle(ringX, CY, R1 + 6, a.to());
            double[] e1 = Scene.onCircle(ringX, CY, R0 - 6, a.to());
            sc.add(new Scene.Line(e0[0], e0[1], e1[0], e1[1], INK, 2, 0));
        }
        for (Labels.Block b : right) {
            leader(sc, (Ring.Arc) b.key, b, ringX + COLUMN - 4);
            b.draw(sc, ringX + COLUMN, -1);
        }
        for (Labels.Block b : left) {
            leader(sc, (Ring.Arc) b.key, b, ringX - COLUMN + 4);
            b.draw(sc, ringX - COLUMN, 1);
        }
        sc.add(new Scene.Text(ringX, CY - 6 * t, DiagramMsg.ONE_CYCLE.text(), 12 * t, 0, GREY, false));
        sc.add(new Scene.Text(ringX, CY + 14 * t, cycle(r), 15 * t, 0, INK, true));
        sc.add(new Scene.Text(ringX, caption, Labels.fit(DiagramMsg.RING_CAPTION.text(),
                12 * t, false, 2 * ringX - 40), 12 * t, 0, GREY, false));
        Layouts.islands(sc, r.islands(), caption + 30);
        return sc;
    }

    /** The sector of state {@code a} as {@link #ring} draws it. */
    Scene.Sector arc(Ring.Arc a) {
        return new Scene.Sector(ringX, CY, R0, R1, a.from(), a.to(), PALETTE[a.index() % PALETTE.length], 0xffffff, a.pos());
    }

    /** The wheel's circle as {@link #wheel} draws it: its centre and outer edge's radius. */
    double[] wheelCircle() {
        return new double[] {CX, wheelY, R + 1};
    }

    private double height(List<Labels.Block> blocks) {
        return blocks.stream().mapToDouble(b -> b.height() + GAP * t).sum();
    }

    /** A thin line from the middle of {@code a}'s arc to its label. */
    private void leader(Scene sc, Ring.Arc a, Labels.Block b, double x) {
        double[] p = Scene.onCircle(ringX, CY, R1 + 2, (a.from() + a.to()) / 2);
        double y = b.top + b.lines.get(0).size() * Labels.LINE / 2 + 2;
        sc.add(new Scene.Line(p[0], p[1], x, y, PALETTE[a.index() % PALETTE.length], 1.5, 0));
    }

    /** The label of a state: its name, how long it lasts, its angles and its exit, in words. */
    private List<Labels.Line> lines(Ring.Arc a, boolean compact) {
        double room = columnRoom;
        String lasts = DiagramMsg.LASTS.text(Double.isNaN(a.seconds()) ? a.duration() : Numbers.format(a.seconds()));
        List<Labels.Line> out = new ArrayList<>();
        if (compact) {
            String mark = a.plates().isEmpty() ? "" : " (latch)";
            out.add(new Labels.Line(Labels.fit(a.state() + mark + ", " + lasts, 12 * t, true, room), 12 * t, true, INK));
            return out;
        }
        out.add(new Labels.Line(Labels.fit(a.state(), 13 * t, true, room), 13 * t, true, INK));
        out.add(new Labels.Line(Labels.fit(lasts, 12 * t, false, room), 12 * t, false, INK));
        if (!a.angles().isEmpty()) {
            out.add(new Labels.Line(Labels.fit("angles " + angles(a), 12 * t, false, room), 12 * t, false, 0x444444));
        }
        if (!a.plates().isEmpty()) {
            // the latch mark of PARSL.md §14: what entering the state does to the plates
            out.add(new Labels.Line(Labels.fit(a.plates(), 12 * t, true, room), 12 * t, true, LATCH));
        }
        if (a.exit() != null) {
            out.add(new Labels.Line(Labels.fit(DiagramMsg.EXIT_WHEN.text(a.exit()), 12 * t, true, room), 12 * t, true, RED));
        }
        if (!a.dock().isEmpty()) {
            out.add(new Labels.Line(Labels.fit(a.dock(), 12 * t, false, room), 12 * t, false, LATCH));
        }
        return out;
    }

    /** The angles as written, in degrees, and their values when the written ones are names. */
    private static String angles(Ring.Arc a) {
        String written = String.join(", ", a.angles());
        boolean plain = a.angles().stream().allMatch(s -> Numbers.parsePlain(s) != null);
        if (plain) {
            return written + "°";
        }
        if (a.pose().isEmpty()) {
            return written;
        }
        List<Double> distinct = a.pose().stream().distinct().toList();
        return written + (distinct.size() == 1 ? " = " + Numbers.format(distinct.get(0)) + "°" : "");
    }

    /** How long one cycle of the ring takes, in words. */
    private static String cycle(Ring r) {
        double total = 0;
        for (Ring.Arc a : r.arcs()) {
            if (Double.isNaN(a.seconds())) {
                return DiagramMsg.CYCLE_VARIES.text();
            }
            total += Math.max(0, a.seconds());
        }
        return DiagramMsg.SECONDS.text(Numbers.format(Math.round(total * 1000) / 1000.0));
    }

    Scene wheel(PhaseWheel w) {
        Scene sc = new Scene(Layouts.width(WIDTH, w.islands()), (int) (wheelY + R + 40 + 30 * t + w.islands().size() * 18));
        List<Scene.Text> head = new ArrayList<>();
        head.add(new Scene.Text(20, 28 * t, DiagramMsg.ON.text(w.automaton(), w.group()), 15 * t, -1, INK, true));
        head.add(new Scene.Text(20, 50 * t, Labels.fit(DiagramMsg.WHEEL_LAG.text(brief(w.offset()), brief(w.phase())),
                12 * t, false, WIDTH - 40), 12 * t, -1, GREY, false));
        head.add(new Scene.Text(20, 68 * t, Labels.fit(positions(w), 12 * t, false, WIDTH - 40), 12 * t, -1, GREY, false));
        List<Labels.Box> taken = Labels.place(sc, head, List.of());
        sc.add(new Scene.Sector(CX, wheelY, R - 1, R + 1, 0, 1, INK, Scene.NONE, null));
        List<Scene.Text> labels = new ArrayList<>();
        double[] zero = Scene.onCircle(CX, wheelY, R - 40, w.ticks().isEmpty() ? 0 : w.ticks().get(0).delay());
        sc.add(new Scene.Line(CX, wheelY, zero[0], zero[1], GREY, 1, 4));
        List<Scene.Text> handLabel = new ArrayList<>();
        hand(sc, w, RED, handLabel);
        // positions 0 and 1 first, then the hand's label: the hand is drawn from 0 to 1
        tickLabels(w, labels, handLabel);
        for (int k = 0; k < 4; k++) {
            double[] p = Scene.onCircle(CX, wheelY, R - 14 - 8 * t, k / 4.0);
            labels.add(new Scene.Text(p[0], p[1] + 4 * t, Numbers.format(k / 4.0), 12 * t, 0, GREY, false));
        }
        Labels.place(sc, labels, taken);
        Layouts.islands(sc, w.islands(), wheelY + R + 20 + 30 * t);
        return sc;
    }

    /**
     * The ticks and the hand of {@code w} drawn over its wheel as a drag would leave them: for
     * the IDE, while the hand is dragged to another phase ({@link PhaseWheel#withPhase}).
     */
    List<Scene.Shape> preview(PhaseWheel w) {
        Scene sc = new Scene(WIDTH, 1);
        List<Scene.Text> labels = new ArrayList<>();
        hand(sc, w, PREVIEW, labels);
        labels.forEach(sc::add);
        return sc.shapes();
    }

    /** The ticks of {@code w} and its hand (to position 1's tick) in {@code colour}; the hand's label goes to {@code labels}. */
    private void hand(Scene sc, PhaseWheel w, int colour, List<Scene.Text> labels) {
        for (PhaseWheel.Tick tick : w.ticks()) {
            double[] a = Scene.onCircle(CX, wheelY, R - 10, tick.delay());
            double[] b = Scene.onCircle(CX, wheelY, R + 14, tick.delay());
            int c = colour != RED ? colour : tick.position() == 0 ? RED : PALETTE[4];
            sc.add(new Scene.Line(a[0], a[1], b[0], b[1], c, tick.position() == 0 ? 3 : 2, 0));
        }
        if (w.ticks().size() > 1) {
            double f = w.ticks().get(1).delay();
            double[] h = Scene.onCircle(CX, wheelY, R - 40, f);
            sc.add(new Scene.Line(CX, wheelY, h[0], h[1], colour, 2, 0));
            double[] l = Scene.onCircle(CX, wheelY, (R - 40) / 2, f);
            // beside the hand's middle, clockwise of it, running away from the line rather than across it
            double nx = Math.cos(2 * Math.PI * f);
            double ny = Math.sin(2 * Math.PI * f);
            double size = 12 * t;
            labels.add(new Scene.Text(l[0] + 8 * nx, l[1] + 8 * ny + (0.35 + 0.45 * ny) * size, "phase " + brief(w.phase()),
                    size, nx >= -1e-9 ? -1 : 1, colour, true));
        }
    }

    /** A label per delay outside the wheel, the positions at it; position 0's and 1's first. */
    private void tickLabels(PhaseWheel w, List<Scene.Text> labels, List<Scene.Text> then) {
        Map<Long, List<PhaseWheel.Tick>> byDelay = new LinkedHashMap<>();
        for (PhaseWheel.Tick tick : w.ticks()) {
            byDelay.computeIfAbsent(Math.round(tick.delay() * 1e6), k -> new ArrayList<>()).add(tick);
        }
        List<Scene.Text> first = new ArrayList<>();
        List<Scene.Text> rest = new ArrayList<>();
        for (List<PhaseWheel.Tick> same : byDelay.values()) {
            PhaseWheel.Tick first0 = same.get(0);
            String at = same.size() <= 3 ? String.join(", ", same.stream().map(u -> Integer.toString(u.position())).toList())
                    : same.get(0).position() + ", " + same.get(1).position() + " … " + same.get(same.size() - 1).position();
            double[] l = Scene.onCircle(CX, wheelY, R + 14 + 18 * t, first0.delay());
            int anchor = l[0] < CX - 5 ? 1 : l[0] > CX + 5 ? -1 : 0;
            Scene.Text text = new Scene.Text(l[0], l[1] + 5 * t, at, 12 * t, anchor, first0.position() == 0 ? RED : PALETTE[4],
                    first0.position() == 0);
            (first0.position() <= 1 ? first : rest).add(text);
        }
        labels.addAll(first);
        labels.addAll(then);
        labels.addAll(rest);
    }

    /** {@code v} to 0.001 of a cycle. */
    private static String brief(double v) {
        return Numbers.format(Math.round(v * 1000) / 1000.0);
    }

    /** "position 0 is module 14, 1 is 16, …": what the positions on the wheel are. */
    private static String positions(PhaseWheel w) {
        StringBuilder s = new StringBuilder();
        for (PhaseWheel.Tick tick : w.ticks()) {
            s.append(tick.position() == 0 ? DiagramMsg.WHEEL_POSITION_0.text(tick.module())
                    : DiagramMsg.WHEEL_POSITION.text(tick.position(), tick.module()));
            if (s.length() > 120) {
                s.append(", …");
                break;
            }
        }
        return s.toString();
    }
}
