package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Event;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.parpe.gui.run.Speed;
import org.parpe.gui.run.RunOn;

/**
 * Issue 23, item 6: an "s" pressed while the editor had the focus during a run went into the
 * script (and the status bar still said "No problems"). Now a steering key steers the robot
 * wherever the focus is, never edits the script during a run, and the status bar names the keys
 * that steer. Real key presses (Display.post) under Xvfb.
 */
class TeleopKeysGuiTest {
    private IdeWindow ide;

    @AfterEach
    void close() {
        Gui.closeIde(ide);
    }

    private static void press(Display d, char c) {
        for (int type : new int[] {SWT.KeyDown, SWT.KeyUp}) {
            Event e = new Event();
            e.type = type;
            e.character = c;
            e.keyCode = c;
            assertTrue(d.post(e), "the key could not be posted");
        }
    }

    @Test
    void aSteeringKeyInTheEditorSteersAndNeverTypesIntoTheScript() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-keys"));
        Gui.open(ide, Gui.example("teleop-dirwave.xml"));
        Gui.pump(() -> ide.program() != null, "the example to load");
        String before = ide.editor.document().get();
        ide.toolbar.setTarget(RunOn.SIMULATOR);
        ide.toolbar.setSpeed(Speed.REAL_TIME);
        assertEquals("", ide.status.keys(), "no steering keys before a run");
        ide.runs.run(false, -1, null);
        Gui.pump(() -> ide.runs.controller().engine() != null && ide.runs.controller().status() != null,
                "the run to start");
        assertEquals("\u2328 w s space Up Down: steer the robot", ide.status.keys());
        ide.shell.forceActive();
        ide.editor.widget().setFocus();
        ide.editor.widget().setCaretOffset(ide.editor.widget().getOffsetAtLine(19));
        Gui.pump(() -> ide.editor.widget().isFocusControl(), "the editor to have the focus");
        press(ide.shell.getDisplay(), 's');
        Gui.pump(() -> ide.runs.controller().engine().control("direction") == 1, "direction = backward from the key s");
        Gui.settle();
        assertEquals(before, ide.editor.document().get(), "the steering key was typed into the script");
        Gui.screenshot(ide.shell, "teleop-keys-in-editor.png");
        Gui.endRun(ide);
        assertEquals("", ide.status.keys());
        // After the run the same key types again.
        ide.editor.widget().setFocus();
        press(ide.shell.getDisplay(), 's');
        Gui.pump(() -> !ide.editor.document().get().equals(before), "the key to type into the idle editor");
    }
}
