package org.parpe.gui.automation;

import org.parpe.gui.text.UiMsg;
import org.parpe.gui.files.Examples;

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
import org.parpe.sim.snapshot.SimSnapshot;
import org.parpe.sim.Simulator;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RobotConfigs;

/**
 * {@code parpe gui --bench}: measures how long the window takes to come up, how many frames
 * per second the 3D view draws for the 55-module centipede, the Robot tab with a 200-module
 * robot, and how opening a generated 10 MB script goes, and prints {@code name=value} lines. A measurement, not a test: nothing here
 * passes or fails on a timing.
 */
public final class Bench {
    private static final int WARMUP = 40;
    private static final int FRAMES = 200;
    private static final int SECONDS = 3;

    private Bench() {
    }

    /** How the benchmark gets its window: the IDE's, automated, with {@code file} open (null: a new script). */
    @FunctionalInterface
    public interface Windows {
        /** Opens a window with its settings in {@code home}. */
        BenchHost open(Path home, Path file);
    }

    /**
     * Runs the benchmark on a window of {@code windows}; {@code mainStarted} is
     * {@link System#nanoTime()} at the start of main.
     */
    public static int run(Display display, long mainStarted, Windows windows) {
        Path home;
        try {
            home = Files.createTempDirectory("parpe-bench");
        } catch (java.io.IOException e) {
            System.err.println("parpe gui: error: " + UiMsg.BENCH_NO_TEMP.text(e.getMessage()));
            return 2;
        }
        Path example = Examples.folder() == null ? null : Examples.folder().resolve("hello-snake.xml");
        BenchHost ide = windows.open(home, example != null && Files.isRegularFile(example) ? example : null);
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
            System.err.println("parpe gui: error: " + UiMsg.BENCH_NO_CENTIPEDE.text(diags.all()));
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
        ide.fillScreen();
        drain(display);
        print("view_fullscreen_width_px", c.getSize().x);
        print("view_fullscreen_height_px", c.getSize().y);
        print("fps_centipede_fullscreen", fps(display, view));
        LiveDiagramBench.run(display, ide);
        RobotTabBench.run(display, ide, home);
        try {
            openLarge(display, ide, home);
        } catch (java.io.IOException e) {
            System.err.println("parpe gui: error: " + UiMsg.BENCH_NO_LARGE_SCRIPT.text(e.getMessage()));
            return 2;
        }
        ide.close();
        return 0;
    }

    /** A valid script of about {@code chars} characters: a snake wave and many extra states. */
    public static String largeScript(int chars) {
        StringBuilder sb = new StringBuilder(String.join("\n", "<?xml version=\"1.0\" ?>", "<program>",
                "  <robot><structure><group1 elements=\"0,2,4,6\" /></structure></robot>",
                "  <main><simpleWave /></main>",
                "  <behaviors><simpleWave><wave group=\"group1\" phase=\"0.25\" period=\"1\" /></simpleWave></behaviors>",
                "  <automata><wave states=\"up, down\" /></automata>",
                "  <states>", "    <up angles=\"30\" />", "    <down angles=\"-30\" />", ""));
        for (int i = 0; sb.length() < chars; i++) {
            sb.append("    <s").append(i).append(" angles=\"").append(i % 60 - 30).append("\" />  <!-- filler state ")
                    .append(i).append(" -->\n");
        }
        return sb.append("  </states>\n</program>\n").toString();
    }

    /**
     * Opens a generated 10 MB script: time until it is in the editor and until it is validated,
     * the longest time the UI thread handled no event meanwhile, and the heap afterwards.
     */
    private static void openLarge(Display display, BenchHost ide, Path home) throws java.io.IOException {
        Path big = home.resolve("large-10mb.xml");
        Files.writeString(big, largeScript(10 << 20));
        int before = ide.validations();
        long[] last = {System.nanoTime(), 0};
        Runnable[] tick = new Runnable[1];
        tick[0] = () -> {
            long now = System.nanoTime();
            last[1] = Math.max(last[1], now - last[0]);
            last[0] = now;
            display.timerExec(5, tick[0]);
        };
        long t0 = System.nanoTime();
        display.timerExec(5, tick[0]);
        ide.open(big);
        while (ide.reading() && !ide.closed()) {
            step(display);
        }
        long shown = System.nanoTime();
        long limit = shown + 120_000_000_000L;
        while (ide.validations() == before && System.nanoTime() < limit) {
            step(display);
        }
        drain(display);
        display.timerExec(-1, tick[0]);
        print("open_10mb_shown_ms", (shown - t0) / 1e6);
        print("open_10mb_validated_ms", (System.nanoTime() - t0) / 1e6);
        print("open_10mb_longest_ui_stall_ms", last[1] / 1e6);
        System.gc();
        Runtime rt = Runtime.getRuntime();
        print("open_10mb_heap_used_mb", (rt.totalMemory() - rt.freeMemory()) / 1e6);
    }

    private static void step(Display display) {
        if (!display.readAndDispatch()) {
            display.sleep();
        }
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

    static void print(String name, double value) {
        System.out.println(name + "=" + (value == Math.rint(value) ? Long.toString((long) value)
                : String.format(Locale.ROOT, "%.1f", value)));
    }
}
