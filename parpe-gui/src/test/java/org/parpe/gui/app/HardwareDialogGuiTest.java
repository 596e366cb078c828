package org.parpe.gui.app;

import org.parpe.gui.hardware.HardwareDialog;
import org.parpe.gui.hardware.HardwareSession;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicReference;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Event;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.run.RunOn;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.link.PtyPair;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.emu.ServoEmulator;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ProfileReader;

/**
 * Run → Hardware… against three emulated Dynamixel servos on a socat pty: connect, see them, limp
 * one, jog one, save a profile that loads and becomes the tool bar's profile, and close (the bus
 * with it). Real widgets under Xvfb, bounded waits, a screenshot as evidence.
 */
class HardwareDialogGuiTest {
    private static IdeWindow ide;
    private static Path dir;

    @BeforeAll
    static void openWindow() throws Exception {
        dir = Files.createTempDirectory("parpe-hw-dialog");
        ide = Gui.openIde(dir.resolve("home"));
    }

    @AfterAll
    static void closeWindow() {
        Gui.closeIde(ide);
    }

    private static Button button(Composite parent, String text) {
        for (Control c : parent.getChildren()) {
            if (c instanceof Button b && b.getText().equals(text)) {
                return b;
            }
            if (c instanceof Composite k) {
                Button b = button(k, text);
                if (b != null) {
                    return b;
                }
            }
        }
        return null;
    }

    private static org.eclipse.swt.widgets.Combo combo(Control parent, String item) {
        if (parent instanceof org.eclipse.swt.widgets.Combo c && c.indexOf(item) >= 0) {
            return c;
        }
        if (parent instanceof Composite k) {
            for (Control c : k.getChildren()) {
                org.eclipse.swt.widgets.Combo found = combo(c, item);
                if (found != null) {
                    return found;
                }
            }
        }
        return null;
    }

    private static void click(HardwareDialog d, String text) {
        Button b = button(d.shell(), text);
        assertNotNull(b, "no button " + text);
        b.notifyListeners(SWT.Selection, new Event());
    }

    private static final java.util.List<double[]> goals = new java.util.concurrent.CopyOnWriteArrayList<>();

