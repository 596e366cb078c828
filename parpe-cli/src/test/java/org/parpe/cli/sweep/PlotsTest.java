package org.parpe.cli.sweep;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.parpe.core.text.Message;
import org.parpe.cli.plot.PngCharts;
import org.parpe.core.plot.PlotStyle;
import org.parpe.sim.sweep.Axis;
import org.parpe.sim.sweep.Evaluation;
import org.parpe.sim.sweep.Objective;
import org.parpe.sim.sweep.OptimizationResult;
import org.parpe.sim.sweep.Point;
import org.parpe.sim.sweep.SweepRow;

/** The sweep PNG drawn by XChart keeps fallen runs apart (red rings) and never on the best line (issue 23 item 1). */
class PlotsTest {

    private static SweepRow row(int i, double bend, double speed, boolean fell) {
        return new SweepRow(new Point(i, i, 0, Map.of("bend", bend), 1), 30, 1, 1, speed, speed, fell ? 97 : 5, 10,
                fell, Message.EMPTY);
    }

    @Test
    void fallenRunsAreRedRingsAndNeverOnTheBestLine() {
        List<SweepRow> rows = new ArrayList<>();
        rows.add(row(0, 10, 0.10, false));
        rows.add(row(1, 10, 0.05, false));
        rows.add(row(2, 20, 0.30, true));
        rows.add(row(3, 20, 0.20, false));
        List<XYChart> panels = Plots.sweepPanels("t", List.of(Axis.list("bend", List.of(10.0, 20.0))), rows,
                Objective.byId("forward-speed"), false);
        XYChart c = panels.get(0);
        XYSeries fell = c.getSeriesMap().get(Plots.FELL_NEVER_BEST.text());
        assertNotNull(fell, c.getSeriesMap().keySet().toString());
        assertInstanceOf(PngCharts.Ring.class, fell.getMarker());
        assertEquals(new Color(PlotStyle.FELL), fell.getMarkerColor());
        XYSeries best = c.getSeriesMap().get(Plots.BEST.text());
        assertArrayEquals(new double[] {0.10, 0.20}, best.getYData(), 1e-12, "the fallen 0.30 is not the best at 20");
        assertEquals("bend", c.getXAxisTitle());
    }

    /**
     * Issue 31 item 3.3: the entries of a legend ran into each other. XChart 3.8.8 lays out a
     * horizontal legend by moving on from a dot's entry by a box's width (20 px) where it drew a
     * line's (24 px), so "each run" touched the next entry's line; one entry a row cannot touch.
     */
    @Test
    void theLegendsOfTheSweepAndConvergencePlotsHaveOneEntryARow() {
        List<SweepRow> rows = List.of(row(0, 10, 0.10, false), row(1, 20, 0.30, true), row(2, 20, 0.20, false));
        List<XYChart> charts = new ArrayList<>(Plots.sweepPanels("t", List.of(Axis.list("bend", List.of(10.0, 20.0))),
                rows, Objective.byId("forward-speed"), false));
        List<Evaluation> evaluations = new ArrayList<>();
        for (SweepRow r : rows) {
            evaluations.add(new Evaluation(0, evaluations.size(), r, r.forwardSpeed(), !r.fell()));
        }
        charts.add(Plots.convergencePanel("t", new OptimizationResult(Objective.byId("forward-speed"),
                List.of(evaluations), false)));
        for (XYChart c : charts) {
            assertTrue(c.getSeriesMap().size() >= 2, c.getSeriesMap().keySet().toString());
            assertEquals(Styler.LegendLayout.Vertical, c.getStyler().getLegendLayout(), c.getTitle());
            assertEquals(Styler.LegendPosition.OutsideS, c.getStyler().getLegendPosition(), "below: the plots keep one width");
        }
    }

    @Test
    void countFallenPutsThemOnTheLine() {
        List<SweepRow> rows = List.of(row(0, 20, 0.30, true), row(1, 20, 0.20, false));
        XYChart c = Plots.sweepPanels("t", List.of(Axis.list("bend", List.of(20.0))), rows,
                Objective.byId("forward-speed"), true).get(0);
        assertArrayEquals(new double[] {0.30}, c.getSeriesMap().get(Plots.BEST.text()).getYData(), 1e-12);
        assertNotNull(c.getSeriesMap().get(Plots.FELL.text()));
    }
}
