package org.parpe.cli.plot;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.geom.Ellipse2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageInputStream;
import javax.imageio.stream.ImageOutputStream;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.Marker;
import org.knowm.xchart.style.markers.SeriesMarkers;
import org.parpe.core.plot.PlotStyle;
import org.w3c.dom.NodeList;

/**
 * Every PNG plot of the command line ({@code --plot}, the sweep, optimisation and merge plots),
 * drawn by XChart in the one style of {@link PlotStyle}: panels of one look, series of angles
 * (commanded dashed, measured solid), dots and rings of runs, and the panels written one under
 * the other as a single PNG. Headless: no window system.
 */
public final class PngCharts {
    private static final Font TITLE = new Font(Font.SANS_SERIF, Font.BOLD, 15);
    private static final Font TEXT = new Font(Font.SANS_SERIF, Font.PLAIN, 13);

    private PngCharts() {
    }

    /** A panel of {@code width} × {@code height} pixels with its title and axis titles. */
    public static XYChart panel(int width, int height, String title, String xTitle, String yTitle) {
        System.setProperty("java.awt.headless", "true");
        XYChart c = new XYChartBuilder().width(width).height(height).title(title).xAxisTitle(xTitle)
                .yAxisTitle(yTitle).build();
        Styler s = c.getStyler();
        s.setChartBackgroundColor(Color.WHITE);
        s.setPlotBackgroundColor(Color.WHITE);
        s.setPlotBorderColor(Color.BLACK);
        s.setChartTitleBoxVisible(false);
        s.setChartTitleFont(TITLE);
        s.setLegendFont(TEXT);
        s.setLegendPosition(Styler.LegendPosition.OutsideS);
        // One entry a row: XChart 3.8.8's horizontal legend moves on from a dot's entry by less
        // than it drew (a box's 20 px for a 24 px line), so a label ran into the next entry.
        s.setLegendLayout(Styler.LegendLayout.Vertical);
        s.setLegendBorderColor(Color.WHITE);
        c.getStyler().setAxisTitleFont(TEXT);
        c.getStyler().setAxisTickLabelsFont(TEXT.deriveFont(12f));
        c.getStyler().setPlotGridLinesColor(new Color(0xE6E6E6));
        c.getStyler().setAntiAlias(true);
        // A fixed pattern spares XChart formatting the labels of every candidate tick spacing.
        c.getStyler().setXAxisDecimalPattern("#0.##");
        c.getStyler().setYAxisDecimalPattern("#0.##");
        return c;
    }

    /** The commanded (dashed) or measured (solid) angle of a module, in {@code rgb}; finite points only. */
    public static XYSeries angle(XYChart c, String name, double[] t, double[] v, int n, int rgb, boolean commanded) {
        XYSeries s = line(c, name, t, v, n, rgb);
        if (PlotStyle.dashed(commanded)) {
            s.setLineStyle(new BasicStroke(PlotStyle.LINE_WIDTH * 0.8f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER,
                    10f, PlotStyle.dash(1f), 0f));
        } else {
            s.setLineStyle(new BasicStroke(PlotStyle.LINE_WIDTH));
        }
        return s;
    }

