package org.parpe.gui.app;

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
import org.parpe.gui.run.Target;
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

    private static void click(HardwareDialog d, String text) {
        Button b = button(d.shell(), text);
        assertNotNull(b, "no button " + text);
        b.notifyListeners(SWT.Selection, new Event());
    }

    @Test
    void findLimpJogAndSaveServos() throws Exception {
        assumeTrue(PtyPair.available(), "socat is not installed");
        try (PtyPair pty = PtyPair.start(dir.resolve("a"), dir.resolve("b"));
             ServoEmulator emu = ServoEmulator.start(LinkOpener.serial(pty.b().toString(), 1_000_000),
                     ServoModel.named("xl430-w250"), EmulatorOptions.of(1, 2, 3), new EmulatorListener() { })) {
            HardwareDialog d = HardwareDialog.open(ide);
            assertTrue(d == HardwareDialog.open(ide), "a second Run > Hardware… brings the same dialog");
            d.portBox().setText(pty.a().toString());
            // Scan tries every protocol and rate; a pty ignores the rate, so Dynamixel's factory 57 600 answers.
            click(d, "Scan");
            Gui.pump(() -> d.table().getItemCount() == 3, "the scan to find three servos");
            assertTrue(d.message().contains("dxl2 at 57600 baud"), d.message());
            d.protocolBox().select(d.protocolBox().indexOf("dxl2"));
            d.baudBox().setText("1000000");
            click(d, "Connect");
            Gui.pump(() -> d.table().getItemCount() == 3, "three servos in the table");
            assertEquals("1", d.table().getItem(0).getText(0));
            assertEquals("xl430-w250 (1060)", d.table().getItem(0).getText(1));
            String status = "Hardware: 3 servos connected (DXL2, " + pty.a() + ")";
            Gui.pump(() -> ide.status().hardware().equals(status), "the status bar to say " + status);

            d.table().setSelection(1);
            d.table().notifyListeners(SWT.Selection, new Event());
            click(d, "Limp");
            Gui.pump(() -> emu.isLimp(2), "servo 2 to go limp");
            Gui.pump(() -> d.table().getItem(1).getText(3).equals("limp"), "the table to show servo 2 limp");

            d.table().setSelection(2);
            d.table().notifyListeners(SWT.Selection, new Event());
            assertTrue(d.slider().isEnabled());
            // The slider counts tenths of a degree from the model's lowest angle (−180°): 30° is 2100.
            d.slider().setSelection(2100);
            d.slider().notifyListeners(SWT.Selection, new Event());
            Gui.pump(() -> Math.abs(emu.angle(3) - 30) < 0.2, "servo 3 to reach the jogged 30°");
            Gui.pump(() -> d.table().getItem(2).getText(2).equals("30.0\u00b0"), "the table to show 30.0° for servo 3");
            Gui.settle();
            Gui.screenshot(d.shell(), "hardware-dialog.png");

            Path profile = dir.resolve("saved.xml");
            d.saveProfile(profile);
            Gui.pump(() -> profile.toString().equals(ide.toolbar().hardwareProfile()), "the profile to be selected");
            DiagnosticList problems = new DiagnosticList();
            HardwareProfile p = ProfileReader.read(profile, problems);
            assertNotNull(p, problems.all().toString());
            assertEquals(ServoProtocol.DXL2, p.protocol());
            assertEquals(1_000_000, p.baud());
            assertEquals(pty.a().toString(), p.port());
            assertEquals(3, p.servos().size());
            assertEquals(3, p.servos().get(2).servo());

            Gui.open(ide, Gui.example("hello-snake.xml"));
            ide.toolbar().setTarget(Target.HARDWARE);
            AtomicReference<RunOutcome> outcome = new AtomicReference<>();
            ide.runs().run(false, 1, outcome::set);
            ide.toolbar().setTarget(Target.SIMULATOR);
            assertNotNull(outcome.get(), "a hardware run is refused at once while the dialog holds the bus");
            assertEquals(RunOutcome.Status.ERROR, outcome.get().status());
            assertTrue(outcome.get().message().contains("Hardware dialog holds the bus"), outcome.get().message());

            click(d, "Close");
            Gui.pump(() -> d.shell().isDisposed(), "the dialog to close");
            assertTrue(ide.hardwareDialog().sessionForTest().awaitClosed(5000), "the bus thread ends");
            Gui.pump(() -> !ide.status().hardware().contains("connected ("), "the status bar to drop the dialog's bus");
        }
    }

    @Test
    void aMissingPortIsSaidInWords() {
        HardwareDialog d = HardwareDialog.open(ide);
        d.portBox().setText(dir.resolve("no-such-port").toString());
        d.protocolBox().select(d.protocolBox().indexOf("sts"));
        d.baudBox().setText("1000000");
        click(d, "Connect");
        Gui.pump(() -> d.message().contains("does not exist"), "the dialog to say the port does not exist");
        assertFalse(d.message().contains("Exception"), d.message());
        d.shell().close();
        Gui.pump(() -> d.shell().isDisposed(), "the dialog to close");
    }
}
