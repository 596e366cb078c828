package org.parpe.core.diagram;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.parpe.core.lang.Numbers;
import org.parpe.core.text.DiagramMsg;
import org.parpe.core.text.Msg;

/**
 * Lays the diagrams out as {@link Scene}s: fixed sizes and a fixed palette, so that the same
 * program always gives the same drawing (snapshot tests compare them byte for byte). Text
 * islands are listed under each drawing with the line they open. The words a drawing shows are
 * {@link Msg}'s in the chosen language; PARSL's names ({@code <main>}, {@code cycles},
 * {@code phase}, ...) stay as the file writes them.
 */
public final class Layouts {
    /** Colours of states, in order (a colour-blind-safe qualitative palette, Okabe–Ito). */
    static final int[] PALETTE = {0xe69f00, 0x56b4e9, 0x009e73, 0xf0e442, 0x0072b2, 0xd55e00, 0xcc79a7, 0x999999};
    static final int INK = 0x222222;
    static final int GREY = 0x888888;
    static final int LIGHT = 0xeeeeee;
    static final int RED = 0xcc0000;
    /** The colour of docking (PARSL.md §14): a state's plate actions, the dock readings an exit waits on. */
    static final int LATCH = 0x1f5fbf;
    private static final double CHAR = 0.6;
    /** The first of the wide characters (CJK radicals onwards: kana, ideographs, full-width forms). */
    private static final char WIDE = '\u2e80';

    private Layouts() {
    }

    /**
     * The width a text takes at {@code size}: {@link #CHAR} of the size per character, a whole
     * size for the wide characters of Chinese, Japanese and Korean (the labels are translated).
     */
    private static double width(String s, double size) {
        int wide = (int) s.chars().filter(c -> c >= WIDE).count();
        return (s.length() - wide) * size * CHAR + wide * size;
    }

    /** The {@code <main>} lane: one box per entry, left to right, with the repeat arrow under them. */
    public static Scene program(ProgramLane lane) {
        List<List<String>> boxes = new ArrayList<>();
        List<Integer> dockLine = new ArrayList<>();
        double total = 40;
        List<Double> widths = new ArrayList<>();
        for (ProgramLane.Step s : lane.steps()) {
            List<String> lines = new ArrayList<>();
            lines.add(s.behavior());
            lines.add(s.time() == null ? DiagramMsg.UNTIL_AUTOMATA_END.text() : DiagramMsg.TIME.text(s.time()));
            if (s.exit() != null) {
                lines.add(DiagramMsg.EXIT_WHEN.text(s.exit()));
            }
            dockLine.add(s.dock().isEmpty() ? -1 : lines.size());
            if (!s.dock().isEmpty()) {
                lines.add(s.dock());
            }
            s.macros().forEach(lines::add);
            boxes.add(lines);
            double w = 24;
            for (String l : lines) {
                w = Math.max(w, width(l, 13) + 24);
            }
            widths.add(w);
            total += w + 40;
        }
        int maxLines = boxes.stream().mapToInt(List::size).max().orElse(1);
        double boxH = 22 + maxLines * 18;
        Scene sc = new Scene((int) Math.max(360, total), (int) (boxH + 110));
        sc.add(new Scene.Text(20, 28, "<main>  cycles " + lane.cycles(), 15, -1, INK, true));
        double x = 40;
        double y = 50;
        for (int i = 0; i < boxes.size(); i++) {
            double w = widths.get(i);
            if (i > 0) {
                arrow(sc, x - 40, y + boxH / 2, x, y + boxH / 2);
            }
            sc.add(new Scene.Rect(x, y, w, boxH, PALETTE[i % PALETTE.length], INK, 1.5, lane.steps().get(i).pos()));
            sc.add(new Scene.Rect(x + 3, y + 3, w - 6, boxH - 6, 0xffffff, Scene.NONE, 0, null));
            List<String> lines = boxes.get(i);
            for (int k = 0; k < lines.size(); k++) {
                boolean dock = k == dockLine.get(i);
                sc.add(new Scene.Text(x + 12, y + 24 + k * 18, lines.get(k), 13, -1, dock ? LATCH : INK, k == 0));
            }
            x += w + 40;
        }
        if (!boxes.isEmpty()) {
            double back = y + boxH + 25;
            sc.add(new Scene.Line(x - 40, y + boxH / 2, x - 20, y + boxH / 2, INK, 1.5, 0));
            sc.add(new Scene.Line(x - 20, y + boxH / 2, x - 20, back, INK, 1.5, 0));
            sc.add(new Scene.Line(x - 20, back, 20, back, INK, 1.5, 0));
            sc.add(new Scene.Line(20, back, 20, y + boxH / 2, INK, 1.5, 0));
            arrow(sc, 20, y + boxH / 2, 40, y + boxH / 2);
            sc.add(new Scene.Text((x - 20 + 20) / 2, back + 18, lane.cycles().equals("1") ? DiagramMsg.RUNS_ONCE.text()
                : lane.cycles().equals("forever") ? DiagramMsg.RUNS_FOREVER.text() : DiagramMsg.RUNS_TIMES.text(lane.cycles()), 12, 0, GREY, false));
        }
        return sc;
    }

