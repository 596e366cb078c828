package org.parpe.gui.app;

import org.eclipse.jface.resource.JFaceResources;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Listener;
import org.eclipse.swt.widgets.Spinner;
import org.eclipse.swt.widgets.Text;
import org.parpe.gui.panels.ChartView;
import org.parpe.gui.panels.Zoom;
import org.parpe.gui.text.UiMsg;

/**
 * The window's keys, wherever the focus is in it (a filter on the display): Esc stops everything;
 * Ctrl + / Ctrl − / Ctrl 0 zoom; during a run the keys bound to controls steer the robot, the
 * script editor and the gait table included (a steering key never edits the script), except in a
 * box that takes a typed value; the status bar says so. UI thread only.
 */
final class WindowKeys implements Listener {
    private final IdeWindow ide;
    private int zoom;

    WindowKeys(IdeWindow ide) {
        this.ide = ide;
    }

    @Override
    public void handleEvent(Event e) {
        if (ide.shell.isDisposed()) {
            return;
        }
        RunActions runs = ide.runs;
        if (e.keyCode == SWT.ESC) {
            if (runs.running()) {
                runs.emergencyStop();
            }
            return;
        }
        Control focus = e.display.getFocusControl();
        boolean mine = focus != null && focus.getShell() == ide.shell;
        if ((e.stateMask & SWT.MOD1) != 0 && mine && !ide.tutorialDock.holds(focus) && zoomKey(e)) {
            // the docked tutorial zooms its lesson itself
            e.doit = false;
            e.type = SWT.None;
            return;
        }
        if (!mine || !runs.running() || (e.stateMask & SWT.MODIFIER_MASK) != 0) {
            return;
        }
        boolean valueBox = (focus instanceof Text || focus instanceof Combo || focus instanceof Spinner) && !ide.grid.hasFocus();
        if (!valueBox && ide.controls.key(e)) {
            // Neither the editor's nor the table's key handling sees it: the text stays as it was.
            e.doit = false;
            e.type = SWT.None;
        }
    }

    /** Ctrl + / Ctrl − / Ctrl 0 ({@link #zoom(int)}). */
    private boolean zoomKey(Event e) {
        int step = Zoom.step(e);
        if (step == Zoom.NONE) {
            return false;
        }
        zoom(step);
        return true;
    }

    /**
     * Larger ({@code step} 1), smaller (−1) or normal (0) text in every view that zooms: the
     * editor, the log, the gait table, the plots and the diagram (a projector). View → Zoom In /
     * Zoom Out / Reset Zoom and their keys come here.
     */
    void zoom(int step) {
        zoom = Zoom.next(zoom, step);
        Zoom.apply(ide.editor.widget(), JFaceResources.getTextFont(), zoom);
        Zoom.apply(ide.runLog(), JFaceResources.getTextFont(), zoom);
        ide.grid.zoom(zoom);
        ChartView.zoomAll(zoom);
        ide.diagram.zoom(zoom);
        ide.robotTab.zoom(zoom);
        ide.status.setMessage(zoom == 0 ? UiMsg.ZOOM_NORMAL.text() : UiMsg.ZOOM_POINTS.text((zoom > 0 ? "+" : "") + zoom * 2));
    }

    /** How many steps of 2 points the text is zoomed in (negative: out). */
    int zoom() {
        return zoom;
    }
}
