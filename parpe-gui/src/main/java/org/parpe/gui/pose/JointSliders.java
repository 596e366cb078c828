package org.parpe.gui.pose;

import java.util.Locale;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.ScrolledComposite;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Scale;
import org.parpe.gui.text.PanelMsg;

/**
 * One slider per module of the group being posed (−90…90°, whole degrees on the slider, the
 * exact angle kept and shown beside it). Moving a slider, or {@link #set} from a drag in the 3D
 * view, reports the new angle to the {@link Listener}. UI thread only.
 */
final class JointSliders {
    /** Told when a joint angle changes. */
    interface Listener {
        void changed(int module, double degrees);
    }

    /** The width of an angle beside its slider ("-90.0°"). */
    private static final int VALUE_WIDTH = 60;
    /** The narrowest a slider is beside its module's name before it goes under it. */
    private static final int SLIDER_AT_LEAST = 100;

    private final ScrolledComposite scroll;
    private final Composite rows;
    private final Listener listener;
    private int[] modules = new int[0];
    private double[] angles = new double[0];
    private Scale[] scales = new Scale[0];
    private Label[] names = new Label[0];
    private Label[] values = new Label[0];
    /** Whether each slider is under its module's name and angle rather than between them. */
    private boolean under;

    JointSliders(Composite parent, Listener listener) {
        this.listener = listener;
        scroll = new ScrolledComposite(parent, SWT.V_SCROLL | SWT.BORDER);
        rows = new Composite(scroll, SWT.NONE);
        rows.setLayout(new GridLayout(3, false));
        scroll.setContent(rows);
        scroll.setExpandHorizontal(true);
        scroll.setExpandVertical(true);
        scroll.addListener(SWT.Resize, e -> arrange(false));
    }

    Control control() {
        return scroll;
    }

    /** Shows a slider per module of {@code ids}, at {@code start} (degrees, same order). */
    void show(int[] ids, double[] start) {
        for (Control c : rows.getChildren()) {
            c.dispose();
        }
        modules = ids.clone();
        angles = start.clone();
        scales = new Scale[ids.length];
        names = new Label[ids.length];
        values = new Label[ids.length];
        for (int k = 0; k < ids.length; k++) {
            Label name = new Label(rows, SWT.NONE);
            name.setText(PanelMsg.POSE_MODULE.text(ids[k]));
            name.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, false, false));
            Scale s = new Scale(rows, SWT.HORIZONTAL);
            s.setMinimum(0);
            s.setMaximum(180);
            s.setPageIncrement(10);
            s.setIncrement(1);
            s.setToolTipText(PanelMsg.POSE_JOINT_TIP.text(ids[k]));
            s.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
            int pos = k;
            s.addListener(SWT.Selection, e -> moved(pos));
            Label v = new Label(rows, SWT.RIGHT);
            v.setLayoutData(new GridData(VALUE_WIDTH, SWT.DEFAULT));
            scales[k] = s;
            names[k] = name;
            values[k] = v;
            display(k);
        }
        under = false;
        arrange(true);
    }

    /**
     * Each slider between its module's name and angle where the pane leaves it {@link #SLIDER_AT_LEAST}
     * pixels, else under them across the pane (a narrow pane, a long language: a slider squeezed to its
     * knob cannot be used). Scrolls up and down only: sideways the sliders shrink to the pane, so names
     * and values stay in sight.
     */
    private void arrange(boolean again) {
        int width = scroll.getClientArea().width;
        GridLayout gl = (GridLayout) rows.getLayout();
        int name = 0;
        for (Label l : names) {
            name = Math.max(name, l.computeSize(SWT.DEFAULT, SWT.DEFAULT).x);
        }
        boolean narrow = width > 0 && name + VALUE_WIDTH + SLIDER_AT_LEAST + 2 * (gl.horizontalSpacing + gl.marginWidth) > width;
        if (narrow != under || again) {
            under = narrow;
            gl.numColumns = narrow ? 2 : 3;
            for (int k = 0; k < scales.length; k++) {
                if (narrow) {
                    scales[k].moveBelow(values[k]);
                } else {
                    scales[k].moveAbove(values[k]);
                }
                ((GridData) scales[k].getLayoutData()).horizontalSpan = narrow ? 2 : 1;
                ((GridData) names[k].getLayoutData()).grabExcessHorizontalSpace = narrow;
            }
            rows.layout(true);
        }
        scroll.setMinHeight(rows.computeSize(width > 0 ? width : SWT.DEFAULT, SWT.DEFAULT).y);
    }

    private void moved(int k) {
        angles[k] = scales[k].getSelection() - 90;
        display(k);
        listener.changed(modules[k], angles[k]);
    }

    private void display(int k) {
        scales[k].setSelection((int) Math.round(angles[k]) + 90);
        values[k].setText(String.format(Locale.ROOT, "%.1f\u00b0", angles[k]));
    }

    /** The position of module {@code id} in the group, or −1. */
    int indexOf(int id) {
        for (int k = 0; k < modules.length; k++) {
            if (modules[k] == id) {
                return k;
            }
        }
        return -1;
    }

    /** Sets module {@code id}'s angle (clamped to −90…90°) and reports it; false if it has no slider. */
    boolean set(int id, double degrees) {
        int k = indexOf(id);
        if (k < 0) {
            return false;
        }
        angles[k] = Math.max(-90, Math.min(90, degrees));
        display(k);
        listener.changed(id, angles[k]);
        return true;
    }

    /** Sets every angle (group order) and reports each. */
    void setAll(double[] degrees) {
        for (int k = 0; k < modules.length && k < degrees.length; k++) {
            set(modules[k], degrees[k]);
        }
    }

    /** The current angles, group order. */
    double[] angles() {
        return angles.clone();
    }

    /** The angle of module {@code id}, or NaN. */
    double angle(int id) {
        int k = indexOf(id);
        return k < 0 ? Double.NaN : angles[k];
    }

    /** The slider of module {@code id} (tests drive it as a user would), or null. */
    Scale scale(int id) {
        int k = indexOf(id);
        return k < 0 ? null : scales[k];
    }
}
