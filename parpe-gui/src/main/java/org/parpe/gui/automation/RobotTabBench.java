package org.parpe.gui.automation;

import org.parpe.gui.text.UiMsg;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.eclipse.swt.widgets.Canvas;
import org.eclipse.swt.widgets.Display;
import org.parpe.gui.robot.RobotTab;
import org.parpe.sim.build.RobotDraft;

/**
 * The Robot tab part of {@code parpe gui --bench} (issue 33): a 200-module snake made editable
 * and opened, the tab in front; frames painted per second while the view turns round the robot
 * (goal ≥ 30), and the time from an edit in the tab to the end of the next paint (the text
 * edited, re-read, the robot assembled and drawn; goal ≤ 50 ms), after a few edits not timed.
 * A measurement, not a test.
 */
final class RobotTabBench {
    private static final double SECONDS = 3;
    private static final int EDITS = 20;
    /** Edits made first and not timed (the JIT compiles the reader and the drawing). */
    private static final int WARMUP = 10;

    private RobotTabBench() {
    }

    static void run(Display display, BenchHost ide, Path home) {
        Path file = home.resolve("snake200-robot.xml");
        try {
            Files.writeString(file, RobotDraft.fromGenerator(file.toString(), "snake:n=200").text());
        } catch (IOException e) {
            System.err.println("parpe gui: warning: " + UiMsg.BENCH_NO_ROBOT_200.text(e.getMessage()));
            return;
        }
        RobotTab tab = ide.robotTab();
        tab.showTab();
        int before = ide.validations();
        ide.open(file);
        while ((ide.reading() || ide.validations() == before) && !ide.closed()) {
            step(display);
        }
        Canvas c = tab.view().control();
        paint(display, tab, c);
        Bench.print("robot_tab_parts", tab.draft().partNames().size());
        Bench.print("robot_tab_bodies", tab.draft().bodies().size());
        Bench.print("robot_tab_free_plates", tab.draft().freePlates().size());
        long f0 = tab.view().frames();
        long t0 = System.nanoTime();
        while (System.nanoTime() - t0 < SECONDS * 1e9) {
            tab.view().rotate(0.03, 0);
            paint(display, tab, c);
        }
        Bench.print("robot_tab_fps_rotating", (tab.view().frames() - f0) / ((System.nanoTime() - t0) / 1e9));
        String part = tab.draft().partNames().get(tab.draft().partNames().size() / 2);
        double[] ms = new double[EDITS];
        for (int i = -WARMUP; i < EDITS; i++) {
            long e0 = System.nanoTime();
            tab.apply(tab.draft().setAngle(part, i % 2 == 0 ? 15 : 0));
            paint(display, tab, c);
            if (i >= 0) {
                ms[i] = (System.nanoTime() - e0) / 1e6;
            }
        }
        java.util.Arrays.sort(ms);
        Bench.print("robot_tab_edit_redrawn_ms_median", ms[EDITS / 2]);
        Bench.print("robot_tab_edit_redrawn_ms_mean", java.util.Arrays.stream(ms).average().orElse(0));
        Bench.print("robot_tab_edit_redrawn_ms_worst", ms[EDITS - 1]);
    }

    /** Asks for a frame and handles events until it is painted. */
    private static void paint(Display display, RobotTab tab, Canvas c) {
        long before = tab.view().frames();
        c.redraw();
        long limit = System.nanoTime() + 2_000_000_000L;
        while (tab.view().frames() == before && System.nanoTime() < limit) {
            if (!display.readAndDispatch()) {
                Thread.onSpinWait();
            }
        }
    }

    private static void step(Display display) {
        if (!display.readAndDispatch()) {
            display.sleep();
        }
    }
}
