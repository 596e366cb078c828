package org.parpe.gui.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.eclipse.swt.layout.FillLayout;
import org.eclipse.swt.widgets.Shell;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.parpe.core.text.Message;
import org.parpe.core.plot.PlotStyle;
import org.parpe.gui.app.Gui;
import org.parpe.gui.panels.ChartView;
import org.parpe.sim.sweep.Objective;
import org.parpe.sim.sweep.Point;
import org.parpe.sim.sweep.SweepRow;

/** The sweep's plot in the IDE's one chart and the one style (issue 19 item 6, issue 23 item 1), real widgets under Xvfb. */
class ResultsPlotGuiTest {
    private Shell shell;

    @AfterEach
    void close() {
        if (shell != null && !shell.isDisposed()) {
            shell.dispose();
        }
    }

    private static SweepRow row(int i, double bend, double speed, boolean fell) {
        return new SweepRow(new Point(i, i, 0, Map.of("bend", bend), 1), 30, 1, 1, speed, speed, fell ? 97 : 5, 10,
                fell, Message.EMPTY);
    }

    @Test
    void fallenRunsAreRedRingsApartFromTheGreyDotsAndTheBlueBestLine() {
        shell = new Shell(Gui.display());
        shell.setLayout(new FillLayout());
        shell.setSize(800, 400);
        ResultsPlot plot = new ResultsPlot(shell);
        shell.open();
        Results r = new Results(Path.of("s.xml"), Results.Mode.SWEEP, List.of("bend"), Map.of(), Objective.byId("forward-speed"),
                org.parpe.sim.sweep.Constraints.NONE, 20_000, 3);
        r.add(row(0, 10, 0.1, false));
        r.add(row(1, 20, 0.3, true));
        r.add(row(2, 20, 0.2, false));
        plot.show(r, "bend");
        ChartView chart = plot.chart();
        Gui.pump(() -> !chart.drawn().isEmpty(), "the plot to be painted", 10_000);
        List<ChartView.Drawn> drawn = chart.drawn();
        ChartView.Drawn fell = drawn.stream().filter(d -> d.name().equals(ResultsPlot.FELL.text())).findFirst().orElseThrow();
        assertTrue(fell.points() && fell.hollow(), "rings");
        assertEquals(PlotStyle.FELL, fell.rgb());
        ChartView.Drawn runs = drawn.stream().filter(d -> d.name().equals(ResultsPlot.RUNS.text())).findFirst().orElseThrow();
        assertFalse(runs.hollow());
        assertEquals(PlotStyle.OTHER_RUN, runs.rgb());
        ChartView.Drawn best = drawn.stream().filter(d -> d.name().equals(ResultsPlot.BEST.text())).findFirst().orElseThrow();
        assertFalse(best.points() || best.dashed());
        assertEquals(PlotStyle.BEST, best.rgb());
    }
}