    private static void arrow(Scene sc, double x1, double y1, double x2, double y2) {
        sc.add(new Scene.Line(x1, y1, x2, y2, INK, 1.5, 0));
        double a = Math.atan2(y2 - y1, x2 - x1);
        for (double d : new double[] {-0.45, 0.45}) {
            sc.add(new Scene.Line(x2, y2, x2 - 9 * Math.cos(a + d), y2 - 9 * Math.sin(a + d), INK, 1.5, 0));
        }
    }

    /** The swimlanes: a lane per group, each instance a bar over the behavior's time. */
    public static Scene lanes(Swimlanes s) {
        double labelW = 200;
        double plotW = 700;
        double horizon = 1;
        for (Swimlanes.Lane l : s.lanes()) {
            for (Swimlanes.Bar b : l.bars()) {
                double start = num(b.start(), 0);
                double period = num(b.period(), 1);
                double cycles = num(b.cycles(), Double.POSITIVE_INFINITY);
                horizon = Math.max(horizon, Double.isInfinite(cycles) ? start + 2 * period : start + cycles * period);
            }
        }
        int rows = s.lanes().stream().mapToInt(l -> l.bars().size()).sum();
        double barH = 34;
        double top = 60;
        double h = top + rows * (barH + 8) + s.lanes().size() * 12 + 40 + s.islands().size() * 18;
        Scene sc = new Scene(width((int) (labelW + plotW + 40), s.islands()), (int) h);
        sc.add(new Scene.Text(20, 28, s.entry() >= 0 ? DiagramMsg.BEHAVIOR_ENTRY.text(s.behavior(), Msg.ordinal(s.entry()))
                : DiagramMsg.BEHAVIOR.text(s.behavior()), 15, -1, INK, true));
        double scale = plotW / horizon;
        double y = top;
        for (double t = 0; t <= horizon + 1e-9; t += step(horizon)) {
            double x = labelW + t * scale;
            sc.add(new Scene.Line(x, top - 8, x, h - 30 - s.islands().size() * 18, LIGHT, 1, 0));
            sc.add(new Scene.Text(x, top - 12, Numbers.format(Math.round(t * 100) / 100.0) + " s", 10, 0, GREY, false));
        }
        for (Swimlanes.Lane l : s.lanes()) {
            double laneH = l.bars().size() * (barH + 8) + 4;
            sc.add(new Scene.Rect(10, y - 2, labelW + plotW + 20, laneH, Scene.NONE, 0xcccccc, 1, null));
            sc.add(new Scene.Text(20, y + 18, l.group(), 13, -1, INK, true));
            sc.add(new Scene.Text(20, y + 34, l.modules().isEmpty() ? DiagramMsg.MACRO_GROUP.text() : modules(l.modules()), 10, -1, GREY,
                    false));
            for (Swimlanes.Bar b : l.bars()) {
                bar(sc, b, labelW, y + 2, barH, scale, plotW);
                y += barH + 8;
            }
            y += 12;
        }
        islands(sc, s.islands(), h - s.islands().size() * 18 - 8);
        return sc;
    }

