package org.parpe.gui.diagram;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;
import org.parpe.gui.automation.Screenshot;
import org.parpe.gui.diagram.Projection.View;

/**
 * The IDE at 1366×768 on a copy of {@code examples/centipede-walk.xml} with the Diagram tab
 * shown, as the diagram GUI tests use it: opening it, showing a view and saving a picture of
 * the window for docs/ide.md.
 */
final class DiagramWindow {

    /** The window and the copy of the example it has open. */
    record Opened(IdeWindow ide, Path copy) {
    }

    private DiagramWindow() {
    }

    /** Opens the IDE with its settings in {@code home} on a copy of the centipede walk, the Diagram tab shown. */
    static Opened open(Path home) throws Exception {
        Path example = Path.of(System.getProperty("parpe.examples", "../examples"), "centipede-walk.xml");
        Path copy = Files.createDirectories(home.resolve("scripts")).resolve("centipede-walk.xml");
        Files.copy(example, copy);
        IdeWindow ide = IdeAccess.openIde(home);
        IdeAccess.shell(ide).setSize(1366, 768);
        IdeAccess.open(ide, copy);
        DiagramPane pane = IdeAccess.diagram(ide);
        assertEquals("Diagram", pane.showTab());
        IdeAccess.pump(() -> pane.current() && IdeAccess.program(ide) != null, "the first diagram and the loaded script");
        return new Opened(ide, copy);
    }

    /** Shows view {@code v} on {@code subject} (null: the default) and waits until it shows the text. */
    static void show(IdeWindow ide, View v, String subject) {
        DiagramPane pane = IdeAccess.diagram(ide);
        if (subject == null) {
            pane.setView(v);
        } else {
            pane.setView(v, subject);
        }
        IdeAccess.pump(() -> pane.current() && pane.shown().view() == v
                && (subject == null || subject.equals(pane.shown().subject())), v + " view of the text");
    }

    /** Asserts that the drawing is at least half as tall as the Diagram tab (issue 24: the controls stay compact). */
    static void canvasHasHalfTheTab(IdeWindow ide) {
        IdeAccess.settle();
        DiagramPane pane = IdeAccess.diagram(ide);
        int tab = pane.control().getSize().y;
        int drawing = pane.canvas().getSize().y;
        assertTrue(tab > 300, "the Diagram tab at 1366×768 is " + tab + " px tall");
        assertTrue(2 * drawing >= tab, "the drawing is " + drawing + " px of the tab's " + tab + " px");
    }

    /** Saves the window to {@code docs/images/ide/NAME} (folder: system property {@code parpe.ideImages}). */
    static void picture(IdeWindow ide, String name) throws Exception {
        // no blinking caret in the editor: the same picture on every run
        IdeAccess.diagram(ide).canvas().setFocus();
        IdeAccess.settle();
        Path dir = Path.of(System.getProperty("parpe.ideImages", "../docs/images/ide"));
        Files.createDirectories(dir);
        Path png = dir.resolve(name);
        Screenshot.save(IdeAccess.shell(ide), png);
        var d = new org.eclipse.swt.graphics.ImageLoader().load(png.toString())[0];
        assertEquals(1366, d.width, "picture width");
        assertTrue(Screenshot.distinctColours(d, 64) >= 64, png + " looks blank");
    }

    /**
     * Runs the open script in the simulator and calls {@code check} with the tick of each of ten
     * new frames of the live overlay ({@code shown}: whether the view's overlay is there); ends
     * the run and waits for the overlay to go. {@code evidence} names a screenshot of the last
     * frame in the test artefacts (it changes from run to run), or is {@code null}.
     */
    static void tenFrames(IdeWindow ide, java.util.function.BooleanSupplier shown, java.util.function.LongConsumer check,
                          String evidence) throws Exception {
        DiagramPane pane = IdeAccess.diagram(ide);
        IdeAccess.pump(() -> !shown.getAsBoolean(), "no overlay while nothing runs");
        java.util.concurrent.atomic.AtomicReference<org.parpe.core.run.RunOutcome> end = new java.util.concurrent.atomic.AtomicReference<>();
        IdeAccess.run(ide, org.parpe.gui.run.RunOn.SIMULATOR, 600, end::set);
        try {
            long last = -1;
            for (int frame = 0; frame < 10; frame++) {
                long after = last;
                IdeAccess.pump(() -> shown.getAsBoolean() && pane.liveTick() > Math.max(0, after) || end.get() != null,
                        "a new frame of the live overlay");
                assertEquals(null, end.get(), "the run ended early");
                long tick = pane.liveTick();
                assertTrue(tick > 0, "a published tick");
                check.accept(tick);
                last = tick;
            }
            if (evidence != null) {
                IdeAccess.screenshot(IdeAccess.shell(ide), evidence);
            }
        } finally {
            IdeAccess.endRun(ide);
        }
        IdeAccess.pump(() -> !shown.getAsBoolean(), "the overlay to go when the run ends");
    }
}
