package org.parpe.sim.sheet;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeSet;
import org.parpe.core.diagram.Labels;
import org.parpe.core.diagram.Scene;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.Geo;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.PartKind;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.config.PartSpec;
import org.parpe.sim.config.PartType;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.internal.Assembly;
import org.parpe.sim.text.SimMsg;

/**
 * A worksheet drawing of an assembled robot at its initial pose: three orthographic views (top,
 * front, side) at one scale with each segment's module ID, and a list of the parts. Laid out
 * once as a {@link Scene}, so it is written as SVG or drawn as PNG like the script diagrams.
 */
public final class RobotSheet {
    /** The most parts listed; the rest are counted. */
    static final int MAX_LISTED = 60;
    private static final int VIEW = 300;
    private static final int MARGIN = 20;
    private static final int TITLE = 40;
    private static final int ROW = 16;
    /** The least room between two ID labels on one line, px. */
    private static final double GAP = 4;
    private static final int INK = 0x222222;
    private static final int GREY = 0x888888;
    private static final Map<PartKind, Integer> COLOURS = Map.of(PartKind.SEGMENT_BASE, 0x0072b2,
            PartKind.SEGMENT_ARM, 0x56b4e9, PartKind.NODE, 0x555555, PartKind.FOOT, 0x009e73, PartKind.HUB, 0xd55e00);

    /** A view: screen right and screen up as world directions. */
    private record View(SimMsg title, Vec3 right, Vec3 up) {
    }

    private static final List<View> VIEWS = List.of(
            new View(SimMsg.SHEET_TOP, new Vec3(1, 0, 0), new Vec3(0, 1, 0)),
            new View(SimMsg.SHEET_FRONT, new Vec3(1, 0, 0), new Vec3(0, 0, 1)),
            new View(SimMsg.SHEET_SIDE, new Vec3(0, 1, 0), new Vec3(0, 0, 1)));

    private RobotSheet() {
    }

    /** The sheet of {@code config} as {@code assembly} placed it. */
    public static Scene of(RobotConfig config, Assembly assembly) {
        List<PartSpec> parts = config.parts();
        int listed = Math.min(parts.size(), MAX_LISTED);
        int listTop = TITLE + VIEW + 50;
        int height = listTop + ROW * (listed + 2 + (parts.size() > listed ? 1 : 0)) + MARGIN;
        Scene sc = new Scene(2 * MARGIN + 3 * VIEW + 2 * MARGIN, height);
        String name = Path.of(config.name()).getFileName() == null ? config.name()
                : Path.of(config.name()).getFileName().toString();
        sc.add(new Scene.Text(MARGIN, 26, SimMsg.SHEET_TITLE.text(name, summary(parts)), 16, -1, INK, true));
        double scale = scale(assembly);
        for (int v = 0; v < VIEWS.size(); v++) {
            view(sc, assembly, VIEWS.get(v), MARGIN + v * (VIEW + MARGIN), TITLE, scale);
        }
        sc.add(new Scene.Text(MARGIN, TITLE + VIEW + 24, SimMsg.SHEET_SCALE.text(cm(assembly, 0), cm(assembly, 1),
                cm(assembly, 2)), 12, -1, GREY, false));
        partList(sc, parts, listTop);
        return sc;
    }

    /** What the robot is made of, in words: "12 segments, 1 node, 4 feet". */
    public static String summary(List<PartSpec> parts) {
        StringBuilder s = new StringBuilder();
        for (PartType t : PartType.values()) {
            long n = parts.stream().filter(p -> p.type() == t).count();
            if (n > 0) {
                s.append(s.length() == 0 ? "" : ", ").append(t.count(n));
            }
        }
        return s.toString();
    }

    /** A view's title at 12 px, or smaller where a language's words would not fit in {@code room}. */
    private static Scene.Text title(String text, double x, double y, double room) {
        double w = Labels.box(new Scene.Text(x, y, text, 12, -1, INK, false)).w();
        return new Scene.Text(x, y, text, w <= room ? 12 : 12 * room / w, -1, INK, false);
    }