    /** A solid line through the first {@code n} finite points, in {@code rgb}, with no markers. */
    public static XYSeries line(XYChart c, String name, double[] x, double[] y, int n, int rgb) {
        double[][] xy = finite(x, y, n);
        XYSeries s = c.addSeries(name, xy[0], xy[1]);
        s.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line);
        s.setMarker(SeriesMarkers.NONE);
        s.setLineColor(color(rgb));
        s.setLineStyle(new BasicStroke(PlotStyle.LINE_WIDTH));
        return s;
    }

    /** Dots (filled) or rings (hollow: set apart) at the finite points, or nothing when there are none. */
    public static XYSeries points(XYChart c, String name, double[] x, double[] y, int rgb, boolean hollow) {
        double[][] xy = finite(x, y, x.length);
        if (xy[0].length == 0) {
            return null;
        }
        XYSeries s = c.addSeries(name, xy[0], xy[1]);
        s.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
        s.setMarker(hollow ? new Ring() : SeriesMarkers.CIRCLE);
        s.setMarkerColor(color(rgb));
        return s;
    }

    /**
     * Writes the panels one under the other as one PNG, whose {@code Title} text (the keyword of
     * the W3C PNG specification, second edition, section 11.3.4.2) is the first panel's title, so that a file browser or a test can read what
     * it shows without looking at it.
     */
    public static void write(List<XYChart> panels, OutputStream out) throws IOException {
        int width = 0;
        int height = 0;
        for (XYChart c : panels) {
            width = Math.max(width, c.getWidth());
            height += c.getHeight();
        }
        BufferedImage img = new BufferedImage(Math.max(1, width), Math.max(1, height), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, img.getWidth(), img.getHeight());
        int top = 0;
        for (XYChart c : panels) {
            Graphics2D p = (Graphics2D) g.create(0, top, c.getWidth(), c.getHeight());
            c.paint(p, c.getWidth(), c.getHeight());
            p.dispose();
            top += c.getHeight();
        }
        g.dispose();
        writePng(img, panels.isEmpty() ? "" : panels.get(0).getTitle(), out);
    }

    /** The title a PNG written by {@link #write} carries, or {@code null} if it has none. */
    public static String title(ImageInputStream png) throws IOException {
        ImageReader r = ImageIO.getImageReadersByFormatName("png").next();
        try {
            r.setInput(png);
            IIOMetadataNode root = (IIOMetadataNode) r.getImageMetadata(0).getAsTree(PNG_METADATA);
            NodeList texts = root.getElementsByTagName("iTXtEntry");
            for (int i = 0; i < texts.getLength(); i++) {
                IIOMetadataNode t = (IIOMetadataNode) texts.item(i);
                if (TITLE_KEY.equals(t.getAttribute("keyword"))) {
                    return t.getAttribute("text");
                }
            }
            return null;
        } finally {
            r.dispose();
        }
    }

    private static final String PNG_METADATA = "javax_imageio_png_1.0";
    private static final String TITLE_KEY = "Title";

    /** Writes {@code img} as PNG with {@code title} as its (UTF-8: a file name may be any text) title. */
    private static void writePng(BufferedImage img, String title, OutputStream out) throws IOException {
        ImageWriter w = ImageIO.getImageWritersByFormatName("png").next();
        try (ImageOutputStream ios = ImageIO.createImageOutputStream(out)) {
            ImageWriteParam param = w.getDefaultWriteParam();
            IIOMetadata meta = w.getDefaultImageMetadata(ImageTypeSpecifier.createFromRenderedImage(img), param);
            IIOMetadataNode entry = new IIOMetadataNode("iTXtEntry");
            entry.setAttribute("keyword", TITLE_KEY);
            entry.setAttribute("compressionFlag", "FALSE");
            entry.setAttribute("compressionMethod", "0");
            entry.setAttribute("languageTag", "");
            entry.setAttribute("translatedKeyword", "");
            entry.setAttribute("text", title);
            IIOMetadataNode text = new IIOMetadataNode("iTXt");
            text.appendChild(entry);
            IIOMetadataNode root = new IIOMetadataNode(PNG_METADATA);
            root.appendChild(text);
            meta.mergeTree(PNG_METADATA, root);
            w.setOutput(ios);
            w.write(null, new IIOImage(img, null, meta), param);
        } finally {
            w.dispose();
        }
    }

    private static double[][] finite(double[] x, double[] y, int n) {
        List<double[]> kept = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            if (Double.isFinite(x[i]) && Double.isFinite(y[i])) {
                kept.add(new double[] {x[i], y[i]});
            }
        }
        double[][] out = new double[2][kept.size()];
        for (int i = 0; i < kept.size(); i++) {
            out[0][i] = kept.get(i)[0];
            out[1][i] = kept.get(i)[1];
        }
        return out;
    }

    private static Color color(int rgb) {
        return new Color(rgb);
    }

    /** A hollow circle: a run set apart from the filled dots (it fell over). */
    public static final class Ring extends Marker {
        @Override
        public void paint(Graphics2D g, double x, double y, int size) {
            g.setStroke(new BasicStroke(1.6f));
            double d = size + 2;
            g.draw(new Ellipse2D.Double(x - d / 2, y - d / 2, d, d));
        }
    }
}
