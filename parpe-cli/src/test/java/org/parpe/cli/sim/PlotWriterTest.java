package org.parpe.cli.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.plot.AngleRecorder;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.core.sensor.Channel;

/**
 * The {@code --plot} PNG in the one style (issue 19 item 6): commanded dashed and measured solid
 * in the module's colour (it was the IDE's opposite), measured being the sensor reading.
 */
class PlotWriterTest {
    private static final String SCRIPT = "<program>\n<robot><structure><g elements=\"0, 1\"/></structure></robot>\n"
            + "<main><b/></main>\n<behaviors><b><w group=\"g\"/></b></behaviors>\n"
            + "<automata><w states=\"s\"/></automata>\n<states>\n<s angles=\"40 * sin(360 * $time)\"/></states>\n</program>\n";

    private static List<XYChart> plot(boolean measured) throws Exception {
        LoadResult r = ScriptLoader.loadText(Path.of("p.xml"), SCRIPT, Map.of());
        assertTrue(r.ok(), () -> r.diagnostics().toString());
        Run.Builder b = Run.builder(r.program(), RunOptions.defaults(), new DiagnosticList()).duration(2);
        if (measured) {
            b.sensorSource(org.parpe.core.run.SourceKind.SIMULATOR, (time, table) -> {
                table.set(0, Channel.ANGLE, 5);
                table.set(1, Channel.ANGLE, -5);
            });
        }
        AngleRecorder rec = AngleRecorder.wholeRun(PlotWriter.SAMPLES).attachTo(b);
        b.build().execute();
        return new PlotWriter(rec).panels();
    }

    @Test
    void commandedIsDashedAndMeasuredSolidInTheModulesColour() throws Exception {
        List<XYChart> panels = plot(true);
        assertEquals(2, panels.size(), "both modules move");
        XYChart first = panels.get(0);
        XYSeries cmd = first.getSeriesMap().get("commanded m0");
        XYSeries meas = first.getSeriesMap().get("measured m0 (simulator)");
        assertNotNull(cmd, first.getSeriesMap().keySet().toString());
        assertNotNull(meas, first.getSeriesMap().keySet().toString());
        assertNotNull(cmd.getLineStyle().getDashArray(), "commanded is dashed");
        assertNull(meas.getLineStyle().getDashArray(), "measured is solid");
        assertEquals(cmd.getLineColor(), meas.getLineColor(), "one colour per module");
        assertEquals(5, meas.getYMax(), 1e-9, "measured is the sensor reading");
        assertEquals(40, cmd.getYMax(), 1.0, "the commanded peak");
        assertEquals("time (s)", first.getXAxisTitle());
        assertEquals("angle (°)", first.getYAxisTitle());
        assertTrue(first.getTitle().startsWith("Joint angles over time"), first.getTitle());
    }

    /** Issue 31 item 3.3: "measured m0 (simulator)" ran into "commanded m0" (see PlotsTest). */
    @Test
    void theLegendHasOneEntryARow() throws Exception {
        for (XYChart c : plot(true)) {
            assertEquals(2, c.getSeriesMap().size());
            assertEquals(Styler.LegendLayout.Vertical, c.getStyler().getLegendLayout(), c.getTitle());
        }
    }

    @Test
    void withoutASensorSourceThereIsNoMeasuredCurve() throws Exception {
        XYChart second = plot(false).get(1);
        assertEquals(List.of("commanded m1"), List.copyOf(second.getSeriesMap().keySet()),
                "the commanded angle echoed back is no measurement");
    }
}