    private static void view(Scene sc, Assembly a, View v, double x0, double y0, double scale) {
        sc.add(new Scene.Rect(x0, y0, VIEW, VIEW, Scene.NONE, 0xcccccc, 1, null));
        sc.add(title(v.title().text(), x0 + 6, y0 + 16, VIEW - 12));
        double[] lo = {Double.MAX_VALUE, Double.MAX_VALUE};
        double[] hi = {-Double.MAX_VALUE, -Double.MAX_VALUE};
        for (Assembly.PlacedPiece p : a.pieces()) {
            for (Vec3 c : corners(p)) {
                double u = Geo.dot(c, v.right());
                double w = Geo.dot(c, v.up());
                lo[0] = Math.min(lo[0], u);
                hi[0] = Math.max(hi[0], u);
                lo[1] = Math.min(lo[1], w);
                hi[1] = Math.max(hi[1], w);
            }
        }
        double cx = x0 + VIEW / 2.0 - scale * (lo[0] + hi[0]) / 2;
        double cy = y0 + 12 + VIEW / 2.0 + scale * (lo[1] + hi[1]) / 2;
        for (Assembly.PlacedPiece p : a.pieces()) {
            int colour = COLOURS.getOrDefault(p.def().kind(), INK);
            Vec3[] c = corners(p);
            for (int[] e : edges(p)) {
                sc.add(new Scene.Line(cx + scale * Geo.dot(c[e[0]], v.right()), cy - scale * Geo.dot(c[e[0]], v.up()),
                        cx + scale * Geo.dot(c[e[1]], v.right()), cy - scale * Geo.dot(c[e[1]], v.up()), colour, 1, 0));
            }
        }
        List<IdLabel> labels = new ArrayList<>();
        List<Assembly.Hinge> hinges = new ArrayList<>(a.hinges());
        hinges.sort(Comparator.comparingInt(Assembly.Hinge::moduleId));
        for (Assembly.Hinge h : hinges) {
            Vec3 m = Geo.scale(Geo.add(a.pieces().get(h.base()).position(), a.pieces().get(h.arm()).position()), 0.5);
            double px = cx + scale * Geo.dot(m, v.right());
            double py = cy - scale * Geo.dot(m, v.up());
            IdLabel same = labels.stream().filter(l -> Math.hypot(l.px - px, l.py - py) < 1).findFirst().orElse(null);
            if (same != null) {
                same.ids.add(h.moduleId());
            } else {
                labels.add(new IdLabel(new TreeSet<>(List.of(h.moduleId())), px, py));
            }
        }
        placeIds(sc, labels, x0, y0);
        sc.add(new Scene.Line(x0 + 10, y0 + VIEW - 10, x0 + 10 + scale * 0.1, y0 + VIEW - 10, GREY, 3, 0));
    }

    /** The IDs of the hinges drawn at one point of a view ("3, 4": lined up along the view), and where it is. */
    private static final class IdLabel {
        final TreeSet<Integer> ids;
        final double px;
        final double py;
        double dx;
        double dy;

        IdLabel(TreeSet<Integer> ids, double px, double py) {
            this.ids = ids;
            this.px = px;
            this.py = py;
        }

        Scene.Text text() {
            return new Scene.Text(px + dx, py + dy + 4, text(ids), 11, 0, INK, true);
        }

        /** "3", "3, 4", "0, 1, 2", "3, 5-9": runs of four or more IDs as ranges. */
        static String text(TreeSet<Integer> ids) {
            StringBuilder s = new StringBuilder();
            List<Integer> all = List.copyOf(ids);
            for (int i = 0; i < all.size(); i++) {
                int j = i;
                while (j + 1 < all.size() && all.get(j + 1) == all.get(j) + 1) {
                    j++;
                }
                s.append(s.length() == 0 ? "" : ", ").append(all.get(i));
                if (j >= i + 3) {
                    s.append('-').append(all.get(j));
                    i = j;
                }
            }
            return s.toString();
        }
    }

    /**
     * Where a label that meets one placed before may go: {label widths right, px down}; up, down,
     * right, left, then further out, row by row, above and below (a long robot's views have room
     * there: the centipede's 55 IDs need it).
     */
    private static final double[][] NUDGES = nudges();

    private static double[][] nudges() {
        List<double[]> n = new ArrayList<>(List.of(new double[] {0, -14}, new double[] {0, 14}, new double[] {1, 0},
                new double[] {-1, 0}, new double[] {0, -28}, new double[] {0, 28}, new double[] {1, -14},
                new double[] {-1, -14}, new double[] {1, 14}, new double[] {-1, 14}));
        for (int row = 2; row <= 9; row++) {
            for (int side : new int[] {-1, 1}) {
                if (row > 2) {
                    n.add(new double[] {0, side * 14 * row});
                }
                n.add(new double[] {0.5, side * 14 * row});
                n.add(new double[] {-0.5, side * 14 * row});
            }
        }
        return n.toArray(double[][]::new);
    }

