package org.parpe.gui.app;

import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.SashForm;
import org.eclipse.swt.widgets.Control;

/** Panes of a sash that grow back to their minimum size. UI thread only. */
final class SashMinimum {
    private SashMinimum() {
    }

    /**
     * Keeps every pane of {@code sash} at least {@code minimum[i]} pixels wide (or high) when the
     * window or a neighbour shrinks it, as far as the sash's size allows: a pane dragged or squeezed
     * to a sliver (the outline's numbers, the 3D view's tools at 1366 pixels) grows back.
     */
    static void keepMinimum(SashForm sash, int... minimum) {
        sash.addListener(SWT.Resize, e -> sash.getDisplay().asyncExec(() -> enforce(sash, minimum)));
        for (Control c : sash.getChildren()) {
            if (!(c instanceof org.eclipse.swt.widgets.Sash)) {
                c.addListener(SWT.Resize, e -> sash.getDisplay().asyncExec(() -> enforce(sash, minimum)));
            }
        }
    }

    private static void enforce(SashForm sash, int[] minimum) {
        if (sash.isDisposed() || sash.getMaximizedControl() != null) {
            return;
        }
        boolean horizontal = (sash.getOrientation() & SWT.HORIZONTAL) != 0;
        int total = horizontal ? sash.getClientArea().width : sash.getClientArea().height;
        int[] out = grown(sash.getWeights(), total, minimum);
        if (out != null) {
            sash.setWeights(out);
        }
    }

    /**
     * New weights for panes of weights {@code w} sharing {@code total} pixels so that each is at
     * least {@code minimum[i]}, taking what the small ones lack from the others in proportion to
     * what they have beyond their minimum; null when nothing needs to change (or cannot).
     */
    static int[] grown(int[] w, int total, int[] minimum) {
        if (w.length != minimum.length) {
            return null;
        }
        int need = java.util.Arrays.stream(minimum).sum();
        long sum = java.util.Arrays.stream(w).asLongStream().sum();
        if (total <= 0 || sum <= 0 || need > total) {
            return null;
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
            return null;
        }
        // Take what the small panes lack from the others, in proportion to what they have beyond their minimum.
        int[] out = new int[w.length];
        for (int i = 0; i < w.length; i++) {
            int beyond = px[i] - minimum[i];
            out[i] = Math.max(Math.max(1, minimum[i]), beyond > 0 ? px[i] - (int) ((long) short_ * beyond / spare) : px[i]);
        }
        // Weights that add up to the pixels, so that the next look finds each pane where it was put
        // (rounding left them a pixel over, and each resize corrected them again).
        int over = java.util.Arrays.stream(out).sum() - total;
        while (over != 0) {
            int k = 0;
            for (int i = 1; i < out.length; i++) {
                if (out[i] - minimum[i] > out[k] - minimum[k]) {
                    k = i;
                }
            }
            int step = over > 0 ? Math.min(over, out[k] - minimum[k]) : over;
            out[k] -= step;
            over -= step;
        }
        return java.util.Arrays.equals(out, w) ? null : out;
    }
}