    private static void bar(Scene sc, Swimlanes.Bar b, double x0, double y, double barH, double scale, double plotW) {
        double start = num(b.start(), 0);
        double period = num(b.period(), 1);
        double cycles = num(b.cycles(), Double.POSITIVE_INFINITY);
        double x = x0 + start * scale;
        double w = Double.isInfinite(cycles) ? x0 + plotW - x : Math.max(4, cycles * period * scale);
        boolean red = !b.overlaps().isEmpty();
        int fill = red ? 0xf6c6c6 : b.conditions().isEmpty() ? 0xdce9f5 : 0xf3ead2;
        sc.add(new Scene.Rect(x, y, w, barH, fill, red ? RED : b.mirrored() ? 0x7a3db8 : 0x4a6f94, red ? 2.5 : 1.2,
                b.pos()));
        if (period > 0 && !Double.isInfinite(period) && b.period() != null) {
            for (double t = start + period; t < start + (Double.isInfinite(cycles) ? 1e9 : cycles * period) - 1e-9
                    && x0 + t * scale < x0 + plotW; t += period) {
                sc.add(new Scene.Line(x0 + t * scale, y + barH - 6, x0 + t * scale, y + barH, GREY, 1, 0));
            }
        }
        StringBuilder label = new StringBuilder((b.mirrored() ? "!" : "") + b.automaton());
        attr(label, "phase", b.phase());
        attr(label, "offset", b.offset());
        attr(label, "period", b.period());
        attr(label, "start", b.start());
        attr(label, "cycles", b.cycles());
        sc.add(new Scene.Text(x + 6, y + 14, label.toString(), 11, -1, INK, false));
        StringBuilder note = new StringBuilder();
        if (b.mirrored()) {
            note.append(DiagramMsg.MIRRORED.text()).append("  ");
        }
        if (!b.conditions().isEmpty()) {
            String all = b.conditions().get(0);
            for (String c : b.conditions().subList(1, b.conditions().size())) {
                all = DiagramMsg.AND.text(all, c);
            }
            note.append(DiagramMsg.IF.text(all)).append("  ");
        }
        if (red) {
            note.append(DiagramMsg.DRIVES_TWICE.text(b.shared(), b.overlaps().get(0)));
        }
        if (note.length() > 0) {
            sc.add(new Scene.Text(x + 6, y + 28, note.toString().trim(), 10, -1, red ? RED : 0x555555, red));
        }
        if (Double.isInfinite(cycles)) {
            sc.add(new Scene.Text(x0 + plotW - 4, y + 28, "…", 12, 1, GREY, false));
        }
    }

    private static void attr(StringBuilder s, String name, String value) {
        if (value != null) {
            s.append("  ").append(name).append(' ').append(value);
        }
    }

    private static String modules(List<Integer> ids) {
        String list = ids.size() <= 5 ? ids.toString() : ids.subList(0, 4) + "…";
        return (ids.size() == 1 ? DiagramMsg.ONE_MODULE : DiagramMsg.MODULES).text(ids.size(),
                list.replace("[", "").replace("]", ""));
    }

    private static double step(double horizon) {
        double raw = horizon / 8;
        double p = Math.pow(10, Math.floor(Math.log10(raw)));
        return raw <= p ? p : raw <= 2 * p ? 2 * p : raw <= 5 * p ? 5 * p : 10 * p;
    }

    private static double num(String text, double fallback) {
        Double d = text == null ? null : Numbers.parsePlain(text);
        return d == null ? fallback : d;
    }

