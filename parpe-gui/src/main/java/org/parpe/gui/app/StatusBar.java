package org.parpe.gui.app;

import org.parpe.gui.text.UiMsg;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.parpe.gui.panels.TitleWidths;

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
    /** The message in full; the field shows as much of it as fits, the tooltip all of it. */
    private String fullMessage = "";

    public StatusBar(Composite parent) {
        bar = new Composite(parent, SWT.NONE);
        GridLayout gl = new GridLayout(12, false);
        gl.marginHeight = 2;
        gl.marginWidth = 6;
        bar.setLayout(gl);
        // A fixed width hint: the field takes the bar's spare room whatever its text, and fit() shortens the text to it.
        message = field(100, true);
        message.addListener(SWT.Resize, e -> fit());
        keys = field(SWT.DEFAULT, false);
        separator();
        counts = field(SWT.DEFAULT, false);
        counts.setText("\u2716 0  \u26a0 0");
        counts.setToolTipText(UiMsg.STATUS_COUNTS_TIP.text());
        keys.setToolTipText(UiMsg.STATUS_KEYS_TIP.text());
        separator();
        sim = field(230, false);
        separator();
        hardware = field(230, false);
        separator();
        time = field(120, false);
        separator();
        caret = field(70, false);
        sim.setText(UiMsg.SIM_IDLE.text());
        hardware.setText(UiMsg.HW_NOT_CONNECTED.text());
        TitleWidths.label(sim);
        TitleWidths.label(hardware);
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

    /**
     * Shows {@code text} in the message field; what does not fit is cut at its end with "…" (a
     * message says what matters first) and the tooltip shows it whole.
     */
    public void setMessage(String text) {
        fullMessage = text;
        message.setToolTipText(text);
        fit();
    }

    /** The message in full, however much of it the field shows. */
    public String message() {
        return fullMessage;
    }

    /** The message field (tests). */
    Label messageField() {
        return message;
    }

    private void fit() {
        int width = message.getSize().x;
        String shown = fullMessage;
        if (width > 0) {
            GC gc = new GC(message);
            try {
                shown = shortened(gc, fullMessage, width);
            } finally {
                gc.dispose();
            }
        }
        if (!shown.equals(message.getText())) {
            message.setText(shown);
        }
    }

    /** {@code text}, or as much of it as fits {@code width} pixels followed by "…", cut after a word where one is near. */
    static String shortened(GC gc, String text, int width) {
        if (gc.textExtent(text).x <= width) {
            return text;
        }
        int lo = 0;
        int hi = text.length();
        while (lo < hi) { // the longest start that fits with the ellipsis
            int mid = (lo + hi + 1) / 2;
            if (gc.textExtent(text.substring(0, mid) + "\u2026").x <= width) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        int space = text.lastIndexOf(' ', lo);
        int end = space > lo * 3 / 4 ? space : lo;
        return text.substring(0, end).stripTrailing().replaceAll("[;,:(\u2014-]+$", "").stripTrailing() + "\u2026";
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
            counts.setToolTipText(UiMsg.STATUS_COUNTS_NOW_TIP.text(errors, warnings));
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
        setHardware(text, null);
    }

    /**
     * The hardware field; {@code alarm} (the robot stopped answering: what to do, or null) shows it
     * white on red, so that it is seen from across a classroom, and is said in the message field.
     */
    public void setHardware(String text, String alarmMessage) {
        boolean alarm = alarmMessage != null;
        if (!text.equals(hardware.getText())) {
            hardware.setText(text);
            hardware.setToolTipText(text);
        }
        if (alarm != hardwareAlarm) {
            hardwareAlarm = alarm;
            hardware.setBackground(alarm ? bar.getDisplay().getSystemColor(SWT.COLOR_RED) : null);
            hardware.setForeground(alarm ? bar.getDisplay().getSystemColor(SWT.COLOR_WHITE) : null);
            if (alarm) {
                setMessage(alarmMessage);
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
