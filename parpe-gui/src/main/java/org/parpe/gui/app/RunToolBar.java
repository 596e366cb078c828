package org.parpe.gui.app;

import org.parpe.gui.text.UiMsg;
import org.parpe.gui.prefs.Prefs;
import java.nio.file.Path;

import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.ToolBar;
import org.eclipse.swt.widgets.ToolItem;
import org.parpe.gui.hardware.PortChoice;
import org.parpe.gui.panels.Icons;
import org.parpe.gui.panels.OverflowBar;
import org.parpe.gui.run.Speed;
import org.parpe.gui.run.RunOn;
import org.parpe.serial.link.SerialLink;

/** The run tool bar: Run, Pause, Stop, emergency stop, speed, target, serial port and hardware profile. */
public final class RunToolBar implements PortChoice {
    private final Composite bar;
    private final ToolItem run;
    private final ToolItem pause;
    private final ToolItem stop;
    private final ToolItem estop;
    private final Combo speed;
    private final Combo target;
    private final Combo port;
    private final Combo profile;
    private final Button browse;

    RunToolBar(Composite parent, RunActions actions, Prefs prefs) {
        // At 1366 pixels the port, profile and Hardware… go behind a chevron (») instead of off the edge.
        OverflowBar overflow = new OverflowBar(parent);
        bar = overflow.control();
        ToolBar tb = new ToolBar(bar, SWT.FLAT | SWT.RIGHT);
        overflow.pin(tb);
        Icons icons = Icons.of(parent.getDisplay());
        run = item(tb, icons.run, UiMsg.TOOL_RUN.text(), UiMsg.TOOL_RUN_TIP.text(), () -> actions.run(true, -1, null));
        pause = item(tb, icons.pause, UiMsg.TOOL_PAUSE.text(), UiMsg.TOOL_PAUSE_TIP.text(), actions::pause);
        stop = item(tb, icons.stop, UiMsg.TOOL_STOP.text(), UiMsg.TOOL_STOP_TIP.text(), actions::stop);
        new ToolItem(tb, SWT.SEPARATOR);
        estop = item(tb, icons.estop, UiMsg.TOOL_ESTOP.text(), UiMsg.TOOL_ESTOP_TIP.text(), actions::emergencyStop);
        speed = speedCombo(actions, prefs);
        target = targetCombo(actions);
        port = portCombo(prefs);
        profile = profileCombo(prefs);
        browse = browseButton();
        Button hardware = new Button(bar, SWT.PUSH);
        hardware.setText(UiMsg.TOOL_HARDWARE.text());
        hardware.setToolTipText(UiMsg.TOOL_HARDWARE_TIP.text());
        hardware.addListener(SWT.Selection, e -> actions.openHardware());
        refreshPorts();
        updatePort();
    }

    /** The speed, as the user chose it last time. */
    private Combo speedCombo(RunActions actions, Prefs prefs) {
        Combo c = combo(UiMsg.TOOL_SPEED.text(), 150);
        for (Speed s : Speed.values()) {
            c.add(s.label());
        }
        fitItems(c);
        c.select(index(Speed.values(), prefs.get("run.speed", Speed.REAL_TIME.name()), Speed::name));
        c.addListener(SWT.Selection, e -> {
            actions.controller().setSpeed(speed());
            prefs.put("run.speed", speed().name());
        });
        return c;
    }

    /** Where the script runs: every session starts on the simulator; each file keeps its own target (RunChoices). */
    private Combo targetCombo(RunActions actions) {
        Combo c = combo(UiMsg.TOOL_TARGET.text(), 170);
        for (RunOn t : RunOn.values()) {
            c.add(t.label());
        }
        fitItems(c);
        c.select(RunOn.SIMULATOR.ordinal());
        c.setToolTipText(UiMsg.TOOL_TARGET_TIP.text());
        c.addListener(SWT.Selection, e -> {
            actions.targetChosen(target());
            updatePort();
        });
        return c;
    }

    /** The serial port, typed or picked from the devices present when the list opens. */
    private Combo portCombo(Prefs prefs) {
        Combo c = labelledBox(UiMsg.TOOL_PORT.text(), 160, UiMsg.TOOL_PORT_TIP.text());
        c.setText(prefs.get("run.port", ""));
        c.addListener(SWT.MouseDown, e -> refreshPorts());
        c.addListener(SWT.Modify, e -> prefs.put("run.port", c.getText()));
        return c;
    }

    /** The hardware profile's file. */
    private Combo profileCombo(Prefs prefs) {
        Combo c = labelledBox(UiMsg.TOOL_PROFILE.text(), 180, UiMsg.TOOL_PROFILE_TIP.text());
        c.setText(prefs.get("run.hardware", ""));
        c.addListener(SWT.Modify, e -> prefs.put("run.hardware", c.getText()));
        return c;
    }

