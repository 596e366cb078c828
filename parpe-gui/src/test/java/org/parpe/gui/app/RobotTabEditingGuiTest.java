package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Event;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.Diagnostic;
import org.parpe.gui.robot.Outside;
import org.parpe.gui.robot.RobotTab;

/**
 * Issue 33's Robot tab beside the text, with real widgets under Xvfb at 1366×768: an edit in the
 * text shows in the tab, an edit in the tab changes only its line of the text and Undo takes it
 * back; a bad configuration is located in Problems and on the tab; a script's robot is shown
 * read-only with its latch plates marked (issue 35) and "Make editable" writes it beside the
 * script; every control of the tab stays in the window at 1366×768 and at twice the text size.
 */
class RobotTabEditingGuiTest {
    private IdeWindow ide;
    private Path dir;

    @BeforeEach
    void open() throws Exception {
        Gui.display();
        dir = Files.createTempDirectory("parpe-robot-edit");
        ide = Gui.openIde(dir.resolve("home"), 1366, 768);
    }

    @AfterEach
    void close() {
        Gui.closeIde(ide);
    }

    private RobotTab tab() {
        return ide.robotTab;
    }

    /** Opens a copy of {@code text} as {@code name}, waits until it is checked and shows the Robot tab. */
    private Path openCopy(String name, String text) throws Exception {
        Path f = dir.resolve(name);
        Files.writeString(f, text);
        int before = ide.validations();
        Gui.open(ide, f);
        Gui.pump(() -> ide.validations() > before, "the check of " + name);
        tab().showTab();
        Gui.settle();
        return f;
    }

    private Button button(String text) {
        for (Control c : tab().controls()) {
            if (c instanceof Button b && b.getText().equals(text)) {
                return b;
            }
        }
        throw new AssertionError("the Robot tab has no button '" + text + "'");
    }

    /** Presses {@code b} as a click does (its selection listeners on the UI thread). */
    private static void press(Button b) {
        assertTrue(b.isEnabled(), "'" + b.getText() + "' is enabled");
        b.notifyListeners(org.eclipse.swt.SWT.Selection, new Event());
        Gui.settle();
    }

    /** Clicks the part {@code part} on the canvas (a press and a release where it is drawn). */
    private void clickPart(String part) {
        Point p = inSight(() -> tab().partPoint(part), part);
        press(p, 0);
        Gui.pump(() -> part.equals(tab().selectedPart()), part + " selected: " + tab().message());
    }

    /** Clicks the disc of free plate {@code part.plate} ({@code ctrl}: with Ctrl held, a second plate). */
    private void clickPlate(String part, int plate, boolean ctrl) {
        Point p = inSight(() -> tab().platePoint(part, plate), part + "." + plate);
        press(p, ctrl ? org.eclipse.swt.SWT.MOD1 : 0);
        Gui.pump(() -> tab().message().contains(part + "." + plate), part + "." + plate + " selected: " + tab().message());
    }

    /** The point {@code where} gives, the view framed on the robot and turned round it until it is clickable. */
    private Point inSight(java.util.function.Supplier<Point> where, String what) {
        tab().view().resetView();
        Gui.settle();
        for (int turn = 0; turn < 8 && where.get() == null; turn++) {
            tab().view().rotate(Math.PI / 4, 0);
            Gui.settle();
        }
        Point p = where.get();
        assertNotNull(p, what + " can be clicked");
        return p;
    }

    /** A press and a release of the left button at {@code p} on the canvas. */
    private void press(Point p, int stateMask) {
        for (int type : new int[] {org.eclipse.swt.SWT.MouseDown, org.eclipse.swt.SWT.MouseUp}) {
            Event e = new Event();
            e.button = 1;
            e.x = p.x;
            e.y = p.y;
            e.stateMask = stateMask;
            tab().view().control().notifyListeners(type, e);
        }
    }

