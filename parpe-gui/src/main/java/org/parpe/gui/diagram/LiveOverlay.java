package org.parpe.gui.diagram;

import java.util.ArrayList;
import java.util.List;
import java.util.function.BooleanSupplier;
import org.eclipse.swt.widgets.Control;
import org.parpe.core.diagram.Scene;
import org.parpe.gui.run.LiveStates;
import org.parpe.gui.text.PanelMsg;

/**
 * The live overlay of the Diagram pane: over the ring, the modules in each state and a dot per
 * module as far through its state as it is; over the lanes, the bars driving modules; over the
 * gait diagram, the time and each module's state ({@link GaitOverlay}). Frames come from a run
 * ({@link #follow}) or a trace being scrubbed ({@link LiveBar}); each is marked through the
 * drawing's {@link ShapeIndex}, by the indices the engine publishes. UI thread only.
 */
final class LiveOverlay {
    private static final int INK = 0x222222;
    private static final int DRIVEN = 0x009e73;
    /** How often the live overlay looks for new states: 40 frames per second at most (the engine publishes up to 50). */
    private static final int LIVE_MS = 25;

    private final DiagramPane pane;
    private final SceneCanvas canvas;
    private final LiveBar bar;
    private int[] counts;
    private long tick = -1;
    private String[] labels;
    private double[] progress;
    private String what = PanelMsg.DIAGRAM_LIVE.text();
    private List<Scene.Shape> marks = List.of();
    private GaitOverlay gaitOverlay;

    LiveOverlay(DiagramPane pane, SceneCanvas canvas, LiveBar bar) {
        this.pane = pane;
        this.canvas = canvas;
        this.bar = bar;
    }

    /**
     * Follows runs: while {@code running} holds and the ring, the lanes or the gait diagram are
     * shown, marks them from what the engine thread published in {@code live} (copied out here, on
     * the UI thread; the engine never waits for the view).
     */
    void follow(LiveStates live, BooleanSupplier running) {
        Control box = pane.control();
        box.getDisplay().timerExec(LIVE_MS, new Runnable() {
            private long seen = -1;
            private Projection drawn;

            @Override
            public void run() {
                long started = System.nanoTime();
                if (box.isDisposed()) {
                    return;
                }
                Projection shown = pane.shown();
                if (drawn != shown) {
                    // a new drawing: show the last frame again (a run paused at a breakpoint publishes no new one)
                    drawn = shown;
                    seen = -1;
                }
                if (bar.scrubbing()) {
                    // the trace's frame is shown, not the run's
                } else if (box.isVisible() && marked(shown) && running.getAsBoolean()) {
                    var frame = live.since(seen);
                    if (frame != null && frame.tick() >= 0) {
                        seen = frame.version();
                        what = PanelMsg.DIAGRAM_LIVE.text();
                        draw(frame);
                    }
                } else if (counts != null) {
                    counts = null;
                    marks = List.of();
                    repaint();
                }
                // every LIVE_MS from the start of this frame, not after it
                box.getDisplay().timerExec((int) Math.max(1, LIVE_MS - (System.nanoTime() - started) / 1_000_000), this);
            }
        });
    }

    /** Whether {@code p} has a drawing the overlay marks. */
    private static boolean marked(Projection p) {
        return p != null && p.scene() != null && (p.ring() != null || p.lanes() != null || p.gait() != null);
    }

    /** A new drawing is shown: no marks until the next frame. */
    void cleared() {
        marks = List.of();
        counts = null;
        labels = null;
        progress = null;
    }

    /** Shows frame {@code f} as the overlay ({@code word}: "live" or "trace"), or no overlay for {@code null}. */
    void showFrame(LiveStates.Frame f, String word) {
        if (f == null || !marked(pane.shown())) {
            counts = null;
            marks = List.of();
            repaint();
            return;
        }
        what = word;
        draw(f);
    }

    /** Draws the live marks, the breakpoints and the wheel's dragged hand over the drawing. */
    void repaint() {
        List<Scene.Shape> all = new ArrayList<>(marks);
        all.addAll(pane.drags().preview());
        Projection shown = pane.shown();
        if (shown != null && shown.ring() != null && shown.scene() != null) {
            all.addAll(bar.marks(shown.ring(), shown.index()));
        }
        canvas.overlay(all);
    }

    private void draw(LiveStates.Frame f) {
        Projection shown = pane.shown();
        if (shown.lanes() != null) {
            lanes(shown, f);
        } else if (shown.gait() != null) {
            gait(shown, f);
        } else {
            ring(shown, f);
        }
        tick = f.tick();
        repaint();
    }

