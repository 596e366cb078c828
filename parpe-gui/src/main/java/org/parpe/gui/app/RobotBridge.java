package org.parpe.gui.app;

import org.parpe.gui.text.UiMsg;
import java.nio.file.Path;
import org.parpe.core.model.Program;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.editor.ParslEditor;
import org.parpe.gui.prefs.Prefs;
import org.parpe.gui.robot.RobotHost;
import org.parpe.gui.run.RunOn;

/** The IDE window as the Robot tab sees it. UI thread only. */
final class RobotBridge extends WindowBridge implements RobotHost {

    RobotBridge(IdeWindow ide) {
        super(ide);
    }

    @Override
    public ParslEditor editor() {
        return ide.editor;
    }

    @Override
    public Path file() {
        return ide.files.pathForLoading();
    }

    @Override
    public void chooseRobot(String robot) {
        ide.viewBar.show(robot);
        ide.robotChosen(robot);
    }

    @Override
    public void open(Path file) {
        if (ide.files.confirmDiscard()) {
            ide.files.openPath(file);
        }
    }

    @Override
    public boolean save() {
        return ide.files.file() != null && !ide.files.dirty() || ide.files.save();
    }

    @Override
    public void tryIt(Program program, String robot) {
        // the one run path: the Pose panel's playback runs a program made elsewhere on a robot of its choice
        ide.runs.play(program, RunOn.SIMULATOR, robot, outcome -> {
            if (outcome.status() == RunOutcome.Status.ERROR) {
                ide.sayLater(UiMsg.TRY_IT_FAILED.text(outcome.message()));
            }
        });
    }

    @Override
    public void say(String message) {
        ide.status.setMessage(message);
    }

    @Override
    public Prefs prefs() {
        return ide.prefs;
    }
}