    @Test
    void theTextAndTheTabFollowEachOtherAndUndoTakesATabEditBack() throws Exception {
        String text = Files.readString(Gui.example("configs/tee-snake.xml"));
        openCopy("tee.xml", text);
        assertEquals(-20, tab().draft().part("left").orElseThrow().angle());
        // typed in the text: the tab follows after the check
        String typed = text.replace("angle=\"-20\"", "angle=\"-35\"");
        int before = ide.validations();
        ide.editor.document().set(typed);
        Gui.pump(() -> ide.validations() > before, "the check of the edited text");
        assertEquals(-35, tab().draft().part("left").orElseThrow().angle(), "the tab shows the text as typed");
        // an edit in the tab changes one line of the text
        clickPart("t1");
        press(button("Turn 90\u00B0"));
        String after = ide.editor.document().get();
        List<String> a = typed.lines().toList();
        List<String> b = after.lines().toList();
        assertEquals(a.size(), b.size(), after);
        int changed = 0;
        for (int i = 0; i < a.size(); i++) {
            if (!a.get(i).equals(b.get(i))) {
                changed++;
                assertTrue(b.get(i).contains("to=\"t1.0\"") && b.get(i).contains("orientation=\"90\""), b.get(i));
            }
        }
        assertEquals(1, changed, "one line changed:\n" + after);
        assertEquals(after, tab().draft().text(), "the tab shows the text");
        // one Undo step
        press(button("Undo"));
        assertEquals(typed, ide.editor.document().get(), "Undo gives back the text before the edit");
        assertEquals(typed, tab().draft().text(), "and the tab shows it");
        press(button("Redo"));
        assertEquals(after, ide.editor.document().get());
    }

    /**
     * "Edit robot" opens a configuration wherever the user was: with the Diagram tab in front the
     * diagram of a robot configuration (no script, nothing to select) failed with an internal
     * error (a NullPointerException in the edit row), which the event loop of this test throws.
     */
    @Test
    void aConfigurationOpensWithTheDiagramTabInFront() throws Exception {
        ide.diagram.showTab();
        Gui.settle();
        Path f = dir.resolve("tee.xml");
        Files.writeString(f, Files.readString(Gui.example("configs/tee-snake.xml")));
        int before = ide.validations();
        Gui.open(ide, f);
        Gui.pump(() -> ide.validations() > before, "the check of the configuration");
        Gui.settle();
        assertEquals(0L, ide.problems().errorCount(), () -> ide.problems().shown().toString());
        tab().showTab();
        Gui.settle();
        assertEquals(8, tab().draft().partNames().size());
    }

    @Test
    void theKitLimitsTheBuilderAndConnectSaysHowFarApartThePlatesAre() throws Exception {
        Path kit = dir.resolve("kit.xml");
        Files.writeString(kit, "<kit>\n  <part type=\"segment\" count=\"3\"/>\n  <part type=\"foot\" count=\"1\"/>\n</kit>\n");
        openCopy("two.xml", String.join("\n", "<?xml version=\"1.0\" ?>", "<robot-config>",
                "  <part name=\"a\" type=\"segment\" id=\"0\"/>", "  <part name=\"b\" type=\"segment\" id=\"1\"/>",
                "  <connect from=\"a.1\" to=\"b.0\"/>", "</robot-config>", ""));
        tab().answerWith(new Outside.Questions() {
            @Override
            public Path saveRobotAs(Path proposed) {
                return null;
            }

            @Override
            public Path open(String title) {
                return kit;
            }
        });
        press(button("Kit\u2026"));
        assertTrue(tab().fitText().contains("1 segment") && tab().fitText().contains("1 foot"),
                "what the kit has left: " + tab().fitText());
        clickPlate("b", 1, false);
        press(button("Place"));
        Gui.pump(() -> tab().draft().partNames().size() == 3, "the third segment");
        assertTrue(tab().fitText().contains("0 segments"), tab().fitText());
        clickPlate("s0", 1, false);
        assertFalse(button("Place").isEnabled(), "no segment left in the kit");
        assertTrue(tab().message().contains("kit has no segment left"), tab().message());
        // two free plates of a straight chain do not meet: refused, saying how far apart
        clickPlate("a", 0, false);
        clickPlate("s0", 1, true);
        String before = ide.editor.document().get();
        press(button("Connect"));
        assertTrue(tab().message().contains("mm") && tab().message().contains("apart"), tab().message());
        assertEquals(before, ide.editor.document().get(), "nothing written");
    }

    /**
     * Connect's refusal says how far apart the plates are once, in the user's language: the tab
     * added the distance unless the refusal held the English word "apart", so in German it said
     * the distance twice (the builder's refusal, then "(die Platten sind … mm voneinander entfernt)").
     */
    @Test
    void connectSaysTheGapOnceInGerman() throws Exception {
        openCopy("two.xml", String.join("\n", "<?xml version=\"1.0\" ?>", "<robot-config>",
                "  <part name=\"a\" type=\"segment\" id=\"0\"/>", "  <part name=\"b\" type=\"segment\" id=\"1\"/>",
                "  <connect from=\"a.1\" to=\"b.0\"/>", "</robot-config>", ""));
        org.parpe.core.text.Lang.use(java.util.Locale.GERMAN);
        try {
            clickPlate("a", 0, false);
            clickPlate("b", 1, true);
            press(button("Connect"));
            assertTrue(tab().message().startsWith("die Platten liegen ") && tab().message().contains(" mm und ")
                    && !tab().message().contains("voneinander entfernt"), tab().message());
        } finally {
            org.parpe.core.text.Lang.use(java.util.Locale.ENGLISH);
        }
    }

