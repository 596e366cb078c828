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

    private final ScrolledComposite scroll;
    private final Composite rows;
    private final Listener listener;
    private int[] modules = new int[0];
    private double[] angles = new double[0];
    private Scale[] scales = new Scale[0];
    private Label[] values = new Label[0];

    JointSliders(Composite parent, Listener listener) {
        this.listener = listener;
        scroll = new ScrolledComposite(parent, SWT.V_SCROLL | SWT.BORDER);
        rows = new Composite(scroll, SWT.NONE);
        rows.setLayout(new GridLayout(3, false));
        scroll.setContent(rows);
        scroll.setExpandHorizontal(true);
        scroll.setExpandVertical(true);
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
        values = new Label[ids.length];
        for (int k = 0; k < ids.length; k++) {
            Label name = new Label(rows, SWT.NONE);
            name.setText(PanelMsg.POSE_MODULE.text(ids[k]));
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
            v.setLayoutData(new GridData(60, SWT.DEFAULT));
            scales[k] = s;
            values[k] = v;
            display(k);
        }
        rows.layout(true);
        // scrolls up and down only: sideways the sliders shrink to the pane, so names and values stay in sight
        scroll.setMinHeight(rows.computeSize(SWT.DEFAULT, SWT.DEFAULT).y);
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
