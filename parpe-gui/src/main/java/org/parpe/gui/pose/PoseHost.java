package org.parpe.gui.pose;

import java.nio.file.Path;
import java.util.function.Consumer;
import org.eclipse.jface.text.IDocument;
import org.eclipse.swt.widgets.Shell;
import org.parpe.core.load.LoadResult;
import org.parpe.core.model.Program;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.run.RunOn;
import org.parpe.gui.view3d.View3D;

/** What the Pose panel needs from the IDE window; UI thread only. */
public interface PoseHost {
    /** The window, for dialogs. */
    Shell shell();

    /** The last program of the editor that loaded, or null. */
    Program program();

    /** The robot picker's choice ("auto", a generator name or a file): when it changes, the posed robot is rebuilt. */
    String robotChoice();

    /** The simulated robot the IDE shows for {@code program} (the robot picker's choice, or "auto"'s). */
    String robotSpec(Program program);

    /** The 3D view. */
    View3D view();

    /** The editor's document (edits through it are undoable). */
    IDocument document();

    /** The files open in the IDE's editors (none for an untitled script): a save never writes over one of them. */
    java.util.List<Path> openFiles();

    /** The path scripts in the editor are loaded relative to. */
    Path scriptPath();

    /** Loads PARSL text as the IDE does (for the playback program). */
    LoadResult load(Path path, String text);

    /** Whether a run is going on (then the 3D view shows it). */
    boolean running();

    /**
     * Runs {@code program} on {@code target} through the IDE's run pipeline (as Run does, with the
     * simulated robot {@code spec}); {@code onEnd} gets the outcome on the UI thread.
     */
    void play(Program program, RunOn target, String spec, Consumer<RunOutcome> onEnd);

    /** Stops the run at the next tick. */
    void stop();

    /** A line in the status bar. */
    void status(String message);

    /** The robot on the serial bus, as the Hardware dialog holds it; null when none is connected. */
    PoseHardware hardware();
}
