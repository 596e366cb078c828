package org.parpe.gui.app;

import java.util.ArrayList;
import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.CTabFolder;
import org.eclipse.swt.custom.SashForm;
import org.eclipse.swt.widgets.Control;
import org.parpe.gui.grid.GridPane;

/**
 * How the window shares its width between outline | editor | 3D view, and the right column's
 * height between the views, the controls and the plots: a tab that wants the room (the Diagram,
 * the Robot tab) widens the right column; the gait table beside the text widens the middle one,
 * except while such a tab is shown (it keeps its share, and nothing moves under the mouse when an
 * edit there opens a table) or the docked tutorial is in front (it keeps its column). UI thread only.
 */
final class ColumnWeights {
    private static final int[] NORMAL = {15, 43, 42};
    private static final int[] TABLE = {11, 61, 28};
    private static final int[] WIDE = {10, 38, 52};
    private static final int[] RIGHT = {54, 18, 28};
    private static final int[] RIGHT_WIDE = {84, 4, 12};

    private final CTabFolder viewFolder;
    private final List<Control> wide = new ArrayList<>();

    /** Sets the weights of {@code main} and {@code right} (whose first folder is {@code viewFolder}) and keeps them. */
    ColumnWeights(SashForm main, SashForm right, CTabFolder viewFolder, GridPane grid, TutorialDock dock) {
        this.viewFolder = viewFolder;
        right.setWeights(RIGHT);
        main.setWeights(NORMAL);
        grid.onShown(v -> {
            if (!wideShown() && !dock.inFront()) {
                main.setWeights(v ? TABLE : NORMAL);
            }
        });
        viewFolder.addListener(SWT.Selection, e -> {
            boolean w = wideShown();
            right.setWeights(w ? RIGHT_WIDE : RIGHT);
            if (!dock.inFront()) {
                main.setWeights(w ? WIDE : grid.visible() ? TABLE : NORMAL);
            }
        });
        // Sane minimums at 1366x768: the outline, the editor, the 3D view's tools, Problems and the plots stay usable.
        SashMinimum.keepMinimum(main, 120, 420, 300);
        // the plots: 150 px, what the chart needs to draw its axes and legend (at 100 it was blank beside the Diagram tab)
        SashMinimum.keepMinimum(right, 150, 70, 150);
    }

    /** {@code tab}'s control wants the room while it is in front of the views. */
    void wide(Control tab) {
        wide.add(tab);
    }

    private boolean wideShown() {
        var shown = viewFolder.getSelection() == null ? null : viewFolder.getSelection().getControl();
        return shown != null && wide.contains(shown);
    }
}
