package org.parpe.gui.diagram;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.diagram.GaitDiagram;
import org.parpe.core.diagram.Layouts;
import org.parpe.core.diagram.PhaseWheel;
import org.parpe.core.diagram.Ring;
import org.parpe.core.diagram.Scene;
import org.parpe.core.diagram.Swimlanes;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.MainEntry;
import org.parpe.core.model.Program;

/**
 * The shapes of one laid-out drawing that the live overlay marks, by the indices the engine
 * publishes ({@code <main>} entry, instance, state): made with the drawing, once per layout, so
 * that a frame of the overlay looks its shapes up by index and never matches names, angles or the
 * places shapes stand for. Which instances play the ring's automaton is read from the bound model
 * ({@link org.parpe.core.model.Instance#automaton()}). Immutable; made off the UI thread.
 */
final class ShapeIndex {
    /** A drawing the overlay does not mark. */
    static final ShapeIndex NONE = new ShapeIndex(List.of(), new boolean[0][], new Scene.Rect[0], new int[0][][], null);

    private final List<Scene.Sector> arcs;
    private final boolean[][] plays;
    private final Scene.Rect[] bars;
    private final int[][][] colours;
    private final double[] wheel;

    private ShapeIndex(List<Scene.Sector> arcs, boolean[][] plays, Scene.Rect[] bars, int[][][] colours, double[] wheel) {
        this.arcs = arcs;
        this.plays = plays;
        this.bars = bars;
        this.colours = colours;
        this.wheel = wheel;
    }

    /**
     * The ring of {@code a} in {@code p} at text scale 1: each state's sector as the layout draws
     * it, and per {@code <main>} entry, per instance of its behavior (the engine's numbering),
     * whether it plays {@code a}.
     */
    static ShapeIndex ring(Program p, Automaton a, Ring r) {
        List<MainEntry> entries = p.main() == null ? List.of() : p.main().entries();
        boolean[][] plays = new boolean[entries.size()][];
        for (int e = 0; e < plays.length; e++) {
            var instances = entries.get(e).definition().instances();
            plays[e] = new boolean[instances.size()];
            for (int i = 0; i < plays[e].length; i++) {
                plays[e][i] = instances.get(i).automaton() == a;
            }
        }
        return new ShapeIndex(Layouts.ringArcs(r, 1), plays, new Scene.Rect[0], new int[0][][], null);
    }

    /** The bars of {@code s} as drawn in {@code scene}, by instance index (each bar's own element). */
    static ShapeIndex lanes(Swimlanes s, Scene scene) {
        Map<SourcePos, Integer> barOf = new HashMap<>();
        int n = 0;
        for (Swimlanes.Lane l : s.lanes()) {
            for (Swimlanes.Bar b : l.bars()) {
                barOf.put(b.pos(), b.index());
                n = Math.max(n, b.index() + 1);
            }
        }
        Scene.Rect[] bars = new Scene.Rect[n];
        // the lanes stand each bar for its instance's own element, which no other shape stands for
        for (Scene.Shape shape : scene.shapes()) {
            Integer i = shape instanceof Scene.Rect r && r.source() != null ? barOf.get(r.source()) : null;
            if (i != null && bars[i] == null) {
                bars[i] = (Scene.Rect) shape;
            }
        }
        return new ShapeIndex(List.of(), new boolean[0][], bars, new int[0][][], null);
    }

    /** The gait diagram {@code g}: each entry's instance's state's colour as the layout colours it. */
    static ShapeIndex gait(GaitDiagram g) {
        return new ShapeIndex(List.of(), new boolean[0][], new Scene.Rect[0], Layouts.stateColours(g), null);
    }

    /** The phase wheel at text scale 1. */
    static ShapeIndex wheel() {
        return new ShapeIndex(List.of(), new boolean[0][], new Scene.Rect[0], new int[0][][], Layouts.wheelCircle(1));
    }

    /** This index for the ring {@code r} or the wheel {@code w} laid out again at {@code textScale}. */
    ShapeIndex laidOut(Ring r, PhaseWheel w, double textScale) {
        return new ShapeIndex(r == null ? arcs : Layouts.ringArcs(r, textScale), plays, bars, colours,
                w == null ? wheel : Layouts.wheelCircle(textScale));
    }

    /** The sector of the ring's state {@code k}, or {@code null}. */
    Scene.Sector arc(int k) {
        return k >= 0 && k < arcs.size() ? arcs.get(k) : null;
    }

    /** Whether instance {@code i} of entry {@code e}'s behavior plays the ring's automaton. */
    boolean plays(int e, int i) {
        return e >= 0 && e < plays.length && i >= 0 && i < plays[e].length && plays[e][i];
    }

    /** How many bars the lanes have (instances of the behavior). */
    int bars() {
        return bars.length;
    }

    /** The bar of instance {@code i} of the lanes, or {@code null}. */
    Scene.Rect bar(int i) {
        return i >= 0 && i < bars.length ? bars[i] : null;
    }

    /** The gait diagram's colour index of state {@code k} of instance {@code i} of entry {@code e}, or −1. */
    int colour(int e, int i, int k) {
        return e >= 0 && e < colours.length && i >= 0 && i < colours[e].length && k >= 0 && k < colours[e][i].length
                ? colours[e][i][k] : -1;
    }

    /** The phase wheel's circle ({@code cx, cy, r}, scene units), or {@code null} without a wheel. */
    double[] wheelCircle() {
        return wheel == null ? null : wheel.clone();
    }
}
