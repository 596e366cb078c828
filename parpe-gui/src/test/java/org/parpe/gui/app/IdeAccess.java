package org.parpe.gui.app;

import java.nio.file.Path;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import org.eclipse.swt.widgets.Shell;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.run.Target;

/** {@link Gui}'s helpers and the window's package-private parts, for GUI tests of other packages. */
public final class IdeAccess {
    private IdeAccess() {
    }

    /** A new automated IDE window with its settings in {@code home}, after its first validation. */
    public static IdeWindow openIde(Path home) {
        return Gui.openIde(home);
    }

    /** Ends any run and closes the window. */
    public static void closeIde(IdeWindow ide) {
        Gui.closeIde(ide);
    }

    /** Opens {@code file} as File > Open does and waits until it is in the editor. */
    public static void open(IdeWindow ide, Path file) {
        Gui.open(ide, file);
    }

    /** Runs the event loop until {@code done} holds (bounded). */
    public static void pump(BooleanSupplier done, String what) {
        Gui.pump(done, what);
    }

    /** Lets layouts and paints finish. */
    public static void settle() {
        Gui.settle();
    }

    /** Saves a screenshot as evidence and checks it is not blank. */
    public static void screenshot(Shell shell, String name) throws Exception {
        Gui.screenshot(shell, name);
    }

    /** Whether a run is going on. */
    public static boolean running(IdeWindow ide) {
        return ide.runs().running();
    }

    /** Runs the editor's script on {@code target} for {@code seconds} of simulated time, as fast as possible. */
    public static void run(IdeWindow ide, Target target, double seconds, Consumer<RunOutcome> onEnd) {
        ide.toolbar().setTarget(target);
        ide.toolbar().setSpeed(org.parpe.gui.run.Speed.MAX);
        ide.runs().run(false, seconds, onEnd);
    }

    /** The status bar's message. */
    public static String status(IdeWindow ide) {
        return ide.status().message();
    }

    /** Selects the simulated robot (a generator name) as the 3D view's picker does. */
    public static void robot(IdeWindow ide, String name) {
        ide.viewBar().select(name);
    }
}