    @Test
    void tryItRunsTheScriptLastOpenOnTheConfigurationInTheEditor() throws Exception {
        openCopy("wheel.xml", Files.readString(Gui.example("wheel.xml")));
        Gui.pump(() -> ide.program() != null, "the wheel script");
        Path robot = openCopy("wheel6.xml", Files.readString(Gui.example("configs/wheel6.xml")));
        assertTrue(button("Try it").isEnabled());
        press(button("Try it"));
        Gui.pump(() -> ide.runs.running() || ide.runs.lastOutcome() != null, "the run on the robot");
        assertTrue(tab().message().startsWith("Trying wheel.xml"), tab().message());
        Gui.pump(() -> ide.runs.snapshot() != null && ide.runs.snapshot().bodies().size() == tab().draft().bodies().size(),
                "the robot of " + robot.getFileName() + " in the 3D view");
        Gui.endRun(ide);
    }

    /**
     * A blank file (a declaration and a comment) is an empty script to the IDE (the status bar
     * says how to begin) and an empty robot to the tab: the first part writes the configuration
     * after what the file holds, as one Undo step.
     */
    @Test
    void aBlankFileStartsARobotKeepingItsComment() throws Exception {
        String blank = "<?xml version=\"1.0\"?>\n<!-- my first robot -->\n";
        openCopy("nothing.xml", blank);
        Gui.pump(() -> ide.status.message().startsWith("The file is empty"), "the status bar saying the file is empty");
        assertTrue(tab().draft().partNames().isEmpty());
        press(button("Place"));
        String text = ide.editor.document().get();
        assertTrue(text.startsWith(blank.strip() + "\n<robot-config>"), text);
        assertEquals(text.indexOf("<?xml"), text.lastIndexOf("<?xml"), "one declaration: " + text);
        assertEquals(1, tab().draft().partNames().size(), text);
        assertTrue(tab().draft().problems().isEmpty(), () -> tab().draft().problems().toString());
        press(button("Undo"));
        assertEquals(blank, ide.editor.document().get(), "one Undo step gives the blank file back");
    }

    @Test
    void aBadConfigurationIsLocatedInProblemsAndOnTheTabWithoutAnException() throws Exception {
        String text = String.join("\n", "<?xml version=\"1.0\" ?>", "<robot-config>",
                "  <part name=\"a\" type=\"segment\" id=\"0\"/>",
                "  <part name=\"b\" type=\"wing\"/>",
                "  <part name=\"c\" type=\"segment\" id=\"1\"/>",
                "  <connect from=\"a.1\" to=\"c.0\"/>",
                "  <connect from=\"a.1\" to=\"b.0\"/>",
                "  <root part=\"a\"/>", "</robot-config>", "");
        Path f = openCopy("bad.xml", text);
        Gui.pump(() -> ide.problems().errorCount() > 0, "the problems in Problems");
        List<Diagnostic> shown = ide.problems().shown();
        assertTrue(shown.stream().anyMatch(d -> d.pos().line() == 4 && d.format().contains("wing")),
                "the unknown type is located on its line: " + shown);
        for (Diagnostic d : shown) {
            assertTrue(d.pos().line() > 0 && d.pos().column() > 0 && Path.of(d.pos().file()).getFileName().equals(f.getFileName()),
                    "located in the file: " + d.format());
            assertFalse(d.format().contains("Exception"), d.format());
        }
        assertTrue(tab().fitText().contains("problem") && tab().fitText().contains(":4:"), "the tab says where: " + tab().fitText());
        assertTrue(ide.status.message().contains("error"), ide.status.message());
        // the window still answers
        long t0 = System.currentTimeMillis();
        Gui.settle();
        assertTrue(System.currentTimeMillis() - t0 < 5000);
    }