    /**
     * The automaton ring: each state an arc proportional to its duration, exits on the edges,
     * each state named beside the ring with how long it lasts, its angles and its exit.
     */
    public static Scene ring(Ring r) {
        return ring(r, 1);
    }

    /**
     * {@link #ring(Ring)} with text {@code textScale} (at least 1) times as large, laid out again
     * so that no label meets another: for a screen where the drawing is shrunk to fit.
     */
    public static Scene ring(Ring r, double textScale) {
        return new Rings(textScale).ring(r);
    }

    /** The phase wheel: a tick per module at its phase delay, numbered by position; the hand to position 1's tick. */
    public static Scene wheel(PhaseWheel w) {
        return wheel(w, 1);
    }

    /** {@link #wheel(PhaseWheel)} with text {@code textScale} (at least 1) times as large, as {@link #ring(Ring, double)}. */
    public static Scene wheel(PhaseWheel w, double textScale) {
        return new Rings(textScale).wheel(w);
    }

    /**
     * The sector of each state of {@code r}, by state index, as {@link #ring(Ring, double)} draws it
     * at {@code textScale}: the index the IDE's live overlay marks states by.
     */
    public static List<Scene.Sector> ringArcs(Ring r, double textScale) {
        Rings rings = new Rings(textScale);
        return r.arcs().stream().map(rings::arc).toList();
    }

    /** The circle of the phase wheel, {@code {cx, cy, r}} (r: its outer edge), as {@link #wheel(PhaseWheel, double)} draws it at {@code textScale}. */
    public static double[] wheelCircle(double textScale) {
        return new Rings(textScale).wheelCircle();
    }

    /** The size of the smallest text of {@link #ring} and {@link #wheel} at text scale 1. */
    public static final double RING_TEXT = Rings.SMALLEST;

    /**
     * The ticks and the hand of {@code w} in the places of {@link #wheel}'s, in another colour:
     * drawn over the wheel while its hand is dragged, {@code w} having the phase it would set
     * ({@link PhaseWheel#withPhase}), {@code textScale} as the wheel was drawn with.
     */
    public static List<Scene.Shape> wheelPreview(PhaseWheel w, double textScale) {
        return new Rings(textScale).preview(w);
    }

    /**
     * Where {@link #gait} puts the plot of {@code g}: {@code {left, top, width, row height}} in
     * scene units (the live overlay draws over it).
     */
    public static double[] gaitPlot(GaitDiagram g) {
        int n = g.moduleIds().length;
        return new double[] {70, 50, 760, Math.max(1, Math.min(16, 480.0 / Math.max(1, n)))};
    }

    /** The colour of the state at {@code index} of {@link GaitDiagram#stateNames()} (colours repeat). */
    public static int stateColour(int index) {
        return PALETTE[Math.floorMod(index, PALETTE.length)];
    }

