package org.parpe.cli.sim;

import org.parpe.cli.text.CliMsg;
import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.List;
import org.knowm.xchart.XYChart;
import org.parpe.cli.plot.PngCharts;
import org.parpe.core.plot.AngleRecorder;
import org.parpe.core.plot.PlotStyle;

/**
 * Draws {@code --plot}: one panel per moving module (at most {@value #MAX_PANELS}), commanded
 * angle dashed and measured angle (the simulator's reading) solid in the module's colour, over
 * the whole run, with time and angle axes and units, by XChart ({@link PngCharts}).
 */
final class PlotWriter {
    /** How many samples of the whole run are kept for the plot (evenly spaced): about one a pixel. */
    static final int SAMPLES = 1000;
    private static final int MAX_PANELS = 8;
    private static final int WIDTH = 1200;
    /** A panel's height: its plot, axis titles and a legend of two rows. */
    private static final int PANEL = 250;

    private final AngleRecorder data;
    private final double[] t;
    private final double[] cmd;
    private final double[] meas;

    PlotWriter(AngleRecorder data) {
        this.data = data;
        t = new double[data.capacity()];
        cmd = new double[data.capacity()];
        meas = new double[data.capacity()];
    }

    void write(OutputStream out) throws IOException {
        PngCharts.write(panels(), out);
    }

    /** The panels, top to bottom. */
    List<XYChart> panels() {
        int[] ids = data.moduleIds();
        List<Integer> shown = chooseModules(ids);
        List<XYChart> panels = new ArrayList<>();
        String title = shown.size() < ids.length ? CliMsg.JOINT_ANGLES_OF.text(shown.size(), ids.length)
                : CliMsg.JOINT_ANGLES.text();
        for (int p = 0; p < shown.size(); p++) {
            int id = ids[shown.get(p)];
            int n = data.copy(id, t, cmd, meas);
            XYChart c = PngCharts.panel(WIDTH, PANEL, (p == 0 ? title + ": " : "") + CliMsg.UNIT_MODULE.text() + " " + id,
                    CliMsg.TIME_S.text(), CliMsg.ANGLE_DEG.text());
            double range = yRange(n);
            c.getStyler().setYAxisMin(-range);
            c.getStyler().setYAxisMax(range);
            c.getStyler().setXAxisMin(0.0);
            c.getStyler().setXAxisMax(n == 0 ? 1 : Math.max(t[n - 1], 0.01));
            int rgb = PlotStyle.series(p);
            // Measured first: the dashed plan is drawn over what the robot did.
            if (anyFinite(meas, n)) {
                PngCharts.angle(c, PlotStyle.MEASURED + " m" + id + " (simulator)", t, meas, n, rgb, false);
            }
            if (anyFinite(cmd, n)) {
                PngCharts.angle(c, PlotStyle.COMMANDED + " m" + id, t, cmd, n, rgb, true);
            }
            panels.add(c);
        }
        return panels;
    }

    /** The modules whose commanded angle changes, in ID order, at most {@value #MAX_PANELS}; else the first ones. */
    private List<Integer> chooseModules(int[] ids) {
        List<Integer> moving = new ArrayList<>();
        for (int m = 0; m < ids.length && moving.size() < MAX_PANELS; m++) {
            int n = data.copy(ids[m], t, cmd, meas);
            double lo = Double.POSITIVE_INFINITY;
            double hi = Double.NEGATIVE_INFINITY;
            for (int s = 0; s < n; s++) {
                lo = Math.min(lo, cmd[s]);
                hi = Math.max(hi, cmd[s]);
            }
            if (hi - lo > 0.5) {
                moving.add(m);
            }
        }
        for (int m = 0; moving.isEmpty() && m < Math.min(MAX_PANELS, ids.length); m++) {
            moving.add(m);
        }
        return moving;
    }

    /** Symmetric angle range covering the copied samples, a multiple of 15°, at least 15°, at most 90°. */
    private double yRange(int n) {
        double max = 0;
        for (int s = 0; s < n; s++) {
            max = Double.isFinite(cmd[s]) ? Math.max(max, Math.abs(cmd[s])) : max;
            max = Double.isFinite(meas[s]) ? Math.max(max, Math.abs(meas[s])) : max;
        }
        return Math.min(90, Math.max(15, Math.ceil(max / 15) * 15));
    }

    private static boolean anyFinite(double[] v, int n) {
        for (int i = 0; i < n; i++) {
            if (Double.isFinite(v[i])) {
                return true;
            }
        }
        return false;
    }
}
