package org.parpe.gui.grid;

import org.eclipse.jface.dialogs.Dialog;
import org.eclipse.jface.dialogs.IDialogConstants;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Text;
import org.parpe.gui.text.PanelMsg;

/** Asks for the amplitude and the phase step of a travelling wave; says which cells it will fill. */
final class WaveDialog extends Dialog {
    private final String target;
    private double amplitude;
    private double phaseStep;
    private Text amplitudeText;
    private Text phaseText;
    private Label error;

    WaveDialog(Shell parent, String target, double amplitude, double phaseStep) {
        super(parent);
        this.target = target;
        this.amplitude = amplitude;
        this.phaseStep = phaseStep;
    }

    @Override
    protected void configureShell(Shell shell) {
        super.configureShell(shell);
        shell.setText(PanelMsg.WAVE_TITLE.text());
    }

    @Override
    protected Control createDialogArea(Composite parent) {
        Composite c = (Composite) super.createDialogArea(parent);
        c.setLayout(new GridLayout(2, false));
        Label about = new Label(c, SWT.WRAP);
        about.setText(PanelMsg.WAVE_ABOUT.text(target));
        GridData wide = new GridData(SWT.FILL, SWT.TOP, true, false, 2, 1);
        wide.widthHint = 380;
        about.setLayoutData(wide);
        amplitudeText = field(c, PanelMsg.WAVE_AMPLITUDE.text(), amplitude);
        phaseText = field(c, PanelMsg.WAVE_PHASE_STEP.text(), phaseStep);
        error = new Label(c, SWT.NONE);
        error.setLayoutData(new GridData(SWT.FILL, SWT.TOP, true, false, 2, 1));
        error.setForeground(parent.getDisplay().getSystemColor(SWT.COLOR_DARK_RED));
        return c;
    }

    private static Text field(Composite c, String label, double value) {
        new Label(c, SWT.NONE).setText(label);
        Text t = new Text(c, SWT.BORDER);
        t.setText(java.math.BigDecimal.valueOf(value).stripTrailingZeros().toPlainString());
        t.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        return t;
    }

    @Override
    protected void okPressed() {
        Double a = number(amplitudeText.getText());
        Double p = number(phaseText.getText());
        if (a == null || p == null) {
            error.setText((a == null ? PanelMsg.WAVE_BAD_AMPLITUDE : PanelMsg.WAVE_BAD_PHASE_STEP)
                    .text((a == null ? amplitudeText : phaseText).getText().trim()));
            getButton(IDialogConstants.OK_ID).getParent().layout();
            return;
        }
        amplitude = a;
        phaseStep = p;
        super.okPressed();
    }

    /**
     * The number typed: a decimal ({@code 2.5}, or {@code 2,5} with a decimal comma) or a fraction
     * ({@code -1/6}, as lesson 2 writes it, with a typographic minus too); null if it is none.
     */
    static Double number(String s) {
        String t = s.trim().replace('\u2212', '-').replace(',', '.');
        int slash = t.indexOf('/');
        try {
            double v = slash < 0 ? Double.parseDouble(t)
                    : Double.parseDouble(t.substring(0, slash).trim()) / Double.parseDouble(t.substring(slash + 1).trim());
            return Double.isFinite(v) ? v : null;
        } catch (NumberFormatException e) {
            return null;
        }
    }

    double amplitude() {
        return amplitude;
    }

    double phaseStep() {
        return phaseStep;
    }
}
