package org.parpe.gui.sweep;

import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Spinner;
import org.eclipse.swt.widgets.Text;
import org.parpe.core.lang.Numbers;
import org.parpe.gui.text.ToolMsg;
import org.parpe.sim.sweep.Constraints;
import org.parpe.sim.sweep.Objective;
import org.parpe.sim.sweep.OptimizeSpec;
import org.parpe.sim.sweep.SweepException;

/**
 * The Optimise tab: the budget of simulations, the independent searches that share it, the
 * constraints (a largest tilt, not fallen over) and the seed. CMA-ES searches every parameter
 * that has both a {@code min} and a {@code max}; the objective is the dialog's.
 */
final class OptimiseTab {
    private final Composite root;
    private final Spinner budget;
    private final Spinner starts;
    private final Button tiltOn;
    private final Text tilt;
    private final Button notFallen;
    private final Text seed;

    OptimiseTab(Composite parent) {
        root = new Composite(parent, SWT.NONE);
        root.setLayout(new GridLayout(3, false));
        budget = spinner(ToolMsg.SWEEP_BUDGET.text(), 2, 1_000_000, 100, ToolMsg.SWEEP_BUDGET_TIP.text());
        starts = spinner(ToolMsg.SWEEP_STARTS.text(), 1, 64, 4, ToolMsg.SWEEP_STARTS_TIP.text());
        tiltOn = new Button(root, SWT.CHECK);
        tiltOn.setText(ToolMsg.SWEEP_LARGEST_TILT.text());
        tilt = new Text(root, SWT.BORDER);
        tilt.setText("30");
        tilt.setLayoutData(new GridData(70, SWT.DEFAULT));
        note(ToolMsg.SWEEP_TILT_NOTE.text());
        notFallen = new Button(root, SWT.CHECK);
        notFallen.setText(ToolMsg.SWEEP_NOT_FALLEN.text());
        notFallen.setSelection(true);
        notFallen.setLayoutData(new GridData(SWT.LEFT, SWT.CENTER, false, false, 2, 1));
        note(ToolMsg.SWEEP_NOT_FALLEN_NOTE.text(Numbers.format(StartRequest.FALL_TILT)));
        new Label(root, SWT.NONE).setText(ToolMsg.SWEEP_SEED.text());
        seed = new Text(root, SWT.BORDER);
        seed.setText("0");
        seed.setLayoutData(new GridData(70, SWT.DEFAULT));
        note(ToolMsg.SWEEP_SEED_NOTE.text());
        Label what = new Label(root, SWT.WRAP);
        what.setText(ToolMsg.SWEEP_SEARCHED.text());
        what.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 3, 1));
    }

    private Spinner spinner(String label, int min, int max, int value, String tip) {
        new Label(root, SWT.NONE).setText(label);
        Spinner s = new Spinner(root, SWT.BORDER);
        s.setValues(value, min, max, 0, 1, 10);
        s.setToolTipText(tip);
        s.setLayoutData(new GridData(SWT.LEFT, SWT.CENTER, false, false, 2, 1));
        return s;
    }

    private void note(String text) {
        Label l = new Label(root, SWT.NONE);
        l.setText(text);
        l.setForeground(root.getDisplay().getSystemColor(SWT.COLOR_DARK_GRAY));
    }

    Control control() {
        return root;
    }

    /** Sets the budget and the number of searches (tests, automation). */
    void setBudget(int runs, int searches) {
        budget.setSelection(runs);
        starts.setSelection(searches);
    }

    /** The constraints the boxes describe; a bad tilt throws with one line. */
    Constraints constraints() throws SweepException {
        double max = Double.POSITIVE_INFINITY;
        if (tiltOn.getSelection()) {
            Double t = Numbers.parsePlain(tilt.getText());
            if (t == null || !(t >= 0 && t <= 180)) {
                throw new SweepException(ToolMsg.SWEEP_BAD_TILT.text(tilt.getText().trim()));
            }
            max = t;
        }
        return new Constraints(max, notFallen.getSelection());
    }

    /** The optimisation the boxes describe for {@code objective}; bad numbers throw with one line. */
    OptimizeSpec spec(Objective objective) throws SweepException {
        Double s = Numbers.parsePlain(seed.getText());
        if (s == null || s != Math.rint(s) || Math.abs(s) > 1e15) {
            throw new SweepException(ToolMsg.SWEEP_BAD_SEED.text(seed.getText().trim()));
        }
        OptimizeSpec spec = new OptimizeSpec(objective, constraints(), budget.getSelection(), starts.getSelection(),
                s.longValue());
        spec.check();
        return spec;
    }
}