    /** The gait diagram: a row per module, time to the right, coloured by state (Fig. 4 of the paper). */
    public static Scene gait(GaitDiagram g) {
        int n = g.moduleIds().length;
        double[] plot = gaitPlot(g);
        double left = plot[0];
        double top = plot[1];
        double plotW = plot[2];
        double rowH = plot[3];
        List<String> names = g.stateNames();
        int[][][] colour = stateColours(g);
        int legendRows = Math.min(names.size(), 24);
        double h = top + n * rowH + 50 + ((legendRows + 3) / 4) * 18 + 20;
        Scene sc = new Scene((int) (left + plotW + 30), (int) h);
        double seconds = g.ticks() * g.dt();
        sc.add(new Scene.Text(20, 28, DiagramMsg.GAIT_TITLE.text(Numbers.format(Math.round((g.ticks() - 1) * g.dt() * 1000)
                / 1000.0), Numbers.format(g.dt())), 15, -1, INK, true));
        sc.add(new Scene.Rect(left, top, plotW, n * rowH, LIGHT, Scene.NONE, 0, null));
        double scale = plotW / g.ticks();
        for (GaitDiagram.Segment s : g.segments()) {
            boolean known = s.entry() >= 0 && s.entry() < colour.length && s.instance() >= 0
                    && s.instance() < colour[s.entry()].length && s.state() >= 0 && s.state() < colour[s.entry()][s.instance()].length;
            int k = known ? colour[s.entry()][s.instance()][s.state()] : 0;
            sc.add(new Scene.Rect(left + s.from() * scale, top + s.row() * rowH, (s.to() - s.from()) * scale, rowH,
                    stateColour(k), Scene.NONE, 0, null));
        }
        int labelEvery = (int) Math.ceil(12 / rowH);
        for (int m = 0; m < n; m += labelEvery) {
            sc.add(new Scene.Text(left - 6, top + m * rowH + Math.min(rowH, 12) - 1, Integer.toString(g.moduleIds()[m]),
                    Math.min(11, Math.max(8, rowH)), 1, INK, false));
        }
        double axis = top + n * rowH;
        for (double t = 0; t <= seconds + 1e-9; t += step(seconds)) {
            double x = left + t / g.dt() * scale;
            sc.add(new Scene.Line(x, axis, x, axis + 5, INK, 1, 0));
            sc.add(new Scene.Text(x, axis + 18, String.format(Locale.ROOT, "%s s", Numbers.format(Math.round(t * 100) / 100.0)),
                    10, 0, INK, false));
        }
        sc.add(new Scene.Text(12, top + 10, DiagramMsg.MODULE_AXIS.text(), 10, -1, GREY, false));
        double ly = axis + 44;
        for (int i = 0; i < legendRows; i++) {
            double x = left + (i % 4) * 190;
            double y = ly + (i / 4) * 18;
            sc.add(new Scene.Rect(x, y - 10, 12, 12, PALETTE[i % PALETTE.length], Scene.NONE, 0, null));
            sc.add(new Scene.Text(x + 18, y, names.get(i), 11, -1, INK, false));
        }
        if (names.size() > legendRows) {
            sc.add(new Scene.Text(left, ly + ((legendRows + 3) / 4) * 18, DiagramMsg.MORE_STATES.text(names.size() - legendRows),
                    11, -1, GREY, false));
        }
        return sc;
    }

    /**
     * The colour index ({@link #stateColour}) of every entry's instance's state of {@code g}, as
     * {@link #gait} colours them: by its name's place in {@link GaitDiagram#stateNames()} (looked
     * up once, here, not per segment nor by the IDE's live overlay, which takes this index).
     */
    public static int[][][] stateColours(GaitDiagram g) {
        List<String> names = g.stateNames();
        Map<String, Integer> colourOf = new java.util.HashMap<>();
        for (int i = 0; i < names.size(); i++) {
            colourOf.put(names.get(i), i);
        }
        int[][][] colour = new int[g.legend().size()][][];
        for (int e = 0; e < colour.length; e++) {
            colour[e] = new int[g.legend().get(e).size()][];
            for (int i = 0; i < colour[e].length; i++) {
                colour[e][i] = new int[g.legend().get(e).get(i).states().size()];
                for (int k = 0; k < colour[e][i].length; k++) {
                    colour[e][i][k] = colourOf.getOrDefault(g.stateName(e, i, k), 0);
                }
            }
        }
        return colour;
    }

    /** At least {@code min}, and wide enough for every island's line. */
    static int width(int min, List<TextIsland> islands) {
        double w = min;
        for (TextIsland t : islands) {
            w = Math.max(w, 50 + width(t.pos() + ": " + t.text(), 11));
        }
        return (int) Math.ceil(w);
    }

    static void islands(Scene sc, List<TextIsland> islands, double y) {
        for (TextIsland t : islands) {
            sc.add(new Scene.Rect(16, y - 12, 10, 14, 0xfff3b0, GREY, 1, t.pos()));
            sc.add(new Scene.Text(32, y, t.pos() + ": " + t.text(), 11, -1, 0x555555, false));
            y += 18;
        }
    }
}
