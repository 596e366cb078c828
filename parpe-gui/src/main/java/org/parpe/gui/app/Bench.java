package org.parpe.gui.app;

import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.widgets.Canvas;
import org.eclipse.swt.widgets.Display;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.gui.view3d.View3D;
import org.parpe.sim.SimSnapshot;
import org.parpe.sim.Simulator;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RobotConfigs;

/**
 * {@code parpe gui --bench}: measures how long the window takes to come up and how many frames
 * per second the 3D view draws for the 55-module centipede, and prints {@code name=value}
 * lines. A measurement, not a test: nothing here passes or fails on a timing.
 */
public final class Bench {
    private static final int WARMUP = 40;
    private static final int FRAMES = 200;
    private static final int SECONDS = 3;

    private Bench() {
    }

    /** Runs the benchmark; {@code mainStarted} is {@link System#nanoTime()} at the start of main. */
    public static int run(Display display, long mainStarted) {
        Path home;
        try {
            home = Files.createTempDirectory("parpe-bench");
        } catch (java.io.IOException e) {
            System.err.println("parpe gui: error: cannot create a temporary folder: " + e.getMessage());
            return 2;
        }
        IdeWindow ide = new IdeWindow(display, new Prefs(home));
        Path example = Examples.folder() == null ? null : Examples.folder().resolve("hello-snake.xml");
        ide.open(example != null && Files.isRegularFile(example) ? example : null, true);
        while (display.readAndDispatch()) {
            // The first paint of every widget.
        }
        display.update();
        long jvmStart = ManagementFactory.getRuntimeMXBean().getStartTime();
        print("window_up_ms", System.currentTimeMillis() - jvmStart);
        print("window_up_from_main_ms", (System.nanoTime() - mainStarted) / 1e6);

        DiagnosticList diags = new DiagnosticList();
        RobotConfig config = RobotConfigs.resolve("centipede", new int[0], diags);
        if (config == null) {
            System.err.println("parpe gui: error: cannot build the centipede: " + diags.all());
            return 1;
        }
        SimSnapshot snap;
        try (Simulator sim = new Simulator(config)) {
            sim.step(50);
            snap = sim.snapshot();
        }
        View3D view = ide.view();
        view.stopAnimation();
        view.setSource(() -> snap);
        print("centipede_modules", config.moduleIds().length);
        print("centipede_bodies", snap.bodies().size());
        Canvas c = view.control();
        print("view_width_px", c.getSize().x);
        print("view_height_px", c.getSize().y);
        print("fps_centipede", fps(display, view));
        print("render_ms_centipede", renderMs(display, view, c.getSize().x, c.getSize().y));
        view.setShowIds(true);
        print("fps_centipede_with_ids", fps(display, view));
        print("render_ms_centipede_with_ids", renderMs(display, view, c.getSize().x, c.getSize().y));
        ide.shell().setBounds(display.getPrimaryMonitor().getClientArea());
        drain(display);
        print("view_fullscreen_width_px", c.getSize().x);
        print("view_fullscreen_height_px", c.getSize().y);
        print("fps_centipede_fullscreen", fps(display, view));
        ide.shell().dispose();
        return 0;
    }

    /** Frames actually painted on screen per second when the view asks for a new frame as soon as the last is done. */
    private static double fps(Display display, View3D view) {
        Canvas c = view.control();
        long end = System.nanoTime() + 1_000_000_000L;
        paintUntil(display, view, c, end);
        long f0 = view.frames();
        long t0 = System.nanoTime();
        paintUntil(display, view, c, t0 + SECONDS * 1_000_000_000L);
        return (view.frames() - f0) / ((System.nanoTime() - t0) / 1e9);
    }

    private static void paintUntil(Display display, View3D view, Canvas c, long end) {
        while (System.nanoTime() < end) {
            long before = view.frames();
            c.redraw();
            while (view.frames() == before && System.nanoTime() < end) {
                if (!display.readAndDispatch()) {
                    Thread.onSpinWait();
                }
            }
        }
    }

    /** Milliseconds to draw one frame into an off-screen image (the drawing cost alone). */
    private static double renderMs(Display display, View3D view, int w, int h) {
        Image img = new Image(display, w, h);
        GC gc = new GC(img);
        try {
            for (int i = 0; i < WARMUP; i++) {
                view.render(gc, w, h);
            }
            long t0 = System.nanoTime();
            for (int i = 0; i < FRAMES; i++) {
                view.render(gc, w, h);
            }
            return (System.nanoTime() - t0) / 1e6 / FRAMES;
        } finally {
            gc.dispose();
            img.dispose();
        }
    }

    private static void drain(Display display) {
        long until = System.currentTimeMillis() + 200;
        while (System.currentTimeMillis() < until) {
            while (display.readAndDispatch()) {
                // Handle everything pending.
            }
            display.update();
        }
    }

    private static void print(String name, double value) {
        System.out.println(name + "=" + (value == Math.rint(value) ? Long.toString((long) value)
                : String.format(Locale.ROOT, "%.1f", value)));
    }
}
