package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import org.eclipse.swt.custom.ScrolledComposite;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Scale;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * Issue 31, item 3: the mouse wheel over the Controls panel changed a slider (and so the running
 * robot) when the user only meant to scroll the panel to the next control. The wheel now scrolls
 * the panel. Real X wheel events (xdotool) over a real slider of
 * lesson 8 at 1366×768, where the panel is too short for all its controls.
 */
class ControlsWheelGuiTest {
    private IdeWindow ide;

    @AfterEach
    void close() {
        Gui.closeIde(ide);
    }

    private static List<Scale> sliders(Composite c) {
        List<Scale> out = new ArrayList<>();
        for (Control k : c.getChildren()) {
            if (k instanceof Scale s) {
                out.add(s);
            } else if (k instanceof Composite m) {
                out.addAll(sliders(m));
            }
        }
        return out;
    }

    @Test
    void theWheelOverASliderScrollsThePanelAndLeavesTheSliderAlone() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-wheel"));
        ide.shell.setBounds(0, 0, 1366, 768);
        Gui.open(ide, Gui.example("tutorial/08-teleop-snake.xml"));
        Gui.pump(() -> ide.program() != null && !sliders((Composite) ide.controls.control()).isEmpty(), "the controls");
        Gui.settle();
        ScrolledComposite panel = (ScrolledComposite) ide.controls.control();
        Rectangle view = panel.getDisplay().map(panel, null, panel.getClientArea());
        assertTrue(panel.getContent().getSize().y > view.height, "the panel holds more than it shows at 1366x768");
        Scale slider = sliders(panel).stream().filter(s -> view.contains(s.getDisplay().map(s.getParent(), null,
                centre(s.getBounds())))).findFirst().orElseThrow(() -> new AssertionError("no slider in sight"));
        int before = slider.getSelection();
        Point at = slider.getDisplay().map(slider.getParent(), null, centre(slider.getBounds()));
        // X11 reports a notch of the wheel down as a click of button 5; SWT's Display.post cannot make one that
        // GTK reads as a wheel, so the X server gets it from xdotool (test-all installs it), as from a mouse
        Process p = new ProcessBuilder("xdotool", "mousemove", Integer.toString(at.x), Integer.toString(at.y),
                "click", "--repeat", "3", "--delay", "50", "5").redirectErrorStream(true).start();
        String said = new String(p.getInputStream().readAllBytes());
        assertEquals(0, p.waitFor(), "xdotool failed (is it installed? test-all installs it): " + said);
        Gui.pump(() -> panel.getOrigin().y > 0 || slider.getSelection() != before, "the wheel to reach the window", 5000);
        Gui.settle();
        assertEquals(before, slider.getSelection(), "the wheel changed the slider");
        assertTrue(panel.getOrigin().y > 0, "the wheel scrolled the panel: origin " + panel.getOrigin());
    }

    private static Point centre(Rectangle r) {
        return new Point(r.x + r.width / 2, r.y + r.height / 2);
    }
}
