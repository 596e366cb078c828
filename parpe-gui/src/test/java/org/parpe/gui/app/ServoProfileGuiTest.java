package org.parpe.gui.app;


import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import org.eclipse.swt.widgets.Display;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.run.Speed;
import org.parpe.gui.run.RunOn;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.link.PtyPair;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.emu.ServoEmulator;

/**
 * The IDE's Hardware target with a hardware profile: errors of the profile reach the Problems
 * view at their lines, and a run drives emulated Dynamixel servos over a socat pty. Real widgets
 * under Xvfb, bounded waits.
 */
class ServoProfileGuiTest {
    private static final long WAIT_MS = 30_000;
    private static final String SCRIPT = "<program>\n<robot><structure><body elements=\"0..1\"/></structure></robot>\n"
            + "<main><b/></main>\n<behaviors><b><w group=\"body\"/></b></behaviors>\n"
            + "<automata><w states=\"s, t\"/></automata>\n"
            + "<states>\n<s angles=\"30\"/>\n<t angles=\"30\"/></states>\n</program>\n";
    private static Display display;
    private static IdeWindow ide;
    private static Path dir;

    @BeforeAll
    static void openWindow() throws Exception {
        display = Gui.display();
        dir = Files.createTempDirectory("parpe-servo-gui");
        ide = Gui.openIde(dir.resolve("home"));
    }

    @AfterAll
    static void closeWindow() {
        if (ide != null && !ide.shell.isDisposed()) {
            ide.runs.stop();
            ide.shell.dispose();
        }
    }

    /**
     * A test that fails half-way must not leave its run going: the alarm test's 600 s run, left
     * running by a failed assertion, made the next test's run wait 30 s and fail too.
     */
    @AfterEach
    void backToTheSimulator() {
        if (ide.runs.running()) {
            ide.runs.stop();
            pump(() -> !ide.runs.running(), "the run left by the test to stop");
        }
        ide.toolbar.setHardwareProfile("");
        ide.toolbar.setPort("");
        ide.toolbar.setTarget(RunOn.SIMULATOR);
    }

    private static void pump(BooleanSupplier done, String what) {
        Gui.pump(done, what, WAIT_MS);
    }

    private static void open() throws Exception {
        Path f = dir.resolve("two.xml");
        Files.writeString(f, SCRIPT);
        int before = ide.validations();
        ide.files.openPath(f);
        pump(() -> ide.validations() > before && ide.program() != null, "the script to load");
    }

    private static RunOutcome runToEnd(double seconds) {
        AtomicReference<RunOutcome> outcome = new AtomicReference<>();
        ide.toolbar.setSpeed(Speed.MAX);
        ide.runs.run(false, seconds, outcome::set);
        pump(() -> outcome.get() != null, "the run to end");
        pump(() -> !display.readAndDispatch(), "pending UI events");
        return outcome.get();
    }

    @Test
    void profileErrorsAreProblemsAtTheirLines() throws Exception {
        open();
        Path profile = dir.resolve("bad-profile.xml");
        Files.writeString(profile, "<hardware protocol=\"dxl2\" port=\"/dev/null\">\n  <servo module=\"0\" id=\"999\"/>\n"
                + "</hardware>\n");
        ide.toolbar.setTarget(RunOn.HARDWARE);
        ide.toolbar.setHardwareProfile(profile.toString());
        RunOutcome o = runToEnd(1);
        assertEquals(RunOutcome.Status.ERROR, o.status());
        List<Diagnostic> errors = ide.problems().shown().stream().filter(d -> d.severity() == Severity.ERROR).toList();
        assertTrue(errors.stream().anyMatch(d -> d.pos().file().equals(profile.toString()) && d.pos().line() == 2
                && d.message().equals("id must be in 0..252, got 999")), errors.toString());
    }

