package org.parpe.gui.app;

import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;

/**
 * The status bar: a message, where the steering keys go during a run, the simulator's state, the
 * hardware's state, simulated time and the caret position.
 */
public final class StatusBar {
    private final Composite bar;
    private final Label message;
    private final Label keys;
    private final Label counts;
    private final Label sim;
    private final Label hardware;
    private final Label time;
    private final Label caret;
    private boolean hardwareAlarm;

    public StatusBar(Composite parent) {
        bar = new Composite(parent, SWT.NONE);
        GridLayout gl = new GridLayout(12, false);
        gl.marginHeight = 2;
        gl.marginWidth = 6;
        bar.setLayout(gl);
        message = field(SWT.DEFAULT, true);
        keys = field(SWT.DEFAULT, false);
        separator();
        counts = field(SWT.DEFAULT, false);
        counts.setText("\u2716 0  \u26a0 0");
        counts.setToolTipText("Errors and warnings in Problems");
        keys.setToolTipText("During a run these keys steer the robot, even in the editor (they never type into the script);"
                + " in a box for a value they type. Esc stops the run.");
        separator();
        sim = field(230, false);
        separator();
        hardware = field(230, false);
        separator();
        time = field(120, false);
        separator();
        caret = field(70, false);
        sim.setText("Simulator: idle");
        hardware.setText("Hardware: not connected");
        time.setText("t = 0.00 s");
    }

    private Label field(int width, boolean grab) {
        Label l = new Label(bar, SWT.NONE);
        GridData gd = new GridData(SWT.FILL, SWT.CENTER, grab, false);
        gd.widthHint = width;
        l.setLayoutData(gd);
        return l;
    }

    private void separator() {
        Label s = new Label(bar, SWT.SEPARATOR | SWT.VERTICAL);
        GridData gd = new GridData(SWT.CENTER, SWT.FILL, false, false);
        gd.heightHint = 16;
        s.setLayoutData(gd);
    }

    public Composite control() {
        return bar;
    }

    public void setMessage(String text) {
        message.setText(text);
        message.setToolTipText(text);
    }

    public String message() {
        return message.getText();
    }

    /** Where the steering keys go ("⌨ w s: steer the robot"), or empty when no run takes keys. */
    public void setKeys(String text) {
        if (!text.equals(keys.getText())) {
            keys.setText(text);
            bar.layout(true);
        }
    }

    public String keys() {
        return keys.getText();
    }

    /** The numbers of errors and warnings in Problems, always as Problems shows them. */
    public void setProblems(long errors, long warnings) {
        String t = "\u2716 " + errors + "  \u26a0 " + warnings;
        if (!t.equals(counts.getText())) {
            counts.setText(t);
            counts.setToolTipText(errors + " error(s) and " + warnings + " warning(s) in Problems");
            bar.layout(true);
        }
    }

    public String problems() {
        return counts.getText();
    }

    public void setSim(String text) {
        sim.setText(text);
    }

    public String sim() {
        return sim.getText();
    }

    public void setHardware(String text) {
        setHardware(text, false);
    }

    /**
     * The hardware field; {@code alarm} (the robot stopped answering) shows it white on red, so
     * that it is seen from across a classroom, and repeats it in the message field.
     */
    public void setHardware(String text, boolean alarm) {
        if (!text.equals(hardware.getText())) {
            hardware.setText(text);
            hardware.setToolTipText(text);
        }
        if (alarm != hardwareAlarm) {
            hardwareAlarm = alarm;
            hardware.setBackground(alarm ? bar.getDisplay().getSystemColor(SWT.COLOR_RED) : null);
            hardware.setForeground(alarm ? bar.getDisplay().getSystemColor(SWT.COLOR_WHITE) : null);
            if (alarm) {
                setMessage(text.replaceFirst("^Hardware: r", "R") + ": check the servo supply and the cable");
            }
        }
    }

    /** Whether the hardware field shows the alarm. */
    public boolean hardwareAlarm() {
        return hardwareAlarm;
    }

    public String hardware() {
        return hardware.getText();
    }

    public void setTime(double t) {
        time.setText(String.format(java.util.Locale.ROOT, "t = %.2f s", t));
    }

    public void setCaret(int line, int column) {
        caret.setText(line + ":" + column);
    }
}