    /**
     * Adds the ID labels of a view, each at its hinge unless its text would meet one placed
     * before: then at the first free nudge inside the view with a thin leader line to its hinge,
     * or, with no free place, merged into the label it meets, which is then placed again (grown,
     * it may meet others).
     */
    private static void placeIds(Scene sc, List<IdLabel> labels, double x0, double y0) {
        List<IdLabel> placed = new ArrayList<>();
        for (IdLabel l : labels) {
            place(l, placed, x0, y0);
        }
        for (IdLabel l : placed) {
            Scene.Text t = l.text();
            if (l.dx != 0 || l.dy != 0) {
                Labels.Box b = Labels.box(t);
                sc.add(new Scene.Line(l.px, l.py, Math.max(b.x(), Math.min(l.px, b.x() + b.w())),
                        Math.max(b.y(), Math.min(l.py, b.y() + b.h())), GREY, 0.5, 0));
            }
            sc.add(t);
        }
    }

    /**
     * Adds {@code l} to {@code placed}: at its hinge if free and inside the view, else nudged, else
     * merged (each merge leaves one label fewer, so this ends).
     */
    private static void place(IdLabel l, List<IdLabel> placed, double x0, double y0) {
        IdLabel met = meets(l, placed);
        boolean free = met == null && inside(l, x0, y0);
        if (free || nudge(l, placed, x0, y0) || met == null) {
            placed.add(l); // at its hinge, nudged, or (only sticking out of the view) at its hinge
            return;
        }
        placed.remove(met);
        met.ids.addAll(l.ids);
        met.dx = 0;
        met.dy = 0;
        place(met, placed, x0, y0);
    }

    /** Moves {@code l} to the first nudge inside the view where it meets none of {@code placed}; false if none. */
    private static boolean nudge(IdLabel l, List<IdLabel> placed, double x0, double y0) {
        double w = Labels.box(l.text()).w();
        for (double[] n : NUDGES) {
            l.dx = n[0] * (w + 8);
            l.dy = n[1];
            if (inside(l, x0, y0) && meets(l, placed) == null) {
                return true;
            }
        }
        l.dx = 0;
        l.dy = 0;
        return false;
    }

    /** Whether {@code l}'s text is inside the view at ({@code x0}, {@code y0}), clear of its title and scale bar. */
    private static boolean inside(IdLabel l, double x0, double y0) {
        Labels.Box b = Labels.box(l.text());
        return b.x() > x0 + 2 && b.x() + b.w() < x0 + VIEW - 2 && b.y() > y0 + 20 && b.y() + b.h() < y0 + VIEW - 16;
    }

    /**
     * The first of {@code placed} other than {@code l} whose text meets {@code l}'s or comes
     * closer than {@link #GAP} beside it (IDs "52" and "50" side by side would read "5250"), or null.
     */
    private static IdLabel meets(IdLabel l, List<IdLabel> placed) {
        Labels.Box t = Labels.box(l.text());
        Labels.Box b = new Labels.Box(t.x() - GAP, t.y(), t.w() + 2 * GAP, t.h());
        return placed.stream().filter(p -> p != l && Labels.box(p.text()).overlaps(b)).findFirst().orElse(null);
    }

    /** One scale for the three views: the robot's largest extent fills a view with a margin. */
    private static double scale(Assembly a) {
        double most = Math.max(extent(a, 0), Math.max(extent(a, 1), extent(a, 2)));
        return (VIEW - 60) / Math.max(most, 0.05);
    }

    /** The robot's size along {@code axis} in whole centimetres, as the scale line writes it. */
    private static String cm(Assembly a, int axis) {
        return String.format(Locale.ROOT, "%.0f", extent(a, axis) * 100);
    }

    /** The robot's extent along world axis {@code axis} (0 x, 1 y, 2 z), m. */
    private static double extent(Assembly a, int axis) {
        double lo = Double.MAX_VALUE;
        double hi = -Double.MAX_VALUE;
        for (Assembly.PlacedPiece p : a.pieces()) {
            for (Vec3 c : corners(p)) {
                double x = axis == 0 ? c.x() : axis == 1 ? c.y() : c.z();
                lo = Math.min(lo, x);
                hi = Math.max(hi, x);
            }
        }
        return hi - lo;
    }

