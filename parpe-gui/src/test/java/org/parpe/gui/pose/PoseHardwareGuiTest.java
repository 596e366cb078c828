package org.parpe.gui.pose;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Scale;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.link.PtyPair;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.emu.ServoEmulator;

/**
 * Posing by hand: two emulated Dynamixel servos on a socat pty, connected in Run > Hardware…
 * (no profile: servo ID = module ID, the middle of the range is 0°). "Robot (limp)" makes the
 * group limp, the servos are turned by hand (back-driven in the emulator), Capture reads their
 * angles; back on the simulator, "Real robot follows" sends the sliders to the servos.
 */
class PoseHardwareGuiTest {
    private static IdeWindow ide;
    private static Path dir;

    @BeforeAll
    static void openWindow() throws Exception {
        dir = Files.createTempDirectory("parpe-pose-hw");
        ide = IdeAccess.openIde(dir.resolve("home"));
    }

    @AfterAll
    static void closeWindow() {
        IdeAccess.closeIde(ide);
    }

    private static void press(PosePanel panel, String text) {
        Button b = panel.button(text);
        assertNotNull(b, "no button " + text);
        if ((b.getStyle() & SWT.CHECK) != 0) {
            b.setSelection(!b.getSelection());
        }
        b.notifyListeners(SWT.Selection, new Event());
    }

    @Test
    void capturesAPoseMadeByHandAndTheRobotFollowsTheSliders() throws Exception {
        assumeTrue(PtyPair.available(), "socat is not installed");
        Path script = dir.resolve("arm-snake.xml");
        Files.writeString(script, """
                <?xml version="1.0"?>
                <!-- a two-module arm on servos 1 and 2 -->
                <program><robot><structure><arm elements="1, 2"/></structure></robot></program>
                """);
        try (PtyPair pty = PtyPair.start(dir.resolve("a"), dir.resolve("b"));
             ServoEmulator emu = ServoEmulator.start(LinkOpener.serial(pty.b().toString(), 1_000_000),
                     ServoModel.named("xl430-w250"), EmulatorOptions.of(1, 2), new EmulatorListener() { })) {
            IdeAccess.open(ide, script);
            IdeAccess.pump(() -> IdeAccess.program(ide) != null && IdeAccess.program(ide).group("arm").isPresent(), "the arm to load");
            IdeAccess.showPosePanel(ide);
            PosePanel panel = IdeAccess.pose(ide);
            panel.pollNow();
            panel.chooseGroup("arm");
            IdeAccess.connectHardware(ide, pty.a().toString(), "dxl2", 1_000_000, 2);

            panel.source().select(1);
            panel.source().notifyListeners(SWT.Selection, new Event());
            IdeAccess.pump(() -> emu.isLimp(1) && emu.isLimp(2), "the arm's servos to go limp");
            assertTrue(emu.backDrive(1, 30) && emu.backDrive(2, -45), "the emulated servos should turn by hand when limp");
            // The dialog reads the positions a few times a second.
            // The dialog reads the positions a few times a second: capture until a reading after the turn arrives.
            boolean captured = false;
            for (int attempt = 0; attempt < 60 && !captured; attempt++) {
                IdeAccess.settle();
                captured = panel.capture() && panel.poses().get(panel.poses().size() - 1).angles()[1] < -44;
            }
            assertTrue(captured, "no capture of the hand-made pose; the panel says: " + IdeAccess.status(ide)
                    + (panel.poses().size() == 0 ? "" : "; last pose " + java.util.Arrays.toString(
                            panel.poses().get(panel.poses().size() - 1).angles())));
            double[] got = panel.poses().get(panel.poses().size() - 1).angles();
            assertArrayEquals(new double[] {30, -45}, got, 0.2);
            assertEquals(30, panel.sliders().angle(1), 0.2, "the sliders (and the simulated arm) take the captured pose");

            panel.source().select(0);
            panel.source().notifyListeners(SWT.Selection, new Event());
            IdeAccess.pump(() -> !emu.isLimp(1) && !emu.isLimp(2), "the arm to hold again");
            press(panel, "Real robot follows");
            Scale s = panel.sliders().scale(2);
            s.setSelection(90 + 10);
            s.notifyListeners(SWT.Selection, new Event());
            IdeAccess.pump(() -> Math.abs(emu.angle(2) - 10) < 0.2, "servo 2 to follow its slider to 10°");
            IdeAccess.screenshot(IdeAccess.shell(ide), "pose-panel-hardware.png");
            IdeAccess.closeHardware(ide);
        }
    }
}
