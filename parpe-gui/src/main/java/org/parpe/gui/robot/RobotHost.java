package org.parpe.gui.robot;

import java.nio.file.Path;
import org.parpe.core.model.Program;
import org.parpe.gui.editor.ParslEditor;
import org.parpe.gui.prefs.Prefs;

/** What the Robot tab needs of the IDE window around it (UI thread only). */
public interface RobotHost {
    /** The editor whose document the tab edits when it holds a robot configuration. */
    ParslEditor editor();

    /** The file in the editor (its path for loading, also when untitled). */
    Path file();

    /** The robot chosen for the script in the editor: {@code auto}, a generator or a configuration file. */
    String robotChoice();

    /** Makes {@code robot} (a configuration file) the robot of the script in the editor. */
    void chooseRobot(String robot);

    /** Opens {@code file} in the editor (File > Open), asking about unsaved text first. */
    void open(Path file);

    /** Saves the editor's text to its file (Save As for an untitled file); false if it was not saved. */
    boolean save();

    /**
     * Runs {@code program} in the simulator at once on {@code robot} (a configuration file or a
     * generator), shown in the 3D view, with the IDE's one run path.
     */
    void tryIt(Program program, String robot);

    /** Says {@code message} in the status bar. */
    void say(String message);

    /** The settings (the kit file, the script last open). */
    Prefs prefs();
}
