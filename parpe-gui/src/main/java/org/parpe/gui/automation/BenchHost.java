package org.parpe.gui.automation;

import java.nio.file.Path;
import org.parpe.core.run.JointSink;
import org.parpe.gui.diagram.DiagramPane;
import org.parpe.gui.robot.RobotTab;
import org.parpe.gui.run.LiveStates;
import org.parpe.gui.view3d.View3D;

/**
 * What the IDE benchmark ({@link Bench}) does with the window beyond the automation's steps: it
 * opens files and times them, and measures the views it draws (the 3D view, the Diagram tab, the
 * Robot tab), so it reaches those views themselves. UI thread only.
 */
public interface BenchHost extends AutomationHost {
    /** Opens {@code file} as File > Open does; its text is read on a worker while {@link #reading()}. */
    void open(Path file);

    /** Whether a file is being read into the editor. */
    boolean reading();

    /** Makes the window fill the screen's client area. */
    void fillScreen();

    /** The 3D view. */
    View3D view();

    /** The Diagram tab beside the 3D view. */
    DiagramPane diagram();

    /** The Robot tab beside the 3D view. */
    RobotTab robotTab();

    /** Tells {@code sink} every tick of the runs from now on (null: no longer). */
    void observeRuns(JointSink sink);

    /** The live states of the run, as the Diagram tab's overlay reads them. */
    LiveStates live();
}
