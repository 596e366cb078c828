package org.parpe.gui.app;

import org.parpe.gui.prefs.Prefs;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import org.parpe.gui.run.RunOn;
import org.parpe.sim.SimTarget;

/**
 * The simulated robot, the world and the run target chosen for each file. A file that was never
 * given a robot runs on {@code auto} (the robot its script is written for), whatever another file
 * ran on; one never given a world runs in the world its script names ({@code <?parpe world?>}),
 * else on the flat floor; the target is the simulator for every file at the start of a session,
 * so that yesterday's serial port cannot make today's lesson fail. The robot and the world are
 * remembered across sessions (in {@link Prefs}), the target only for this session. UI thread only.
 */
final class RunChoices {
    private static final String ROBOT = "robot.";
    private static final String WORLD = "world.";

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

    /**
     * The world chosen for the current file ({@link WorldPicker#FLAT} or a world file), or
     * {@code declared} (the world its script names; null: the flat floor) unless one was chosen for it.
     */
    String world(Path declared) {
        String fallback = declared == null ? WorldPicker.FLAT : declared.toString();
        return current == null ? fallback : prefs.get(WORLD + current, fallback);
    }

    void worldChosen(String world) {
        if (current != null) {
            prefs.put(WORLD + current, world);
        }
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
