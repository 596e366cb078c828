package org.parpe.gui.diagram;

import java.util.ArrayList;
import java.util.List;
import org.parpe.core.diagram.GaitDiagram;
import org.parpe.core.diagram.Layouts;
import org.parpe.core.diagram.Scene;
import org.parpe.gui.run.LiveStates;
import org.parpe.gui.text.PanelMsg;

/**
 * The live overlay of the gait diagram: a line at the frame's time (while it lies in the time
 * drawn) and, right of the plot, a "now" column with each module's row in the colour of the
 * state it is in at that frame (the colours the layout gave it, {@link ShapeIndex}). Made once per diagram;
 * {@link #marks} is called for each frame on the UI thread.
 */
final class GaitOverlay {
    private static final int INK = 0x222222;

    private final GaitDiagram gait;
    private final ShapeIndex index;
    private final double[] plot;
    private final int colours;
    private String[] labels = new String[0];
    private int[] counts = new int[0];

    /** The overlay of {@code gait}, its states coloured as {@code index} says the layout coloured them. */
    GaitOverlay(GaitDiagram gait, ShapeIndex index) {
        this.gait = gait;
        this.index = index;
        this.plot = Layouts.gaitPlot(gait);
        this.colours = gait.stateNames().size();
    }

    /** The shapes showing frame {@code f} over the diagram; {@link #labels()} and {@link #counts()} describe it. */
    List<Scene.Shape> marks(LiveStates.Frame f, String what) {
        double left = plot[0];
        double top = plot[1];
        double width = plot[2];
        double rowH = plot[3];
        int n = gait.moduleIds().length;
        List<Scene.Shape> marks = new ArrayList<>();
        labels = new String[n];
        counts = new int[colours];
        double column = left + width + 6;
        marks.add(new Scene.Text(column + 7, top - 4, PanelMsg.DIAGRAM_NOW.text(), 10, 0, INK, true));
        for (int m = 0; m < n && m < f.instance().length; m++) {
            labels[m] = gait.stateName(f.entry(), f.instance()[m], f.state()[m]);
            int k = index.colour(f.entry(), f.instance()[m], f.state()[m]);
            if (k >= 0) {
                counts[k]++;
                marks.add(new Scene.Rect(column, top + m * rowH, 14, rowH, Layouts.stateColour(k), Scene.NONE, 0, null));
            }
        }
        marks.add(new Scene.Rect(column, top, 14, n * rowH, Scene.NONE, INK, 1, null));
        String where;
        if (f.tick() < gait.ticks()) {
            double x = left + f.tick() * width / gait.ticks();
            marks.add(new Scene.Line(x, top - 6, x, top + n * rowH + 6, INK, 2, 0));
            where = PanelMsg.DIAGRAM_BLACK_LINE_NOW.text();
        } else {
            where = PanelMsg.DIAGRAM_NOW_AFTER.text();
        }
        marks.add(new Scene.Text(left + width, top - 8, PanelMsg.DIAGRAM_TICK_GAIT.text(what, f.tick(), where),
                11, 1, INK, false));
        return marks;
    }

    /** The diagram it draws over. */
    GaitDiagram gait() {
        return gait;
    }

    /** Per module (row), the name of the state its row shows now, or {@code null}. */
    String[] labels() {
        return labels.clone();
    }

    /** Per state name of the diagram (in its colours' order), the modules in it now. */
    int[] counts() {
        return counts.clone();
    }
}
