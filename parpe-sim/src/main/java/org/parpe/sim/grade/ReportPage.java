package org.parpe.sim.grade;

import java.util.List;
import java.util.Locale;
import org.parpe.core.text.Lang;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.text.SimMsg;
import org.parpe.sim.world.Challenge;
import org.parpe.sim.world.World;

/**
 * The report as one self-contained HTML page: the ranked table and an inline SVG map of the world
 * (arena, walls and other solids seen from above, zones, checkpoints, the start) with each ranked
 * robot's centre-of-mass path. Every text that comes from a file name or a message is escaped;
 * the page loads nothing (no scripts, no links but to the traces beside it).
 */
public final class ReportPage {
    private static final String[] COLOURS = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf",
        "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22"};
    private static final String STYLE = "body{font-family:sans-serif;margin:1.5em;color:#222}"
            + "table{border-collapse:collapse;margin-top:1em}td,th{border:1px solid #bbb;padding:.25em .5em;"
            + "vertical-align:top;text-align:left;white-space:nowrap}td.n{text-align:right;font-variant-numeric:tabular-nums}"
            + "tr.bad td{background:#fff3f0}pre{margin:0;white-space:pre-wrap;font-size:.85em;max-width:50em}"
            + "svg{border:1px solid #999;background:#fafafa;max-width:100%;height:auto}.sw{display:inline-block;"
            + "width:1em;height:.6em;margin-right:.3em}";

    /** The table's column headings. */
    private static final List<SimMsg> HEADINGS = List.of(SimMsg.REPORT_RANK, SimMsg.REPORT_STUDENT, SimMsg.REPORT_SCORE,
            SimMsg.REPORT_PARTS, SimMsg.REPORT_FORWARD, SimMsg.REPORT_DISTANCE, SimMsg.REPORT_FELL, SimMsg.REPORT_TIME,
            SimMsg.REPORT_TRACE, SimMsg.REPORT_PROBLEM);

    private ReportPage() {
    }

    /**
     * The page for {@code rows} (in rank order) of challenge {@code c} in {@code world}, its words
     * in the chosen language ({@link Lang}), which the page declares.
     */
    public static String html(List<Row> rows, Challenge c, World world) {
        String title = esc(SimMsg.REPORT_TITLE.text(c.file().getFileName()));
        StringBuilder b = new StringBuilder("<!DOCTYPE html>\n<html lang=\"").append(Lang.current().toLanguageTag())
                .append("\">\n<head>\n<meta charset=\"utf-8\">\n");
        b.append("<title>").append(title).append("</title>\n");
        b.append("<style>").append(STYLE).append("</style>\n</head>\n<body>\n");
        b.append("<h1>").append(title).append("</h1>\n<p>").append(esc(Report.summary(rows, c))).append("</p>\n");
        b.append(new WorldMap(world).svg(rows)).append('\n');
        table(b, rows);
        return b.append("</body>\n</html>\n").toString();
    }

    private static void table(StringBuilder b, List<Row> rows) {
        b.append("<table>\n<tr>");
        for (SimMsg h : HEADINGS) {
            b.append("<th>").append(esc(h.text())).append("</th>");
        }
        b.append("</tr>\n");
        for (int i = 0; i < rows.size(); i++) {
            Row r = rows.get(i);
            Outcome o = r.outcome();
            b.append(r.rank() > 0 ? "<tr>" : "<tr class=\"bad\">");
            b.append("<td class=\"n\">").append(r.rank() > 0 ? r.rank() : "-").append("</td><td>");
            if (r.rank() > 0) {
                b.append("<span class=\"sw\" style=\"background:").append(colour(i)).append("\"></span>");
            }
            b.append(esc(r.student().name())).append("</td>");
            if (o.ranked()) {
                b.append(String.format(Locale.ROOT, "<td class=\"n\">%.1f</td><td>%s</td><td class=\"n\">%.3f</td>"
                        + "<td class=\"n\">%.3f</td><td>%s</td><td class=\"n\">%.2f</td>", o.score(), esc(o.parts()),
                        o.dx(), o.distance(), esc((o.fell() ? SimMsg.REPORT_YES : SimMsg.REPORT_NO).text()), o.time()));
            } else {
                b.append("<td></td><td></td><td></td><td></td><td></td><td></td>");
            }
            b.append("<td>").append(r.trace().isEmpty() ? "" : "<a href=\"" + esc(r.trace()) + "\">CSV</a>").append("</td>");
            b.append("<td>").append(o.reason().isEmpty() ? "" : "<pre>" + esc(o.reason()) + "</pre>").append("</td></tr>\n");
        }
        b.append("</table>\n");
    }

    /** The colour of the path of the robot in row {@code i} (from 0): rows that share a rank differ. */
    static String colour(int i) {
        return COLOURS[i % COLOURS.length];
    }

    /** {@code s} as HTML text or attribute value: markup, quotes and control characters escaped. */
    static String esc(String s) {
        StringBuilder b = new StringBuilder(s.length());
        for (int i = 0; i < s.length(); i++) {
            char ch = s.charAt(i);
            switch (ch) {
                case '&' -> b.append("&amp;");
                case '<' -> b.append("&lt;");
                case '>' -> b.append("&gt;");
                case '"' -> b.append("&quot;");
                case '\'' -> b.append("&#39;");
                default -> b.append(ch < 0x20 && ch != '\n' ? "&#xFFFD;" : String.valueOf(ch));
            }
        }
        return b.toString();
    }

    /** The world seen from above, in metres (y up), as an SVG element. */
    private record WorldMap(World world) {
        String svg(List<Row> rows) {
            double[] box = bounds(rows);
            double w = box[2] - box[0];
            double h = box[3] - box[1];
            double stroke = Math.max(w, h) / 400;
            StringBuilder b = new StringBuilder(String.format(Locale.ROOT,
                    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"%s %s %s %s\">",
                    Math.round(900 * Math.min(1, w / h)), Math.round(900 * Math.min(1, h / w)),
                    n(box[0]), n(-box[3]), n(w), n(h)));
            if (world.arena() != null) {
                rect(b, world.arena(), "fill=\"#fff\" stroke=\"#999\"", stroke);
            }
            for (World.Solid s : world.solids()) {
                if (s.shape() instanceof BodyShape.Box box3) {
                    solid(b, s, box3, stroke);
                }
            }
            world.zones().forEach(z -> rect(b, z, "fill=\"#2ca02c\" fill-opacity=\"0.15\" stroke=\"#2ca02c\"", stroke));
            world.checkpoints().forEach(z -> rect(b, z, "fill=\"none\" stroke=\"#aaa\" stroke-dasharray=\""
                    + n(stroke * 4) + "\"", stroke));
            b.append(String.format(Locale.ROOT, "<circle cx=\"%s\" cy=\"%s\" r=\"%s\" fill=\"#000\"/>",
                    n(world.start().x()), n(-world.start().y()), n(stroke * 4)));
            for (int i = rows.size() - 1; i >= 0; i--) { // the winner drawn last, on top
                Row r = rows.get(i);
                if (r.rank() > 0 && r.path().length >= 4) {
                    path(b, r, colour(i), stroke);
                }
            }
            return b.append("</svg>").toString();
        }

        private static void path(StringBuilder b, Row r, String colour, double stroke) {
            b.append("<polyline fill=\"none\" stroke-width=\"").append(n(stroke * 2)).append("\" stroke=\"")
                    .append(colour).append("\" points=\"");
            double[] p = r.path();
            for (int k = 0; k + 1 < p.length; k += 2) {
                b.append(k == 0 ? "" : " ").append(n(p[k])).append(',').append(n(-p[k + 1]));
            }
            b.append("\"><title>").append(r.rank()).append(". ").append(esc(r.student().name())).append("</title></polyline>");
        }

        private static void rect(StringBuilder b, World.Region z, String style, double stroke) {
            b.append(String.format(Locale.ROOT, "<rect x=\"%s\" y=\"%s\" width=\"%s\" height=\"%s\" stroke-width=\"%s\" %s/>",
                    n(Math.min(z.x0(), z.x1())), n(-Math.max(z.y0(), z.y1())), n(Math.abs(z.x1() - z.x0())),
                    n(Math.abs(z.y1() - z.y0())), n(stroke), style));
        }

        /** A box's footprint: its four corners turned by its rotation about z. */
        private static void solid(StringBuilder b, World.Solid s, BodyShape.Box box, double stroke) {
            double c = s.rotation().get(0, 0);
            double si = s.rotation().get(1, 0);
            b.append("<polygon fill=\"#777\" fill-opacity=\"0.3\" stroke=\"#777\" stroke-width=\"").append(n(stroke))
                    .append("\" points=\"");
            double[][] corners = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
            for (int k = 0; k < 4; k++) {
                double lx = corners[k][0] * box.hx();
                double ly = corners[k][1] * box.hy();
                double x = s.position().x() + c * lx - si * ly;
                double y = s.position().y() + si * lx + c * ly;
                b.append(k == 0 ? "" : " ").append(n(x)).append(',').append(n(-y));
            }
            b.append("\"/>");
        }

        /** x0, y0, x1, y1 around the arena (or the solids, zones and paths), with a margin. */
        private double[] bounds(List<Row> rows) {
            double[] box = {world.start().x() - 0.5, world.start().y() - 0.5, world.start().x() + 0.5, world.start().y() + 0.5};
            if (world.arena() != null) {
                World.Region a = world.arena();
                box = new double[] {Math.min(a.x0(), a.x1()), Math.min(a.y0(), a.y1()), Math.max(a.x0(), a.x1()),
                    Math.max(a.y0(), a.y1())};
            } else {
                for (World.Solid s : world.solids()) {
                    box = grow(box, s.position().x(), s.position().y());
                }
                for (World.Region z : world.zones()) {
                    box = grow(grow(box, z.x0(), z.y0()), z.x1(), z.y1());
                }
            }
            for (Row r : rows) {
                for (int k = 0; r.rank() > 0 && k + 1 < r.path().length; k += 2) {
                    box = grow(box, r.path()[k], r.path()[k + 1]);
                }
            }
            double m = 0.05 * Math.max(box[2] - box[0], box[3] - box[1]);
            return new double[] {box[0] - m, box[1] - m, box[2] + m, box[3] + m};
        }

        private static double[] grow(double[] box, double x, double y) {
            return new double[] {Math.min(box[0], x), Math.min(box[1], y), Math.max(box[2], x), Math.max(box[3], y)};
        }

        private static String n(double v) {
            return String.format(Locale.ROOT, "%.4f", v);
        }
    }
}
