package org.parpe.gui.panels;

import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.parpe.gui.text.ToolMsg;
import org.parpe.sim.SimTarget;
import org.parpe.sim.config.RobotConfigs;

/**
 * The robot to simulate, with the choices of the IDE's runs: {@code auto} (the standard robot
 * that fits the script), one of the simulator's generators, or a robot configuration file.
 * Starts on the robot the IDE's run uses. The Sweep dialog and File → Export Robot… show it.
 */
public final class RobotChoice {
    private final String autoText = ToolMsg.ROBOT_CHOICE_AUTO.text(SimTarget.AUTO);
    private final String browse = ToolMsg.ROBOT_CHOICE_BROWSE.text();

    private final Combo combo;
    private String file;
    private String previous;

    public RobotChoice(Composite parent, String current) {
        combo = new Combo(parent, SWT.READ_ONLY);
        combo.add(autoText);
        RobotConfigs.generatorNames().forEach(combo::add);
        combo.add(browse);
        if (current != null && !SimTarget.AUTO.equals(current) && combo.indexOf(current) < 0) {
            useFile(current);
        }
        int at = current == null ? -1 : combo.indexOf(current);
        combo.select(at >= 0 ? at : 0);
        previous = combo.getText();
        combo.setToolTipText(ToolMsg.ROBOT_CHOICE_TIP.text());
        combo.addListener(SWT.Selection, e -> chosen());
    }

    public Combo control() {
        return combo;
    }

    private void chosen() {
        if (!browse.equals(combo.getText())) {
            previous = combo.getText();
            return;
        }
        java.nio.file.Path chosen = FileDialogs.ask(combo.getShell(), SWT.OPEN, ToolMsg.ROBOT_CHOICE_TITLE.text(), "*.xml", null, null);
        if (chosen == null) {
            combo.select(combo.indexOf(previous));
            return;
        }
        String p = chosen.toString();
        useFile(p);
        previous = p;
    }

    /** Adds the configuration file {@code path} (replacing the previous one) and selects it. */
    public void useFile(String path) {
        if (file != null) {
            combo.remove(file);
        }
        file = path;
        combo.add(path, combo.getItemCount() - 1);
        combo.select(combo.indexOf(path));
    }

    /** {@code auto}, a generator name, or a configuration file path. */
    public String robot() {
        String t = combo.getText();
        return autoText.equals(t) || browse.equals(t) ? SimTarget.AUTO : t;
    }

    /** Selects a generator by name (tests, automation). */
    public void select(String name) {
        int at = combo.indexOf(name);
        if (at >= 0) {
            combo.select(at);
            previous = name;
        }
    }
}
