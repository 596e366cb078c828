package org.parpe.gui.app;

import org.parpe.gui.prefs.Prefs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.ToolItem;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.parpe.gui.run.Speed;
import org.parpe.gui.run.RunOn;

/** The emergency stop is on the tool bar, visible and enabled, whatever the run is doing. */
class RunToolBarGuiTest {
    private IdeWindow ide;

    @BeforeEach
    void openWindow() throws Exception {
        ide = new IdeWindow(Gui.display(), new Prefs(Files.createTempDirectory("parpe-toolbar-test")));
        ide.open(Gui.example("teleop-dirwave.xml"), true);
        Gui.pump(() -> ide.program() != null, "teleop-dirwave.xml to load");
    }

    @AfterEach
    void closeWindow() {
        if (ide != null && !ide.shell().isDisposed()) {
            Gui.endRun(ide);
            ide.shell().dispose();
        }
    }

    private void assertEmergencyStopShown(String when) {
        Gui.settle();
        ToolItem estop = ide.toolbar().emergencyStop();
        assertTrue(estop.getEnabled(), "emergency stop disabled " + when);
        Rectangle b = estop.getBounds();
        Rectangle bar = estop.getParent().getClientArea();
        assertTrue(b.width > 0 && b.height > 0 && bar.contains(b.x + b.width - 1, b.y + b.height / 2),
                "emergency stop not shown " + when + ": item at " + b + ", tool bar area " + bar);
        assertTrue(estop.getParent().isVisible(), "tool bar hidden " + when);
    }

    @Test
    void emergencyStopIsShownIdleRunningAndPaused() throws Exception {
        assertEmergencyStopShown("while idle");
        ide.toolbar().setTarget(RunOn.SIMULATOR);
        ide.toolbar().setSpeed(Speed.TIMES_10);
        ide.runs().run(false, -1, null);
        Gui.pump(() -> ide.runs().controller().status() != null && ide.runs().controller().status().time() > 0.3,
                "the run to start");
        assertEmergencyStopShown("while running");
        ide.runs().pause();
        assertTrue(ide.runs().controller().paused());
        assertEmergencyStopShown("while paused");
        Gui.screenshot(ide.shell(), "paused-with-emergency-stop.png");
        ide.runs().pause();
        assertEmergencyStopShown("after resuming");
        ide.runs().emergencyStop();
        Gui.pump(() -> !ide.runs().running(), "the emergency stop to end the run");
        assertEmergencyStopShown("after the run");
        assertEquals(false, ide.runs().running());
    }
}
