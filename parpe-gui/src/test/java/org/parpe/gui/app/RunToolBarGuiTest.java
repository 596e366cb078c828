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
        if (ide != null && !ide.shell.isDisposed()) {
            Gui.endRun(ide);
            ide.shell.dispose();
        }
    }

    private void assertEmergencyStopShown(String when) {
        Gui.settle();
        ToolItem estop = ide.toolbar.emergencyStop();
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
        ide.toolbar.setTarget(RunOn.SIMULATOR);
        ide.toolbar.setSpeed(Speed.TIMES_10);
        ide.runs.run(false, -1, null);
        Gui.pump(() -> ide.runs.controller().status() != null && ide.runs.controller().status().time() > 0.3,
                "the run to start");
        assertEmergencyStopShown("while running");
        ide.runs.pause();
        assertTrue(ide.runs.controller().paused());
        assertEmergencyStopShown("while paused");
        Gui.screenshot(ide.shell, "paused-with-emergency-stop.png");
        ide.runs.pause();
        assertEmergencyStopShown("after resuming");
        ide.runs.emergencyStop();
        Gui.pump(() -> !ide.runs.running(), "the emergency stop to end the run");
        assertEmergencyStopShown("after the run");
        assertEquals(false, ide.runs.running());
    }

    /**
     * Issue 31, item 3: at a breakpoint Run was enabled beside Resume, two buttons for one thing
     * (and Run suggests a new run). Paused, Resume goes on and Run is disabled.
     */
    @Test
    void atABreakpointResumeIsEnabledAndRunIsNot() throws Exception {
        Gui.open(ide, Gui.example("centipede-walk.xml"));
        Gui.pump(() -> ide.program() != null, "centipede-walk.xml to load");
        var c = ide.runs.controller();
        c.breakpoints().toggle(new org.parpe.core.run.Breakpoints.Point("step", 1, org.parpe.core.run.Breakpoints.Kind.ENTER));
        ide.toolbar.setTarget(RunOn.SIMULATOR);
        ide.toolbar.setSpeed(Speed.MAX);
        ide.runs.run(false, 600, null);
        Gui.pump(() -> c.breakpoints().hit() != null && ide.toolbar.pauseItem().getText().equals("Resume"),
                "the run to stop at the breakpoint");
        assertTrue(c.paused());
        assertTrue(ide.toolbar.pauseItem().getEnabled(), "Resume is enabled at the breakpoint");
        assertEquals(false, ide.toolbar.runItem().getEnabled(), "Run is disabled beside Resume");
        assertEmergencyStopShown("at the breakpoint");
        ide.runs.pause(); // Resume
        Gui.pump(() -> !c.paused() && ide.toolbar.pauseItem().getText().equals("Pause"), "the run to go on");
        assertEquals(false, ide.toolbar.runItem().getEnabled(), "Run stays disabled while the run goes on");
        Gui.endRun(ide);
        assertTrue(ide.toolbar.runItem().getEnabled(), "Run is enabled again after the run");
    }
}
