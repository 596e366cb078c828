package org.parpe.core.diagram;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * Text labels that never overlap: the box a {@link Scene.Text} takes (estimated from its
 * length, as every back end's sans-serif font is about as wide), a column of label blocks pushed
 * apart, and a greedy placement that leaves out a label whose box would meet one placed before.
 * The ring and the phase wheel ({@link Layouts#ring}, {@link Layouts#wheel}) are laid out with
 * it, and tests check their drawings with {@link #box}.
 */
public final class Labels {
    /** Width of a character in ems, a little more than DejaVu Sans's mean (its digits are 0.64 em). */
    private static final double CHAR = 0.58;
    private static final double BOLD = 0.64;
    /** Height of a line of text, in ems. */
    static final double LINE = 1.3;

    private Labels() {
    }

    /** A rectangle in scene units. */
    public record Box(double x, double y, double w, double h) {
        /** Whether this box and {@code o} share any area. */
        public boolean overlaps(Box o) {
            return x < o.x + o.w && o.x < x + w && y < o.y + h && o.y < y + h;
        }
    }

    /** The estimated width of {@code s} at {@code size}. */
    static double width(String s, double size, boolean bold) {
        return s.length() * size * (bold ? BOLD : CHAR);
    }

    /** The box text {@code t} takes: from its ascent above the baseline to its descent below. */
    public static Box box(Scene.Text t) {
        double w = width(t.text(), t.size(), t.bold());
        double x = t.anchor() < 0 ? t.x() : t.anchor() == 0 ? t.x() - w / 2 : t.x() - w;
        return new Box(x, t.y() - 0.95 * t.size(), w, 1.2 * t.size());
    }

    /** {@code s} cut to at most {@code room} wide at {@code size}, with "…" when cut. */
    static String fit(String s, double size, boolean bold, double room) {
        if (width(s, size, bold) <= room) {
            return s;
        }
        int n = Math.max(1, (int) (room / (size * (bold ? BOLD : CHAR))) - 1);
        return s.substring(0, Math.min(s.length(), n)) + "…";
    }

    /** One line of a label block. */
    record Line(String text, double size, boolean bold, int color) {
    }

    /**
     * A block of lines beside a point it stands for ({@code wantY}: where its middle should be);
     * {@link #stack} sets {@code top}.
     */
    static final class Block {
        final List<Line> lines;
        final double wantY;
        final Object key;
        double top;

        Block(List<Line> lines, double wantY, Object key) {
            this.lines = List.copyOf(lines);
            this.wantY = wantY;
            this.key = key;
        }

        double height() {
            return lines.stream().mapToDouble(l -> l.size() * LINE).sum();
        }

        /** Adds the lines to {@code sc} from {@code top}, starting at, centred on or ending at {@code x}. */
        void draw(Scene sc, double x, int anchor) {
            double y = top;
            for (Line l : lines) {
                y += l.size() * LINE;
                sc.add(new Scene.Text(x, y - 0.3 * l.size(), l.text(), l.size(), anchor, l.color(), l.bold()));
            }
        }
    }

    /**
     * Puts {@code blocks} one under the other in a column, each as near its wanted place as the
     * others let it, {@code gap} apart, from {@code top} down and, when they fit, above
     * {@code bottom}; returns the bottom of the lowest (a column longer than the room goes on
     * below {@code bottom}).
     */
    static double stack(List<Block> blocks, double top, double bottom, double gap) {
        List<Block> order = new ArrayList<>(blocks);
        order.sort(Comparator.comparingDouble(b -> b.wantY));
        for (Block b : order) {
            b.top = b.wantY - b.height() / 2;
        }
        down(order, top, gap);
        for (int i = order.size() - 1; i >= 0; i--) {
            Block b = order.get(i);
            double limit = i == order.size() - 1 ? bottom : order.get(i + 1).top - gap;
            b.top = Math.min(b.top, limit - b.height());
        }
        return down(order, top, gap);
    }

    private static double down(List<Block> order, double top, double gap) {
        double at = top;
        for (Block b : order) {
            b.top = Math.max(b.top, at);
            at = b.top + b.height() + gap;
        }
        return at - gap;
    }

    /**
     * Adds each of {@code texts} (the first first: put those that must show early) to {@code sc}
     * unless its box would meet the box of one added before or one of {@code taken}; returns the
     * boxes now taken.
     */
    static List<Box> place(Scene sc, List<Scene.Text> texts, List<Box> taken) {
        List<Box> boxes = new ArrayList<>(taken);
        for (Scene.Text t : texts) {
            Box b = box(t);
            if (boxes.stream().noneMatch(b::overlaps)) {
                boxes.add(b);
                sc.add(t);
            }
        }
        return boxes;
    }
}
