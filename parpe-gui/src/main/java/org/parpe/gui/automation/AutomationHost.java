package org.parpe.gui.automation;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Consumer;
import org.eclipse.swt.widgets.Display;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.run.Speed;

/**
 * What the command line's automation ({@link Automation}: {@code --run-for}, {@code --screenshot},
 * {@code --pose-panel}, {@code --grid}, {@code --exit}) does with the IDE window: the steps a user
 * would take, not the window's parts. UI thread only.
 */
public interface AutomationHost {
    /** The window's display, whose timers drive the automation. */
    Display display();

    /** Whether the window has closed. */
    boolean closed();

    /** How many checks of the script the window has shown (the automation waits for the first). */
    int validations();

    /** The name of the file in the editor, as its tab shows it. */
    String fileName();

    /** Whether the last check loaded the script and Problems lists no error (the script can run). */
    boolean runnable();

    /** What Problems lists. */
    List<Diagnostic> problems();

    /** The status bar's message. */
    String statusMessage();

    /**
     * Brings the Pose panel to the front and loads into it the poses the script plays; false if
     * there are none to load (the status bar says why).
     */
    boolean showScriptPoses();

    /** Whether the posed robot stands in the Pose panel's pose. */
    boolean posingReady();

    /** Takes the 3D view's camera close to the posed modules (no longer following the robot). */
    void focusOnPosedModules();

    /**
     * Shows gait table {@code name} in the grid editor with every module cell selected (the focus,
     * and the entry selected in the text, on the first); false if the script has no such table.
     */
    boolean selectGaitTable(String name);

    /** The name of the gait table the grid editor shows, or null if it shows none. */
    String gaitTableShown();

    /**
     * Runs the script in the simulator at {@code speed} for {@code seconds} of simulated time with
     * the parameter values remembered (no questions), as Run does; {@code onEnd} gets the outcome.
     */
    void runInSimulator(Speed speed, double seconds, Consumer<RunOutcome> onEnd);

    /** Whether a run is going on. */
    boolean running();

    /** Stops the run, as the Stop button does. */
    void stop();

    /** Saves a PNG picture of the window as the screen shows it. */
    void screenshot(Path file) throws IOException;

    /** The titles of the menu bar's menus, as their widgets hold them (with the mnemonic's {@code &}). */
    List<String> menuTitles();

    /** Closes the window, the unsaved text kept for recovery first (as {@code --exit} does). */
    void close();
}