    /** Marks each arc of the ring with the modules in its state at {@code f}'s tick, and each module's progress. */
    private void ring(Projection shown, LiveStates.Frame f) {
        ShapeIndex index = shown.index();
        int[] in = new int[shown.ring().arcs().size()];
        for (int m = 0; m < f.instance().length; m++) {
            int k = f.state()[m];
            if (index.plays(f.entry(), f.instance()[m]) && k >= 0 && k < in.length) {
                in[k]++;
            }
        }
        counts = in;
        labels = null;
        List<Scene.Shape> out = new ArrayList<>();
        for (int k = 0; k < in.length; k++) {
            Scene.Sector c = index.arc(k);
            if (in[k] > 0 && c != null) {
                out.add(new Scene.Sector(c.cx(), c.cy(), c.r0() - 10, c.r0() - 2, c.from(), c.to(), INK, Scene.NONE, null));
                double[] p = Scene.onCircle(c.cx(), c.cy(), c.r0() - 22, (c.from() + c.to()) / 2);
                out.add(new Scene.Text(p[0], p[1] + 4, Integer.toString(in[k]), 12, 0, INK, true));
            }
        }
        progress = new double[f.instance().length];
        out.addAll(RingProgress.marks(index, f, progress));
        // under the ring's title, not beside it, and as much lower as the ring's text is larger
        out.add(new Scene.Text(shown.scene().width() - 12, 50 * pane.textScale(),
                PanelMsg.DIAGRAM_TICK_RING.text(what, f.tick()), 11, 1, INK, false));
        marks = out;
    }

    /** Marks each bar of the lanes with the modules it drives at {@code f}'s tick. */
    private void lanes(Projection shown, LiveStates.Frame f) {
        var lanes = shown.lanes();
        ShapeIndex index = shown.index();
        int[] driven = new int[index.bars()];
        if (f.entry() == lanes.entry()) {
            for (int m = 0; m < f.instance().length; m++) {
                int i = f.instance()[m];
                if (i >= 0 && i < driven.length) {
                    driven[i]++;
                }
            }
        }
        counts = driven;
        labels = null;
        progress = null;
        List<Scene.Shape> out = new ArrayList<>();
        for (int i = 0; i < driven.length; i++) {
            Scene.Rect r = index.bar(i);
            if (driven[i] > 0 && r != null) {
                out.add(new Scene.Rect(r.x() - 3, r.y() - 3, r.w() + 6, r.h() + 6, Scene.NONE, DRIVEN, 3, null));
                out.add(new Scene.Text(r.x() + r.w() - 8, r.y() + 14, PanelMsg.DIAGRAM_DRIVEN_NOW.text(driven[i]), 11, 1,
                        DRIVEN, true));
            }
        }
        out.add(new Scene.Text(shown.scene().width() - 12, 28, (f.entry() == lanes.entry()
                ? PanelMsg.DIAGRAM_TICK_LANES : PanelMsg.DIAGRAM_TICK_OTHER_ENTRY).text(what, f.tick()), 11, 1, INK, false));
        marks = out;
    }

    /** Marks the gait diagram with the time of {@code f} and each module's state then. */
    private void gait(Projection shown, LiveStates.Frame f) {
        if (gaitOverlay == null || gaitOverlay.gait() != shown.gait()) {
            gaitOverlay = new GaitOverlay(shown.gait(), shown.index());
        }
        marks = gaitOverlay.marks(f, what);
        counts = gaitOverlay.counts();
        labels = gaitOverlay.labels();
        progress = null;
    }

    /** Modules per state of the ring, per bar of the lanes or per colour of the gait diagram; {@code null} without an overlay. */
    int[] counts() {
        return counts == null ? null : counts.clone();
    }

    /** The engine tick of the overlay shown, or −1. */
    long tick() {
        return counts == null ? -1 : tick;
    }

    /** On the ring, per module, how far it is through its state as its dot shows it (−1: not on this ring); else {@code null}. */
    double[] progress() {
        return counts == null || progress == null ? null : progress.clone();
    }

    /** The shapes drawn over the drawing now: the marks, the breakpoints, a dragged hand. */
    List<Scene.Shape> overlaid() {
        return canvas.overlaid();
    }

    /** On the gait diagram, per module, the state its "now" cell shows; else {@code null}. */
    String[] labels() {
        return counts == null || labels == null ? null : labels.clone();
    }
}
