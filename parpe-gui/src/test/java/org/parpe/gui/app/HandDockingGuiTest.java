package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicReference;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Shell;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.run.RunOn;
import org.parpe.gui.run.Speed;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.link.PtyPair;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.emu.ServoEmulator;

/**
 * Docking on servos without latches (PARSL.md §14: "the user must join or part those plates by
 * hand"): the IDE's hardware run pauses at a plate action and asks; Continue goes on. Emulated
 * Dynamixel servos over a socat pty, real widgets under Xvfb, bounded waits.
 */
class HandDockingGuiTest {
    /** Module 1 arms its plate 1 on entering grab (t = 0) and releases it on entering let_go (t = 0.3 s). */
    private static final String SCRIPT = "<program>\n<robot><structure><body elements=\"0\"/><tip elements=\"1\"/>"
            + "</structure>\n<actuators><latch elements=\"tip\"/></actuators></robot>\n"
            + "<main><b time=\"0.6\"/></main>\n<behaviors><b><hold group=\"body\"/><dock group=\"tip\"/></b></behaviors>\n"
            + "<automata><hold states=\"s\"/><dock states=\"grab, let_go\" times=\"0.3, 10\"/></automata>\n"
            + "<states>\n<s angles=\"10\"/>\n<grab angles=\"10\" latch=\"1\"/>\n<let_go angles=\"10\" unlatch=\"1\"/>\n"
            + "</states>\n</program>\n";
    private static Display display;
    private static IdeWindow ide;
    private static Path dir;

    @BeforeAll
    static void openWindow() throws Exception {
        display = Gui.display();
        dir = Files.createTempDirectory("parpe-hand-docking");
        ide = Gui.openIde(dir.resolve("home"));
    }

    @AfterAll
    static void closeWindow() {
        Gui.closeIde(ide);
    }

    /** The open question, or null. */
    private static Shell question() {
        return Arrays.stream(display.getShells()).filter(s -> !s.isDisposed() && s.isVisible()
                && HandDocking.title().equals(s.getText())).findFirst().orElse(null);
    }

    private static String text(Composite c) {
        StringBuilder b = new StringBuilder();
        for (Control k : c.getChildren()) {
            if (k instanceof Label l) {
                b.append(l.getText()).append('\n');
            } else if (k instanceof Composite inner) {
                b.append(text(inner));
            }
        }
        return b.toString();
    }

    private static void press(Composite c, String label) {
        for (Control k : c.getChildren()) {
            if (k instanceof Button b && b.getText().equals(label)) {
                b.notifyListeners(SWT.Selection, new org.eclipse.swt.widgets.Event());
                return;
            }
            if (k instanceof Composite inner) {
                press(inner, label);
            }
        }
    }

    /** Waits for the question, checks the run waits for it and what it asks, and presses Continue. */
    private static void answer(String expected, String screenshot) throws Exception {
        Gui.pump(() -> question() != null, "the question: " + expected);
        Shell q = question();
        assertNotNull(q);
        String asked = text(q);
        assertTrue(asked.contains(expected), asked);
        assertTrue(ide.runs.controller().paused(), "the run is paused while the question is open");
        long tick = ide.runs.controller().engine().tick();
        Gui.settle();
        assertEquals(tick, ide.runs.controller().engine().tick(), "the run waits for the answer");
        Gui.screenshot(ide.shell, screenshot); // the window: paused, Resume offered, the status line says why
        org.parpe.gui.automation.Screenshot.save(q, Path.of(System.getProperty("parpe.artefacts",
                "target/gui-test-artefacts"), "question-" + screenshot));
        press(q, "Continue");
        Gui.pump(() -> q.isDisposed(), "the question to close");
        Gui.pump(() -> !ide.runs.controller().paused() || !ide.runs.running(), "the run to go on");
    }

    @Test
    void aHardwareRunAsksForTheHandsAndWaits() throws Exception {
        assumeTrue(PtyPair.available(), "socat is not installed");
        Path script = dir.resolve("dock.xml");
        Files.writeString(script, SCRIPT);
        int before = ide.validations();
        ide.files.openPath(script);
        Gui.pump(() -> ide.validations() > before && ide.program() != null, "the script to load");
        assertEquals(0L, ide.problems().errorCount(), () -> "problems: " + ide.problems().shown());
        try (PtyPair pty = PtyPair.start(dir.resolve("a"), dir.resolve("b"));
             ServoEmulator emu = ServoEmulator.start(LinkOpener.serial(pty.b().toString(), 1_000_000),
                     ServoModel.named("xl430-w250"), EmulatorOptions.of(5, 6), new EmulatorListener() { })) {
            Path profile = dir.resolve("profile.xml");
            Files.writeString(profile, "<hardware protocol=\"dxl2\" baud=\"1000000\">\n"
                    + "  <servo module=\"0\" id=\"5\"/>\n  <servo module=\"1\" id=\"6\"/>\n</hardware>\n");
            ide.toolbar.setTarget(RunOn.HARDWARE);
            ide.toolbar.setHardwareProfile(profile.toString());
            ide.toolbar.setPort(pty.a().toString());
            ide.toolbar.setSpeed(Speed.MAX);
            AtomicReference<RunOutcome> outcome = new AtomicReference<>();
            ide.runs.run(false, -1, outcome::set);
            answer("arms plate 1 of module 1: join that plate to the plate it meets", "hand-docking-join.png");
            answer("releases plate 1 of module 1: part that plate from the one it holds", "hand-docking-part.png");
            Gui.pump(() -> outcome.get() != null, "the run to end");
            assertEquals(RunOutcome.Status.COMPLETED, outcome.get().status(), outcome.get().message());
            assertEquals(0.6, outcome.get().time(), 0.02);
        } finally {
            ide.toolbar.setHardwareProfile("");
            ide.toolbar.setPort("");
            ide.toolbar.setTarget(RunOn.SIMULATOR);
        }
    }
}
