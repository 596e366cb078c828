package org.parpe.gui.app;

import org.parpe.gui.text.UiMsg;
import java.util.function.Function;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.CTabFolder;
import org.eclipse.swt.custom.CTabItem;
import org.eclipse.swt.custom.SashForm;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Shell;
import org.parpe.gui.help.TutorialWindow;

/**
 * The tutorial docked in the IDE: a tab beside Outline, whose column widens while the tutorial is
 * in front, so that the lesson, the editor and the 3D view / Diagram are all in sight. Used where
 * the screen has no room for the tutorial's own window beside the IDE (a 1366×768 laptop, or a
 * maximised IDE): a window there covered the 3D view and the Diagram.
 */
final class TutorialDock {
    /** The narrowest tutorial window that is still readable beside the IDE, pixels. */
    static final int WINDOW_MIN = 480;
    /** Outline | editor | 3D view with the tutorial in front, and without. */
    private static final int[] WITH = {38, 34, 28};
    private static final int[] WITHOUT = {15, 43, 42};

    private final CTabFolder folder;
    private final SashForm main;
    private CTabItem tab;
    private TutorialWindow tutorial;

    TutorialDock(CTabFolder folder, SashForm main) {
        this.folder = folder;
        this.main = main;
        folder.addListener(SWT.Selection, e -> fit());
    }

    /** Whether the screen has no room for the tutorial's window beside {@code ide}: it is docked. */
    static boolean wanted(Shell ide) {
        Rectangle screen = ide.getMonitor().getClientArea();
        Rectangle window = ide.getBounds();
        int room = Math.max(screen.x + screen.width - (window.x + window.width), window.x - screen.x);
        return ide.getMaximized() || room < WINDOW_MIN;
    }

    /** Shows the docked tutorial, made by {@code make} in the tab the first time; returns it. */
    TutorialWindow open(Function<Composite, TutorialWindow> make) {
        if (tab == null || tab.isDisposed()) {
            tab = new CTabItem(folder, SWT.CLOSE);
            tab.setText(UiMsg.TAB_TUTORIAL.text());
            tutorial = make.apply(folder);
            tab.setControl(tutorial.control());
            tab.addListener(SWT.Dispose, e -> {
                tutorial.control().dispose();
                if (!main.isDisposed()) {
                    main.setWeights(WITHOUT);
                }
            });
            tutorial.open();
        }
        folder.setSelection(tab);
        fit();
        return tutorial;
    }

    /** The docked tutorial, or null when none is open. */
    TutorialWindow tutorial() {
        return tab == null || tab.isDisposed() ? null : tutorial;
    }

    /** Whether {@code c} is part of the docked tutorial. */
    boolean holds(org.eclipse.swt.widgets.Control c) {
        TutorialWindow t = tutorial();
        for (; t != null && c != null; c = c.getParent()) {
            if (c == t.control()) {
                return true;
            }
        }
        return false;
    }

    /** Whether the docked tutorial is the tab in front of its column. */
    boolean inFront() {
        return tab != null && !tab.isDisposed() && folder.getSelection() == tab;
    }

    /** The left column is wide while the tutorial is in front, narrow for the outline. */
    private void fit() {
        main.setWeights(inFront() ? WITH : WITHOUT);
    }
}
