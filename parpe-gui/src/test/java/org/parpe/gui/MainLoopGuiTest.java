package org.parpe.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import java.util.stream.Stream;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Display;
import org.junit.jupiter.api.Test;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.app.Gui;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;
import org.parpe.gui.prefs.Prefs;
import org.parpe.gui.run.RunOn;

/**
 * Issue 31, item 1: an Error in a listener (the double-click's {@code NoClassDefFoundError})
 * went past the IDE's event loop, which caught RuntimeExceptions only: the window closed, no
 * crash file was written although docs/ide.md promises one, and a run in progress died with
 * the window. Now the loop writes the crash file, stops the run as Esc does, names the file, and
 * the window stays with its text.
 */
class MainLoopGuiTest {
    @Test
    void anErrorInTheEventLoopWritesTheCrashFileStopsTheRunAndKeepsTheWindow() throws Exception {
        IdeWindow ide = IdeAccess.openIde(Files.createTempDirectory("parpe-loop"));
        try {
            IdeAccess.open(ide, Gui.example("hello-snake.xml"));
            String text = IdeAccess.editor(ide).document().get();
            AtomicReference<RunOutcome> outcome = new AtomicReference<>();
            IdeAccess.run(ide, RunOn.SIMULATOR, -1, outcome::set);
            IdeAccess.pump(() -> IdeAccess.running(ide) && IdeAccess.controller(ide).status() != null, "the run to start");
            Path crashes = Prefs.defaultHome().resolve("crash");
            List<Path> before = list(crashes);

            Display d = IdeAccess.shell(ide).getDisplay();
            // A listener that links a missing class, as jface.text's double-click did: the Error
            // comes out of readAndDispatch as it is (asyncExec would wrap it in an SWTException).
            var editor = IdeAccess.editor(ide).widget();
            boolean[] thrown = new boolean[1];
            editor.addListener(SWT.Paint, e -> {
                if (!thrown[0]) {
                    thrown[0] = true;
                    throw new NoClassDefFoundError("com/ibm/icu/text/BreakIterator");
                }
            });
            editor.redraw();
            boolean[] aliveAfter = new boolean[1];
            String[] logAfter = new String[1];
            long until = System.currentTimeMillis() + 30_000;
            Runnable[] watch = new Runnable[1];
            watch[0] = () -> {
                aliveAfter[0] = !IdeAccess.shell(ide).isDisposed();
                if (outcome.get() != null || System.currentTimeMillis() > until) {
                    logAfter[0] = IdeAccess.runLog(ide);
                    IdeAccess.shell(ide).dispose();
                } else {
                    d.timerExec(50, watch[0]);
                }
            };
            d.asyncExec(watch[0]);
            assertEquals(0, Main.dispatch(d, ide, null), "the loop's exit code");

            assertTrue(thrown[0], "the listener was not called");
            assertTrue(aliveAfter[0], "the window closed on the Error");
            assertNotNull(outcome.get(), "the run was not stopped within 30 s of the Error");
            assertEquals(RunOutcome.Status.STOPPED, outcome.get().status(), outcome.get().toString());
            List<Path> after = list(crashes);
            after.removeAll(before);
            assertEquals(1, after.size(), "crash files written: " + after);
            String crash = Files.readString(after.get(0));
            assertTrue(crash.contains("java.lang.NoClassDefFoundError: com/ibm/icu/text/BreakIterator"), crash);
            assertEquals(text, IdeAccess.editor(ide).document().get(), "the text changed");
            String log = logAfter[0];
            assertTrue(log.contains("please attach " + after.get(0)), "the Run log does not name the crash file: " + log);
            assertTrue(log.contains("EMERGENCY STOP"), log);
        } finally {
            IdeAccess.closeIde(ide);
        }
    }

    private static List<Path> list(Path dir) throws Exception {
        if (!Files.isDirectory(dir)) {
            return new java.util.ArrayList<>();
        }
        try (Stream<Path> s = Files.list(dir)) {
            return new java.util.ArrayList<>(s.toList());
        }
    }

    @Test
    void theSameFailureAgainNamesTheFirstFile() throws Exception {
        IdeWindow ide = IdeAccess.openIde(Files.createTempDirectory("parpe-loop-again"));
        try {
            Error e = new NoClassDefFoundError("com/ibm/icu/text/BreakIterator");
            String first = ide.internalError(e);
            assertTrue(Files.isRegularFile(Path.of(first)), first);
            assertEquals(first, ide.internalError(e), "a second crash file for the same failure");
            assertFalse(first.equals(ide.internalError(new IllegalStateException("another"))));
        } finally {
            IdeAccess.closeIde(ide);
        }
    }
}
