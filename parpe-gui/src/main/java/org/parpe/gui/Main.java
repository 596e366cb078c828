package org.parpe.gui;

import org.parpe.gui.automation.LaunchOptions;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.eclipse.swt.SWT;
import org.eclipse.swt.SWTError;
import org.eclipse.swt.widgets.Display;
import org.parpe.gui.automation.Automation;
import org.parpe.gui.automation.Bench;
import org.parpe.gui.app.IdeWindow;
import org.parpe.gui.prefs.Prefs;
import org.parpe.gui.text.IdeLanguage;
import org.parpe.gui.text.UiMsg;

/**
 * Entry point of the IDE: {@code parpe gui [FILE] [--run-for S] [--screenshot F] [--exit] [--bench] [--lang CODE]}.
 * Exit codes: 0 success, 1 the script had errors or the run failed, 2 usage or start-up problems.
 */
public final class Main {
    private Main() {
    }

    public static void main(String[] args) {
        // as the command line: its messages in UTF-8 where the locale says so though Java fell back to ASCII
        org.parpe.core.text.Terminal.utf8WhereNamed(System::getenv);
        System.exit(run(args));
    }

    /** Runs the IDE until its window closes; returns the exit code. */
    public static int run(String[] args) {
        long started = System.nanoTime();
        List<String> list = Arrays.asList(args);
        if (!list.isEmpty() && list.get(0).equals("gui")) {
            list = list.subList(1, list.size());
        }
        Prefs prefs = new Prefs(Prefs.defaultHome());
        // the language first, as the command line's: the options' own errors and help are told in it
        Locale language;
        try {
            language = IdeLanguage.choose(LaunchOptions.langOption(list), prefs.get(IdeLanguage.PREFERENCE, null),
                    System::getenv);
        } catch (IllegalArgumentException e) {
            System.err.println("parpe gui: error: " + e.getMessage());
            return 2;
        }
        org.parpe.core.text.Lang.use(language);
        LaunchOptions options;
        try {
            options = LaunchOptions.parse(list);
        } catch (IllegalArgumentException e) {
            System.err.println("parpe gui: error: " + e.getMessage());
            System.err.println(LaunchOptions.usage());
            return 2;
        }
        if (options.help()) {
            System.out.println(LaunchOptions.usage());
            return 0;
        }
        IdeLanguage.use(language);
        if (options.file() != null) {
            try {
                // the command line's rule for an input file: the same words for a folder, a FIFO, a missing file
                org.parpe.core.xml.InputFiles.checkKind(options.file());
            } catch (java.io.IOException e) {
                System.err.println("parpe gui: error: " + UiMsg.CANNOT_READ_FILE.text(options.file(), e.getMessage()));
                return 2;
            }
        }
        Display.setAppName("PARPE");
        Display display;
        try {
            display = new Display();
        } catch (SWTError | UnsatisfiedLinkError e) {
            System.err.println("parpe gui: error: " + UiMsg.NO_DISPLAY.text(e.getMessage(), System.getenv("DISPLAY")));
            return 2;
        }
        try {
            // the benchmark's windows: automated, their settings in a home of its own
            Bench.Windows windows = (home, file) -> openWindow(display, new Prefs(home), file, true).automated();
            return options.bench() ? Bench.run(display, started, windows) : loop(display, options, prefs);
        } finally {
            display.dispose();
        }
    }

    private static int loop(Display display, LaunchOptions options, Prefs prefs) {
        // The installed PARPE copies its examples to the user's own folder on first use.
        org.parpe.gui.files.Examples.folder();
        IdeWindow ide = openWindow(display, prefs, options.file(), options.automated());
        Automation auto = options.automated() ? Automation.start(ide.automated(), options) : null;
        return dispatch(display, ide, auto);
    }

    /** A new IDE window, open, with {@code file} in its editor (null: it recovers or starts a new script). */
    private static IdeWindow openWindow(Display display, Prefs prefs, Path file, boolean automated) {
        IdeWindow ide = new IdeWindow(display, prefs);
        ide.open(file, automated);
        return ide;
    }

    /**
     * Handles events until {@code ide}'s window closes. A failure of PARPE itself in a listener
     * must not take the user's work or a run with it: a RuntimeException or an Error (a class
     * missing from the jars is a LinkageError) is written to the crash file and named to the
     * user, an Error stops the run as Esc does ({@link IdeWindow#internalError}), and the window
     * stays, with its text, to be saved.
     */
    static int dispatch(Display display, IdeWindow ide, Automation auto) {
        while (!ide.closed()) {
            try {
                if (!display.readAndDispatch()) {
                    display.sleep();
                }
            } catch (RuntimeException | Error e) {
                String file = ide.internalError(e);
                System.err.println("parpe gui: " + UiMsg.INTERNAL_ERROR_EVENT.text(e, file));
                if (auto != null) {
                    auto.fail(UiMsg.INTERNAL_ERROR_EVENT.text(e, file));
                }
            }
        }
        return auto == null ? 0 : auto.exitCode();
    }

    /** SWT's version, for reports. */
    public static String swtVersion() {
        return Integer.toString(SWT.getVersion());
    }
}