    @Test
    void aRunDrivesDynamixelServosOfTheProfile() throws Exception {
        assumeTrue(PtyPair.available(), "socat is not installed");
        open();
        try (PtyPair pty = PtyPair.start(dir.resolve("a"), dir.resolve("b"));
             ServoEmulator emu = ServoEmulator.start(LinkOpener.serial(pty.b().toString(), 1_000_000),
                     ServoModel.named("xl430-w250"), EmulatorOptions.of(5, 6), new EmulatorListener() { })) {
            Path profile = dir.resolve("profile.xml");
            Files.writeString(profile, "<hardware protocol=\"dxl2\" baud=\"1000000\">\n"
                    + "  <servo module=\"0\" id=\"5\" zero=\"10\"/>\n  <servo module=\"1\" id=\"6\" direction=\"-1\"/>\n"
                    + "</hardware>\n");
            ide.toolbar.setTarget(RunOn.HARDWARE);
            ide.toolbar.setHardwareProfile(profile.toString());
            ide.toolbar.setPort(pty.a().toString());
            RunOutcome o = runToEnd(1);
            assertEquals(RunOutcome.Status.COMPLETED, o.status(), o.message() + " " + ide.problems().shown());
            Thread.sleep(300);
            assertEquals(40, emu.angle(5), 0.1, "module 0 at 30° through zero 10");
            assertEquals(-30, emu.angle(6), 0.1, "module 1 at 30° turned the other way");
        }
    }

    @Test
    void aRobotThatStopsAnsweringRaisesTheAlarm() throws Exception {
        // The status bar used to keep saying all was well while the servos had been silent for a
        // minute, and Stop reported "emergency stop sent" into the silence.
        assumeTrue(PtyPair.available(), "socat is not installed");
        open();
        try (PtyPair pty = PtyPair.start(dir.resolve("c"), dir.resolve("d"))) {
            ServoEmulator emu = ServoEmulator.start(LinkOpener.serial(pty.b().toString(), 1_000_000),
                    ServoModel.named("xl430-w250"), EmulatorOptions.of(5, 6), new EmulatorListener() { });
            Path profile = dir.resolve("alarm.xml");
            Files.writeString(profile, "<hardware protocol=\"dxl2\" baud=\"1000000\">\n"
                    + "  <servo module=\"0\" id=\"5\"/>\n  <servo module=\"1\" id=\"6\"/>\n</hardware>\n");
            ide.toolbar.setTarget(RunOn.HARDWARE);
            ide.toolbar.setHardwareProfile(profile.toString());
            ide.toolbar.setPort(pty.a().toString());
            AtomicReference<RunOutcome> outcome = new AtomicReference<>();
            ide.runs.run(false, 600, outcome::set);
            pump(() -> ide.status.hardware().startsWith("Hardware: " + pty.a()), "the run to drive the servos");
            assertFalse(ide.status.hardwareAlarm());
            emu.close();
            pump(() -> ide.status.hardwareAlarm(), "the hardware alarm");
            assertTrue(ide.status.hardware().matches("Hardware: robot not responding since \\d\\d:\\d\\d:\\d\\d"),
                    ide.status.hardware());
            assertTrue(ide.status.message().startsWith("Robot not responding since "), ide.status.message());
            // and a banner across the window says it, to be seen from across a classroom
            String banner = ide.alarm.shown();
            assertNotNull(banner, "no banner while the robot does not answer");
            assertTrue(banner.startsWith("Robot not responding since "), banner);
            Gui.settle();
            Gui.screenshot(ide.shell, "robot-not-responding.png");
            Gui.screenshot(ide.shell, "hardware-alarm.png");
            ide.runs.stop();
            pump(() -> outcome.get() != null, "the run to stop");
            pump(() -> ide.problems().shown().stream().anyMatch(d ->
                    d.message().startsWith("emergency stop sent but not confirmed")), "the stop said unconfirmed");
            pump(() -> !ide.status.hardwareAlarm(), "the alarm to end with the run");
            pump(() -> ide.alarm.shown() == null, "the banner to go with the alarm");
        }
    }
}
