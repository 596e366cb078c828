package org.parpe.gui.app;

import org.parpe.gui.prefs.Prefs;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import org.parpe.gui.run.RunOn;
import org.parpe.sim.SimTarget;

/**
 * The simulated robot and the run target chosen for each file. A file that was never given a
 * robot runs on {@code auto} (the robot its script is written for), whatever another file ran
 * on; the target is the simulator for every file at the start of a session, so that yesterday's
 * serial port cannot make today's lesson fail. The robot is remembered across sessions (in
 * {@link Prefs}), the target only for this session. UI thread only.
 */
final class RunChoices {
    private static final String ROBOT = "robot.";

    private final Prefs prefs;
    private final Map<Path, RunOn> targets = new HashMap<>();
    private Path current;

    RunChoices(Prefs prefs) {
        this.prefs = prefs;
    }

    /** {@code file} is now in the editor: its choices become the current ones. */
    void switchTo(Path file) {
        current = key(file);
    }

    /** The robot chosen for the current file: {@code auto} unless one was chosen for it. */
    String robot() {
        return current == null ? SimTarget.AUTO : prefs.get(ROBOT + current, SimTarget.AUTO);
    }

    /** The target chosen for the current file in this session: the simulator unless another was chosen. */
    RunOn target() {
        return current == null ? RunOn.SIMULATOR : targets.getOrDefault(current, RunOn.SIMULATOR);
    }

    void robotChosen(String robot) {
        if (current != null) {
            prefs.put(ROBOT + current, robot);
        }
    }

    void targetChosen(RunOn target) {
        if (current != null) {
            targets.put(current, target);
        }
    }

    private static Path key(Path file) {
        return file.toAbsolutePath().normalize();
    }
}