    /** "…": picks the hardware profile's file. */
    private Button browseButton() {
        Button b = new Button(bar, SWT.PUSH);
        b.setText("\u2026");
        b.setToolTipText(UiMsg.TOOL_PROFILE_BROWSE_TIP.text());
        b.addListener(SWT.Selection, e -> {
            Path chosen = org.parpe.gui.panels.FileDialogs.ask(bar.getShell(), SWT.OPEN, UiMsg.HARDWARE_PROFILE.text(), "*.xml", null, null);
            if (chosen != null) {
                profile.setText(chosen.toString());
            }
        });
        return b;
    }

    /** A label and an editable combo box of the given width. */
    private Combo labelledBox(String label, int width, String tip) {
        new Label(bar, SWT.NONE).setText(label);
        Combo c = new Combo(bar, SWT.DROP_DOWN);
        GridData gd = new GridData(SWT.LEFT, SWT.CENTER, false, false);
        gd.widthHint = width;
        c.setLayoutData(gd);
        c.setToolTipText(tip);
        return c;
    }

    private static <T> int index(T[] values, String name, java.util.function.Function<T, String> key) {
        for (int i = 0; i < values.length; i++) {
            if (key.apply(values[i]).equals(name)) {
                return i;
            }
        }
        return 0;
    }

    private static ToolItem item(ToolBar tb, Image image, String text, String tip, Runnable action) {
        ToolItem it = new ToolItem(tb, SWT.PUSH);
        it.setImage(image);
        it.setText(text);
        it.setToolTipText(tip);
        it.addListener(SWT.Selection, e -> action.run());
        return it;
    }

    private Combo combo(String label, int width) {
        Label l = new Label(bar, SWT.NONE);
        l.setText(label);
        GridData ld = new GridData(SWT.LEFT, SWT.CENTER, false, false);
        ld.horizontalIndent = 12;
        l.setLayoutData(ld);
        Combo c = new Combo(bar, SWT.READ_ONLY);
        GridData gd = new GridData(SWT.LEFT, SWT.CENTER, false, false);
        gd.widthHint = width;
        c.setLayoutData(gd);
        return c;
    }

    /** A combo at least as wide as its longest item (a longer language's, e.g. "So schnell wie möglich"), else at its width. */
    private static void fitItems(Combo c) {
        GridData gd = (GridData) c.getLayoutData();
        if (c.computeSize(SWT.DEFAULT, SWT.DEFAULT).x > c.computeSize(gd.widthHint, SWT.DEFAULT).x) {
            gd.widthHint = SWT.DEFAULT;
        }
    }

    private void updatePort() {
        port.setEnabled(target().hardware());
        profile.setEnabled(target().hardware());
        browse.setEnabled(target().hardware());
    }

    /** Lists the serial devices present now (USB adapters first), keeping what the user typed. */
    void refreshPorts() {
        String typed = port.getText();
        List<String> found = SerialLink.availablePorts();
        port.setItems(found.toArray(new String[0]));
        port.setText(typed);
    }

    Composite control() {
        return bar;
    }

    Speed speed() {
        return Speed.values()[Math.max(0, speed.getSelectionIndex())];
    }

    RunOn target() {
        return RunOn.values()[Math.max(0, target.getSelectionIndex())];
    }

    /** Selects a target (automation runs in the simulator). */
    public void setTarget(RunOn t) {
        target.select(t.ordinal());
        updatePort();
    }

    /** Picks a target as the user does in the tool bar: the file in the editor keeps it (tests). */
    void chooseTarget(RunOn t) {
        target.select(t.ordinal());
        target.notifyListeners(SWT.Selection, new org.eclipse.swt.widgets.Event());
    }

    /** Selects a speed without remembering it (automation). */
    public void setSpeed(Speed s) {
        speed.select(s.ordinal());
    }

    /** The emergency stop button. */
    ToolItem emergencyStop() {
        return estop;
    }

    /** The Run button (tests). */
    ToolItem runItem() {
        return run;
    }

    /** The Pause / Resume button (tests). */
    ToolItem pauseItem() {
        return pause;
    }

    @Override
    public String port() {
        return port.getText().trim();
    }

    /** The hardware profile chosen, or null for G1 modules without one. */
    @Override
    public String hardwareProfile() {
        String p = profile.getText().trim();
        return p.isEmpty() ? null : p;
    }

    /** Types a hardware profile into the profile box (automation, tests). */
    @Override
    public void setHardwareProfile(String p) {
        profile.setText(p);
    }

    /** Types a serial port into the port box (automation, tests). */
    @Override
    public void setPort(String p) {
        port.setText(p);
    }

    /** Enables the buttons that make sense now. */
    void update(boolean running, boolean paused) {
        // Paused (a breakpoint, Pause), Resume goes on: Run beside it would be a second button for the same (F5 still resumes).
        run.setEnabled(!running);
        pause.setEnabled(running);
        Icons icons = Icons.of(pause.getDisplay());
        pause.setText(paused ? UiMsg.TOOL_RESUME.text() : UiMsg.TOOL_PAUSE.text());
        pause.setImage(paused ? icons.run : icons.pause);
        stop.setEnabled(running);
        estop.setEnabled(true);
        // "Resume" is wider than "Pause": without a new layout the tool bar keeps its old width
        // and the last item, the emergency stop, is pushed out of sight.
        bar.layout(true, true);
    }
}