    @Test
    void aScriptsRobotIsReadOnlyWithItsLatchPlatesMarkedAndMakeEditableWritesItBeside() throws Exception {
        Path script = openCopy("docking-snake-loop.xml", Files.readString(Gui.example("docking-snake-loop.xml")));
        Gui.pump(() -> ide.program() != null && tab().draft() != null, "the script and its robot");
        assertEquals(10, tab().draft().config().moduleIds().length, "auto's snake of the script's ten modules");
        assertFalse(button("Place").isEnabled(), "read-only");
        assertFalse(tab().latchingParts().isEmpty(), "the end modules' plates are marked: they can latch");
        assertEquals(2, tab().latchingParts().size(), tab().latchingParts().toString());
        Path target = dir.resolve("docking-snake-loop-robot.xml");
        tab().answerWith(new Outside.Questions() {
            @Override
            public Path saveRobotAs(Path proposed) {
                assertEquals(target, proposed, "proposed beside the script");
                return proposed;
            }

            @Override
            public Path open(String title) {
                return null;
            }
        });
        press(button("Make editable\u2026"));
        assertTrue(Files.isRegularFile(target), "written");
        assertEquals(target.toString(), ide.robotChoice(), "the script's robot is the file now");
        assertTrue(button("Edit robot").isEnabled());
        press(button("Edit robot"));
        Gui.pump(() -> target.equals(ide.files.file()), "the robot's file in the editor");
        Gui.pump(() -> button("Place").isEnabled() || tab().draft().text().equals(ide.editor.document().get()), "the tab on the file");
        assertEquals(Files.readString(target), tab().draft().text());
        assertTrue(script.toFile().exists());
    }

    @Test
    void everyControlIsInTheWindowAt1366x768AndAtTwiceTheTextSize() throws Exception {
        openCopy("tee.xml", Files.readString(Gui.example("configs/tee-snake.xml")));
        allInside("normal text");
        Gui.screenshot(ide.shell, "robot-tab-1366x768.png");
        Control probe = tab().controls().get(0);
        int normal = probe.getFont().getFontData()[0].getHeight();
        while (probe.getFont().getFontData()[0].getHeight() < 2 * normal) {
            ide.zoom(1);
        }
        Gui.settle();
        Gui.screenshot(ide.shell, "robot-tab-zoom-200.png");
        allInside("twice the text");
        Path out = Path.of(System.getProperty("parpe.ideImages", "../docs/images/ide"));
        Files.createDirectories(out);
        org.parpe.gui.automation.Screenshot.save(ide.shell, out.resolve("robot-zoom-200.png"));
    }

    /**
     * Every control of the tab, brought into sight (the rows scroll when the text is large), is
     * visible, at least 8 px each way, and wholly inside the window, the tab and the part of the
     * rows' box in sight.
     */
    private void allInside(String when) {
        Rectangle window = ide.shell.getClientArea();
        Rectangle windowOnScreen = ide.shell.getDisplay().map(ide.shell, null, window);
        Rectangle tabArea = tab().control().getDisplay().map(tab().control(), null, ((org.eclipse.swt.widgets.Composite) tab().control()).getClientArea());
        for (Control c : tab().controls()) {
            if (c instanceof org.eclipse.swt.widgets.Label l && (l.getStyle() & org.eclipse.swt.SWT.WRAP) != 0 && l.getText().isEmpty()) {
                continue; // an empty line under the view takes no room
            }
            tab().reveal(c);
            Gui.settle();
            Rectangle r = c.getDisplay().map(c.getParent(), null, c.getBounds());
            for (Control up = c.getParent(); up != tab().control(); up = up.getParent()) {
                Rectangle seen = c.getDisplay().map(up, null, ((org.eclipse.swt.widgets.Composite) up).getClientArea());
                assertTrue(seen.contains(r.x, r.y) && seen.contains(r.x + r.width - 1, r.y + r.height - 1),
                        when + ": " + c + " at " + r + " is in sight in " + up + " " + seen);
            }
            String what = when + ": " + c + " at " + r;
            assertTrue(c.isVisible(), what + " is visible");
            assertTrue(r.width >= 8 && r.height >= 8, what + " has room");
            assertTrue(windowOnScreen.contains(r.x, r.y) && windowOnScreen.contains(r.x + r.width - 1, r.y + r.height - 1),
                    what + " is inside the window " + windowOnScreen);
            assertTrue(tabArea.contains(r.x, r.y) && tabArea.contains(r.x + r.width - 1, r.y + r.height - 1),
                    what + " is inside the tab " + tabArea);
        }
        Rectangle canvas = tab().view().control().getBounds();
        assertTrue(canvas.height >= 150 && canvas.width >= 250, when + ": the 3D view keeps room: " + canvas);
    }
}
