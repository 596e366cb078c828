package org.parpe.gui.app;

import org.eclipse.jface.resource.JFaceResources;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.CTabFolder;
import org.eclipse.swt.custom.CTabItem;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;


/** Small helpers that give every pane the same framed, titled look. */
final class Panels {
    static final Color SELECTED = org.parpe.gui.panels.Theme.pick(0xDCE6F4, 0x2F4A6E);

    private Panels() {
    }

    /** A tab folder with a border and the selected tab tinted. */
    static CTabFolder folder(Composite parent) {
        CTabFolder f = new CTabFolder(parent, SWT.BORDER | SWT.FLAT);
        f.setSimple(false);
        f.setTabHeight(24);
        f.setSelectionBackground(SELECTED);
        f.setFont(JFaceResources.getDialogFont());
        return f;
    }

    /** Adds a tab holding {@code content} (created by the caller with the folder as parent). */
    static CTabItem tab(CTabFolder folder, String title, Control content) {
        CTabItem it = new CTabItem(folder, SWT.NONE);
        it.setText(title);
        it.setControl(content);
        if (folder.getSelectionIndex() < 0) {
            folder.setSelection(it);
        }
        return it;
    }

    /**
     * Keeps every pane of {@code sash} at least {@code minimum[i]} pixels wide (or high) when the
     * window or a neighbour shrinks it, as far as the sash's size allows: a pane dragged or squeezed
     * to a sliver (the outline's numbers, the 3D view's tools at 1366 pixels) grows back.
     */
    static void keepMinimum(org.eclipse.swt.custom.SashForm sash, int... minimum) {
        sash.addListener(SWT.Resize, e -> sash.getDisplay().asyncExec(() -> enforce(sash, minimum)));
        for (Control c : sash.getChildren()) {
            if (!(c instanceof org.eclipse.swt.widgets.Sash)) {
                c.addListener(SWT.Resize, e -> sash.getDisplay().asyncExec(() -> enforce(sash, minimum)));
            }
        }
    }

    private static void enforce(org.eclipse.swt.custom.SashForm sash, int[] minimum) {
        if (sash.isDisposed() || sash.getMaximizedControl() != null) {
            return;
        }
        int[] w = sash.getWeights();
        if (w.length != minimum.length) {
            return;
        }
        boolean horizontal = (sash.getOrientation() & SWT.HORIZONTAL) != 0;
        int total = horizontal ? sash.getClientArea().width : sash.getClientArea().height;
        int need = java.util.Arrays.stream(minimum).sum();
        long sum = java.util.Arrays.stream(w).asLongStream().sum();
        if (total <= 0 || sum <= 0 || need > total) {
            return;
        }
        int[] px = new int[w.length];
        int short_ = 0;
        int spare = 0;
        for (int i = 0; i < w.length; i++) {
            px[i] = (int) (total * w[i] / sum);
            if (px[i] < minimum[i]) {
                short_ += minimum[i] - px[i];
                px[i] = minimum[i];
            } else {
                spare += px[i] - minimum[i];
            }
        }
        if (short_ == 0 || spare == 0) {
            return;
        }
        // Take what the small panes lack from the others, in proportion to what they have beyond their minimum.
        int[] out = new int[w.length];
        for (int i = 0; i < w.length; i++) {
            int beyond = px[i] - minimum[i];
            out[i] = Math.max(1, beyond > 0 && px[i] > minimum[i] ? px[i] - (int) ((long) short_ * beyond / spare) : px[i]);
        }
        sash.setWeights(out);
    }
}