    @Test
    void findLimpJogAndSaveServos() throws Exception {
        assumeTrue(PtyPair.available(), "socat is not installed");
        try (PtyPair pty = PtyPair.start(dir.resolve("a"), dir.resolve("b"));
             ServoEmulator emu = ServoEmulator.start(LinkOpener.serial(pty.b().toString(), 1_000_000),
                     ServoModel.named("xl430-w250"), EmulatorOptions.of(1, 2, 3), new EmulatorListener() {
                        @Override
                        public void onSetpoints(int seq, double[] angles) {
                            goals.add(angles.clone());
                        }
                    })) {
            assertTrue(emu.backDrive(3, 25));
            // Posing by hand with the dialog open: the Pose panel is shown.
            ide.bottom.showPose();
            Gui.settle();
            HardwareDialog d = HardwareDialog.open(ide.hardware);
            assertTrue(d == HardwareDialog.open(ide.hardware), "a second Run > Hardware… brings the same dialog");
            d.widgets().port().setText(pty.a().toString());
            // Scan tries every protocol and rate; a pty ignores the rate, so Dynamixel's factory 57 600 answers.
            click(d, "Scan");
            Gui.pump(() -> d.widgets().table().getItemCount() == 3, "the scan to find three servos");
            assertTrue(d.widgets().message().getText().contains("dxl2 at 57600 baud"), d.widgets().message().getText());
            // After the scan the boxes say what it found (they used to stay "any").
            assertEquals("dxl2", d.widgets().protocol().getText());
            assertEquals("57600", d.widgets().baud().getText());
            // Placed over the IDE window, not at the screen's corner over the menu.
            assertTrue(d.shell().getLocation().x > ide.shell.getLocation().x
                    && d.shell().getLocation().y > ide.shell.getLocation().y, d.shell().getLocation().toString());
            // Kept open, it leaves the Pose panel's Capture button free.
            Button capture = button((Composite) ide.pose.control(), "&Capture");
            assertNotNull(capture);
            org.eclipse.swt.graphics.Rectangle at = capture.getDisplay().map(capture.getParent(), null, capture.getBounds());
            assertTrue(at.width > 0 && at.height > 0, "the Capture button is laid out: " + at);
            assertFalse(d.shell().getBounds().intersects(at), d.shell().getBounds() + " covers Capture at " + at);
            d.widgets().protocol().select(d.widgets().protocol().indexOf("dxl2"));
            d.widgets().baud().setText("1000000");
            click(d, "Connect");
            Gui.pump(() -> d.widgets().table().getItemCount() == 3, "three servos in the table");
            assertEquals("1", d.widgets().table().getItem(0).getText(0));
            assertEquals("xl430-w250 (1060)", d.widgets().table().getItem(0).getText(1));
            String status = "Hardware: 3 servos connected (DXL2, " + pty.a() + ")";
            Gui.pump(() -> ide.status.hardware().equals(status), "the status bar to say " + status);

            d.widgets().table().setSelection(1);
            d.widgets().table().notifyListeners(SWT.Selection, new Event());
            click(d, "Limp");
            Gui.pump(() -> emu.isLimp(2), "servo 2 to go limp");
            Gui.pump(() -> d.widgets().table().getItem(1).getText(3).equals("limp"), "the table to show servo 2 limp");

            d.widgets().table().setSelection(2);
            d.widgets().table().notifyListeners(SWT.Selection, new Event());
            Gui.pump(() -> d.widgets().jogBox().isEnabled(), "the jog box for servo 3");
            // The jog box starts at the servo's position (25°), not at 0° or the range's end: the
            // old slider started at 0° and one click on its trough drove a servo from 25° to 81.8°.
            assertEquals(250, d.widgets().jogBox().getSelection());
            assertEquals(10, d.widgets().jogBox().getIncrement(), "one arrow click: 1°");
            // Without a profile the number box keeps to the limits a starter profile writes, ±90°
            // (issue 31: it offered the model's whole range, to 179.9°).
            assertEquals(900, d.widgets().jogBox().getMaximum());
            assertEquals(-900, d.widgets().jogBox().getMinimum());
            assertEquals("starter limits -90.0\u00b0..90.0\u00b0", d.widgets().jogValue().getText());
            // One arrow click: 26°.
            d.widgets().jogBox().setSelection(d.widgets().jogBox().getSelection() + d.widgets().jogBox().getIncrement());
            d.widgets().jogBox().notifyListeners(SWT.Selection, new Event());
            Gui.pump(() -> Math.abs(emu.angle(3) - 26) < 0.2, "servo 3 to move 1° to 26°");
            // A typed 81.8° is reached at a limited speed: goals a small step apart, never a jump.
            goals.clear();
            d.widgets().jogBox().setSelection(818);
            d.widgets().jogBox().notifyListeners(SWT.DefaultSelection, new Event());
            Gui.pump(() -> Math.abs(emu.angle(3) - 81.8) < 0.2, "servo 3 to reach the typed 81.8°");
            double previous = 26;
            for (double[] g : goals) {
                if (!Double.isNaN(g[2])) {
                    assertTrue(Math.abs(g[2] - previous) <= HardwareSession.JOG_DEG_PER_S
                            * HardwareSession.JOG_TICK_MS / 1000.0 + 0.1, "a goal step from " + previous + " to " + g[2]);
                    previous = g[2];
                }
            }
            assertEquals(81.8, previous, 0.1);
            Gui.pump(() -> d.widgets().table().getItem(2).getText(2).equals("81.8\u00b0"), "the table to show 81.8° for servo 3");
            Gui.settle();
            Gui.screenshot(d.shell(), "hardware-dialog.png");

            Path profile = dir.resolve("saved.xml");
            d.saveProfile(profile);
            Gui.pump(() -> profile.toString().equals(ide.toolbar.hardwareProfile()), "the profile to be selected");
            DiagnosticList problems = new DiagnosticList();
            HardwareProfile p = ProfileReader.read(profile, problems);
            assertNotNull(p, problems.all().toString());
            assertEquals(ServoProtocol.DXL2, p.protocol());
            assertEquals(1_000_000, p.baud());
            assertEquals(pty.a().toString(), p.port());
            assertEquals(3, p.servos().size());
            assertEquals(3, p.servos().get(2).servo());

            // Issue 20, item 10: with a profile on the tool bar the jog keeps to the joint's limits
            // (servo angle = zero + direction * joint), not only to the model's range.
            Path limited = dir.resolve("limited.xml");
            Files.writeString(limited, "<hardware protocol=\"dxl2\" port=\"" + pty.a() + "\" baud=\"1000000\">\n"
                    + "  <servo module=\"0\" id=\"3\" model=\"xl430-w250\" zero=\"10\" direction=\"-1\" min=\"-60\" max=\"5\"/>\n"
                    + "</hardware>\n");
            ide.toolbar.setHardwareProfile(limited.toString());
            d.widgets().table().setSelection(2);
            d.widgets().table().notifyListeners(SWT.Selection, new Event());
            Gui.pump(() -> d.widgets().jogBox().isEnabled(), "the jog box for servo 3 again");
            assertEquals(50, d.widgets().jogBox().getMinimum(), "servo angle of joint max 5°: 10 - 5 = 5°");
            assertEquals(700, d.widgets().jogBox().getMaximum(), "servo angle of joint min -60°: 10 + 60 = 70°");
            assertEquals(700, d.widgets().jogBox().getSelection(), "servo 3 at 81.8° shows the nearest allowed angle");
            assertTrue(d.widgets().jogValue().getText().startsWith("module 0's limits 5"), d.widgets().jogValue().getText());
            ide.toolbar.setHardwareProfile(profile.toString());

            Gui.open(ide, Gui.example("hello-snake.xml"));
            ide.toolbar.setTarget(RunOn.HARDWARE);
            AtomicReference<RunOutcome> outcome = new AtomicReference<>();
            ide.runs.run(false, 1, outcome::set);
            ide.toolbar.setTarget(RunOn.SIMULATOR);
            assertNotNull(outcome.get(), "a hardware run is refused at once while the dialog holds the bus");
            assertEquals(RunOutcome.Status.ERROR, outcome.get().status());
            assertTrue(outcome.get().message().contains("Hardware dialog holds the bus"), outcome.get().message());

            org.eclipse.swt.widgets.Combo source = combo(ide.pose.control(), "Robot (limp)");
            assertNotNull(source, "the Pose panel's source box");
            source.select(1);
            source.notifyListeners(SWT.Selection, new Event());
            assertTrue(ide.pose.posingTheRobot(), "posing the connected robot");
            click(d, "Close");
            Gui.pump(() -> d.shell().isDisposed(), "the dialog to close");
            // It used to stay on "Robot (limp)" with nothing connected.
            assertFalse(ide.pose.posingTheRobot(), "the Pose panel no longer poses a robot that is gone");
            assertTrue(ide.hardware.hardwareDialog().session().awaitClosed(5000), "the bus thread ends");
            Gui.pump(() -> !ide.status.hardware().contains("connected ("), "the status bar to drop the dialog's bus");
        }
    }

    @Test
    void aMissingPortIsSaidInWords() {
        HardwareDialog d = HardwareDialog.open(ide.hardware);
        d.widgets().port().setText(dir.resolve("no-such-port").toString());
        d.widgets().protocol().select(d.widgets().protocol().indexOf("sts"));
        d.widgets().baud().setText("1000000");
        click(d, "Connect");
        Gui.pump(() -> d.widgets().message().getText().contains("does not exist"), "the dialog to say the port does not exist");
        assertFalse(d.widgets().message().getText().contains("Exception"), d.widgets().message().getText());
        d.shell().close();
        Gui.pump(() -> d.shell().isDisposed(), "the dialog to close");
    }
}
