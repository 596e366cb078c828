package org.parpe.gui.automation;

import org.parpe.gui.text.UiMsg;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import org.eclipse.swt.widgets.Display;
import org.parpe.core.run.JointSink;
import org.parpe.gui.diagram.DiagramPane;
import org.parpe.gui.files.Examples;
import org.parpe.gui.run.Speed;

/**
 * The live diagram part of {@code parpe gui --bench}: the centipede walk
 * ({@code examples/centipede-walk.xml}) runs in the simulator at real time for a few seconds with
 * the Diagram tab showing the program lane (no overlay), then the ring, the lanes and the gait
 * diagram (with the live overlay); for each, the overlay's new frames per second and the paints
 * of the drawing per second on the UI thread, and the lateness of the run's ticks on the engine
 * thread (wall clock at each tick less its due time, from the earliest schedule of the ticks
 * before); then the time one overlay frame takes on the UI thread (marks made, canvas painted),
 * whose inverse is the frame rate the overlay could reach. A measurement, not a test.
 */
final class LiveDiagramBench {
    private static final double SECONDS = 4;

    private LiveDiagramBench() {
    }

    static void run(Display display, BenchHost ide) {
        Path script = Examples.folder() == null ? null : Examples.folder().resolve("centipede-walk.xml");
        if (script == null || !Files.isRegularFile(script)) {
            System.err.println("parpe gui: warning: " + UiMsg.BENCH_NO_CENTIPEDE_WALK.text());
            return;
        }
        ide.open(script);
        while (ide.reading()) {
            step(display);
        }
        DiagramPane pane = ide.diagram();
        pane.showTab();
        measure(display, ide, pane, "program", "PROGRAM");
        measure(display, ide, pane, "ring", "RING");
        measure(display, ide, pane, "lanes", "LANES");
        measure(display, ide, pane, "gait", "GAIT");
    }

    private static void measure(Display display, BenchHost ide, DiagramPane pane, String name, String view) {
        pane.showView(view);
        long until = System.nanoTime() + 30_000_000_000L;
        while ((!pane.current() || !pane.viewShown().equals(view)) && System.nanoTime() < until) {
            step(display);
        }
        int ticks = (int) Math.round(SECONDS / 0.01) + 1;
        long[] at = new long[ticks];
        ide.observeRuns((JointSink) (tick, time, commanded) -> {
            if (tick < ticks) {
                at[(int) tick] = System.nanoTime();
            }
        });
        boolean[] done = {false};
        ide.runInSimulator(Speed.REAL_TIME, SECONDS, o -> done[0] = true);
        // from the first tick on
        while (at[0] == 0 && !done[0]) {
            step(display);
        }
        long t0 = System.nanoTime();
        long paints0 = pane.paints();
        long frames = 0;
        long lastTick = pane.liveTick();
        while (!done[0]) {
            if (!display.readAndDispatch()) {
                display.sleep();
            }
            if (pane.liveTick() != lastTick) {
                lastTick = pane.liveTick();
                frames++;
            }
        }
        double s = (System.nanoTime() - t0) / 1e9;
        ide.observeRuns(null);
        double[] late = lateness(at);
        int n = late.length;
        print("live_" + name + "_overlay_frames_per_s", frames / s);
        print("live_" + name + "_paints_per_s", (pane.paints() - paints0) / s);
        if (!name.equals("program")) {
            frameCost(ide, pane, name);
        }
        if (n > 0) {
            print("live_" + name + "_tick_late_ms_p50", late[n / 2]);
            print("live_" + name + "_tick_late_ms_p99", late[n * 99 / 100]);
            print("live_" + name + "_tick_late_ms_max", late[n - 1]);
        }
    }

    /**
     * How late each tick after the first came (ms, sorted), against the earliest schedule seen so
     * far: the pacer starts again from where the run is after a lag of more than 0.25 s
     * (WallClockPacer), as the start of the simulator causes.
     */
    private static double[] lateness(long[] at) {
        double[] late = new double[at.length - 1];
        int n = 0;
        double anchor = Double.POSITIVE_INFINITY;
        for (int k = 0; k < at.length; k++) {
            if (at[k] != 0) {
                double due = at[k] / 1e6 - k * 10.0;
                anchor = Math.min(anchor, due);
                if (k > 0) {
                    late[n++] = due - anchor;
                }
            }
        }
        late = Arrays.copyOf(late, n);
        Arrays.sort(late);
        return late;
    }

    /** The UI thread's cost of one overlay frame: marks made and the canvas painted. */
    private static void frameCost(BenchHost ide, DiagramPane pane, String name) {
        var last = ide.live().since(-1);
        if (last == null || last.tick() < 0) {
            return;
        }
        for (int i = 0; i < 20; i++) {
            pane.drawFrame(last);
        }
        long f0 = System.nanoTime();
        for (int i = 0; i < 60; i++) {
            pane.drawFrame(last);
        }
        print("live_" + name + "_overlay_frame_ms", (System.nanoTime() - f0) / 1e6 / 60);
    }

    private static void step(Display display) {
        if (!display.readAndDispatch()) {
            display.sleep();
        }
    }

    private static void print(String name, double value) {
        System.out.println(name + "=" + String.format(Locale.ROOT, "%.2f", value));
    }
}