    /** Corners of a piece in the world: a box's eight, a disc's rims as two 16-gons. */
    private static Vec3[] corners(Assembly.PlacedPiece p) {
        BodyShape s = p.def().shape();
        Vec3[] local;
        if (s instanceof BodyShape.Box b) {
            local = new Vec3[8];
            for (int i = 0; i < 8; i++) {
                local[i] = new Vec3((i & 1) == 0 ? -b.hx() : b.hx(), (i & 2) == 0 ? -b.hy() : b.hy(),
                        (i & 4) == 0 ? -b.hz() : b.hz());
            }
        } else {
            double r = s instanceof BodyShape.Cylinder c ? c.radius() : ((BodyShape.Sphere) s).radius();
            double h = s instanceof BodyShape.Cylinder c ? c.length() / 2 : 0;
            local = new Vec3[32];
            for (int i = 0; i < 16; i++) {
                double t = 2 * Math.PI * i / 16;
                local[i] = new Vec3(r * Math.cos(t), r * Math.sin(t), -h);
                local[16 + i] = new Vec3(r * Math.cos(t), r * Math.sin(t), h);
            }
        }
        Mat3 r = p.rotation();
        Vec3[] world = new Vec3[local.length];
        for (int i = 0; i < local.length; i++) {
            world[i] = Geo.add(p.position(), Geo.mul(r, local[i]));
        }
        return world;
    }

    /** Edges between {@link #corners}: a box's twelve; a disc's rims and four lines across. */
    private static int[][] edges(Assembly.PlacedPiece p) {
        if (p.def().shape() instanceof BodyShape.Box) {
            return BOX_EDGES;
        }
        int[][] e = new int[36][];
        for (int i = 0; i < 16; i++) {
            e[i] = new int[] {i, (i + 1) % 16};
            e[16 + i] = new int[] {16 + i, 16 + (i + 1) % 16};
        }
        for (int k = 0; k < 4; k++) {
            e[32 + k] = new int[] {4 * k, 16 + 4 * k};
        }
        return e;
    }

    private static final int[][] BOX_EDGES = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3}, {4, 6}, {5, 7},
        {0, 4}, {1, 5}, {2, 6}, {3, 7}};

    private static void partList(Scene sc, List<PartSpec> parts, double top) {
        double[] col = {MARGIN, MARGIN + 200, MARGIN + 300, MARGIN + 400, MARGIN + 500, MARGIN + 580};
        SimMsg[] head = {SimMsg.SHEET_PART, SimMsg.SHEET_TYPE, SimMsg.SHEET_MODULE_ID, SimMsg.SHEET_ANGLE, SimMsg.SHEET_LIMP,
            SimMsg.SHEET_DEFINED_AT};
        for (int i = 0; i < head.length; i++) {
            Scene.Text t = new Scene.Text(col[i], top, head[i].text(), 12, -1, INK, true);
            sc.add(t);
            if (i + 1 < col.length) { // a longer heading in another language pushes the next columns right
                col[i + 1] = Math.max(col[i + 1], col[i] + Labels.box(t).w() + 3 * GAP);
            }
        }
        sc.add(new Scene.Line(MARGIN, top + 4, sc.width() - MARGIN, top + 4, GREY, 1, 0));
        double y = top;
        for (int k = 0; k < Math.min(parts.size(), MAX_LISTED); k++) {
            PartSpec p = parts.get(k);
            y += ROW;
            String[] cells = {p.name(), p.type() == PartType.HUB ? SimMsg.SHEET_HUB_PLATES.text(p.type().xmlName(), p.plates())
                : p.type().xmlName(),
                p.isSegment() ? Integer.toString(p.moduleId()) : "",
                p.isSegment() ? org.parpe.core.xml.FlatXmlFile.plain(p.angle()) + "°" : "",
                p.limp() ? SimMsg.SHEET_LIMP.text() : "", p.pos().line() > 0 ? SimMsg.SHEET_LINE.text(p.pos().line()) : ""};
            for (int i = 0; i < cells.length; i++) {
                sc.add(new Scene.Text(col[i], y, cells[i], 12, -1, i == 2 ? 0x0072b2 : INK, i == 2));
            }
        }
        if (parts.size() > MAX_LISTED) {
            sc.add(new Scene.Text(MARGIN, y + ROW, SimMsg.SHEET_MORE.text(parts.size() - MAX_LISTED), 12, -1, GREY, false));
        }
    }
}
