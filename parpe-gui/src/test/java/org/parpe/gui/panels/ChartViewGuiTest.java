package org.parpe.gui.panels;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.graphics.ImageData;
import org.eclipse.swt.graphics.RGB;
import org.eclipse.swt.layout.FillLayout;
import org.eclipse.swt.widgets.Shell;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.plot.AngleRecorder;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.core.sensor.Channel;
import org.parpe.gui.app.Gui;

/**
 * The IDE's one chart (issue 19 item 6, issue 23 item 7) with real widgets under Xvfb: the live
 * plot draws commanded dashed and measured solid in the module's colour (it drew them the other
 * way round), zoom thickens lines and enlarges text, and the paper is the theme's.
 */
class ChartViewGuiTest {
    private static final String SCRIPT = "<program>\n<robot><structure><g elements=\"0, 1\"/></structure></robot>\n"
            + "<main><b/></main>\n<behaviors><b><w group=\"g\"/></b></behaviors>\n"
            + "<automata><w states=\"s\"/></automata>\n<states>\n<s angles=\"40 * sin(360 * $time)\"/></states>\n</program>\n";

    private Shell shell;

    @AfterEach
    void close() {
        ChartView.zoomAll(0);
        if (shell != null && !shell.isDisposed()) {
            shell.dispose();
        }
    }

    private PlotView plotOfARun() throws Exception {
        shell = new Shell(Gui.display());
        shell.setLayout(new FillLayout());
        shell.setSize(900, 400);
        PlotView view = new PlotView(shell);
        shell.open();
        LoadResult r = ScriptLoader.loadText(Path.of("p.xml"), SCRIPT, Map.of());
        assertTrue(r.ok(), () -> r.diagnostics().toString());
        Run.Builder b = Run.builder(r.program(), RunOptions.defaults(), new DiagnosticList()).duration(3);
        b.sensorSource(org.parpe.core.run.SourceKind.SIMULATOR, (time, table) -> table.set(0, Channel.ANGLE, 10));
        AngleRecorder rec = PlotView.newRecorder().attachTo(b);
        b.build().execute();
        view.setModules(r.program().moduleIds());
        view.setRecorder(rec);
        Gui.pump(() -> !view.chart().drawn().isEmpty(), "the plot to be painted", 10_000);
        return view;
    }

    private static ChartView.Drawn series(ChartView chart, String name) {
        Optional<ChartView.Drawn> d = chart.drawn().stream().filter(s -> s.name().equals(name)).findFirst();
        assertTrue(d.isPresent(), name + " in " + chart.drawn());
        return d.get();
    }

    @Test
    void commandedIsDashedAndMeasuredSolidInTheModulesColour() throws Exception {
        ChartView chart = plotOfARun().chart();
        ChartView.Drawn cmd = series(chart, "m0 commanded");
        ChartView.Drawn meas = series(chart, "m0 measured");
        assertTrue(cmd.dashed(), "commanded is dashed");
        assertTrue(!meas.dashed(), "measured is solid");
        assertEquals(cmd.rgb(), meas.rgb(), "one colour per module");
        assertNotEquals(cmd.rgb(), series(chart, "m1 commanded").rgb(), "modules have their own colours");
    }

    @Test
    void zoomEnlargesTheTextAndThickensTheLines() throws Exception {
        ChartView chart = plotOfARun().chart();
        int points = chart.control().getFont().getFontData()[0].getHeight();
        int width = series(chart, "m0 measured").width();
        ChartView.zoomAll(4);
        Gui.pump(() -> series(chart, "m0 measured").width() > width, "thicker lines after zooming in", 10_000);
        assertEquals(points + 8, chart.control().getFont().getFontData()[0].getHeight());
        ChartView.zoomAll(0);
        Gui.pump(() -> series(chart, "m0 measured").width() == width, "the normal lines after Ctrl+0", 10_000);
        assertEquals(points, chart.control().getFont().getFontData()[0].getHeight());
    }

    @Test
    void thePaperIsTheThemesNotWhite() throws Exception {
        ChartView chart = plotOfARun().chart();
        Gui.settle();
        Image shot = new Image(shell.getDisplay(), chart.control().getSize().x, chart.control().getSize().y);
        GC gc = new GC(chart.control());
        gc.copyArea(shot, 0, 0);
        gc.dispose();
        ImageData data = shot.getImageData();
        RGB corner = data.palette.getRGB(data.getPixel(2, 2));
        shot.dispose();
        assertEquals(Theme.paper().getRGB(), corner, "the chart's background is the theme's text background (dark with a dark theme)");
        assertNotEquals(Theme.ink().getRGB(), corner, "text stands out from the paper");
    }

    /**
     * Issue 38: the chart's message was drawn on one line and ran past the chart's right edge in
     * a narrow pane, at 200 % zoom or in a longer language. Now it wraps at the chart's width.
     */
    @Test
    void aMessageWiderThanTheChartWrapsInsideIt() {
        shell = new Shell(Gui.display());
        shell.setLayout(new FillLayout());
        shell.setSize(240, 300);
        ChartView chart = new ChartView(shell, SWT.NONE);
        shell.open();
        chart.message("Run a script to see joint angles (dashed: commanded, solid: measured)");
        Gui.settle();
        GC gc = new GC(chart.control());
        Image shot = new Image(shell.getDisplay(), chart.control().getSize().x, chart.control().getSize().y);
        int lineH;
        try {
            gc.copyArea(shot, 0, 0);
            lineH = gc.getFontMetrics().getHeight();
        } finally {
            gc.dispose();
        }
        ImageData data = shot.getImageData();
        shot.dispose();
        RGB paper = data.palette.getRGB(data.getPixel(1, 1));
        int lines = 0;
        boolean inLine = false;
        int rightmostInk = 0;
        for (int y = 0; y < data.height; y++) {
            boolean ink = false;
            for (int x = 0; x < data.width; x++) {
                if (!data.palette.getRGB(data.getPixel(x, y)).equals(paper)) {
                    ink = true;
                    rightmostInk = Math.max(rightmostInk, x);
                }
            }
            lines += ink && !inLine ? 1 : 0;
            inLine = ink;
        }
        assertTrue(lines >= 3, "the message wraps onto several lines: " + lines);
        assertTrue(rightmostInk < data.width - lineH / 4, "no text at the chart's right edge: ink at x = " + rightmostInk
                + " of " + data.width);
    }
}
