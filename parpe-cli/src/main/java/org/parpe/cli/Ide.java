package org.parpe.cli;

import org.parpe.cli.text.CliMsg;
import java.io.PrintStream;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Hands {@code parpe}, {@code parpe gui …} and {@code parpe SCRIPT.xml} (what a file manager or a
 * user types to open a script) to the IDE. The installed PARPE has the IDE on the command line's
 * class path and runs it in the same process; the command-line jar of a source checkout does not
 * carry it, and its {@code ./parpe} launcher starts the IDE's jar itself.
 */
final class Ide {
    static final String MAIN = "org.parpe.gui.Main";

    private Ide() {
    }

    /** Whether the arguments ask for the IDE rather than a command. */
    static boolean wanted(String[] args) {
        if (args.length == 0 || args[0].equals("gui")) {
            return true;
        }
        String name = args[0].toLowerCase(java.util.Locale.ROOT);
        return (name.endsWith(".xml") || name.endsWith(".parsl")) && Files.isRegularFile(Path.of(args[0]));
    }

    /** Whether the IDE is on the class path (the installed PARPE), so that {@link #open} can run it. */
    static boolean present() {
        try {
            Class.forName(MAIN, false, Ide.class.getClassLoader());
            return true;
        } catch (ClassNotFoundException e) {
            return false;
        }
    }

    /** Runs the IDE with the arguments until its window closes; returns its exit code. */
    static int open(String[] args, PrintStream err) {
        Class<?> main;
        try {
            main = Class.forName(MAIN);
        } catch (ClassNotFoundException e) {
            // the command-line jar of a source checkout: its launcher starts the IDE's own jar
            err.println("parpe: " + CliMsg.NO_IDE.text() + " ./parpe gui "
                    + String.join(" ", args.length > 0 && args[0].equals("gui")
                    ? java.util.Arrays.copyOfRange(args, 1, args.length) : args));
            return 2;
        }
        // The IDE draws with SWT, not AWT; the headless AWT the command line chose stays as it is.
        try {
            return (Integer) main.getMethod("run", String[].class).invoke(null, (Object) args);
        } catch (InvocationTargetException e) {
            return Main.internalError(e.getCause(), err);
        } catch (ReflectiveOperationException e) {
            return Main.internalError(e, err);
        }
    }
}
