package org.parpe.gui.sweep;

import org.parpe.gui.panels.RobotChoice;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.RowData;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Spinner;
import org.eclipse.swt.widgets.Text;
import org.parpe.gui.text.ToolMsg;
import org.parpe.sim.sweep.Objective;

/**
 * The dialog's top line, shared by sweeps and optimisations: the robot, the world, the simulated
 * seconds per run, the threads (every core unless changed) and the objective.
 */
final class RunSettings {
    private final RobotChoice robot;
    private final WorldChoice world;
    private final Text duration;
    private final Spinner jobs;
    private final Combo objective;

    /**
     * The line in {@code parent} (a {@link org.parpe.gui.panels.WrapRow}: it wraps where the dialog is narrower
     * than a longer language's line), starting on the IDE's robot
     * {@code currentRobot} and world {@code currentWorld} (null: the flat floor).
     */
    RunSettings(Composite parent, String currentRobot, java.nio.file.Path currentWorld) {
        new Label(parent, SWT.NONE).setText(ToolMsg.SWEEP_ROBOT.text());
        robot = new RobotChoice(parent, currentRobot);
        new Label(parent, SWT.NONE).setText("   " + ToolMsg.SWEEP_WORLD.text());
        world = new WorldChoice(parent, currentWorld);
        new Label(parent, SWT.NONE).setText("   " + ToolMsg.SWEEP_SECONDS.text());
        duration = new Text(parent, SWT.BORDER);
        duration.setText("10");
        duration.setLayoutData(new RowData(60, SWT.DEFAULT));
        duration.setToolTipText(ToolMsg.SWEEP_SECONDS_TIP.text());
        new Label(parent, SWT.NONE).setText("   " + ToolMsg.SWEEP_JOBS.text());
        jobs = new Spinner(parent, SWT.BORDER);
        // Each simulation at once holds a robot of its own: more than the cores only costs memory (1 024 took gigabytes).
        int cores = Runtime.getRuntime().availableProcessors();
        jobs.setValues(cores, 1, cores, 0, 1, 4);
        jobs.setToolTipText(ToolMsg.SWEEP_JOBS_TIP.text(cores));
        new Label(parent, SWT.NONE).setText("   " + ToolMsg.SWEEP_OBJECTIVE.text());
        objective = new Combo(parent, SWT.READ_ONLY);
        for (Objective o : Objective.values()) {
            objective.add(label(o));
        }
        objective.select(0);
        objective.setToolTipText(ToolMsg.SWEEP_OBJECTIVE_TIP.text());
    }

    RobotChoice robot() {
        return robot;
    }

    WorldChoice world() {
        return world;
    }

    /** The seconds per run as typed (checked at Start). */
    String duration() {
        return duration.getText();
    }

    void setDuration(String seconds) {
        duration.setText(seconds);
    }

    int jobs() {
        return jobs.getSelection();
    }

    void setJobs(int n) {
        jobs.setSelection(n);
    }

    Objective objective() {
        return Objective.values()[objective.getSelectionIndex()];
    }

    void selectObjective(Objective o) {
        objective.select(o.ordinal());
    }

    /** The objective's name with its unit in the IDE's language (the engine's {@link Objective#label()} is English). */
    static String label(Objective o) {
        return switch (o) {
            case FORWARD_SPEED -> ToolMsg.SWEEP_COL_FORWARD_SPEED.text();
            case SPEED -> ToolMsg.SWEEP_COL_SPEED.text();
            case FORWARD -> ToolMsg.SWEEP_COL_FORWARD.text();
            case DISTANCE -> ToolMsg.SWEEP_COL_DISTANCE.text();
            case SCORE -> ToolMsg.SWEEP_OBJECTIVE_SCORE.text();
        };
    }

    /** Whether the boxes can be changed (not while runs are going on). */
    void setEnabled(boolean enabled) {
        robot.control().setEnabled(enabled);
        world.control().setEnabled(enabled);
        duration.setEnabled(enabled);
        jobs.setEnabled(enabled);
        objective.setEnabled(enabled);
    }
}
