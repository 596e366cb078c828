package org.parpe.gui.pose;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Locale;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.layout.FillLayout;
import org.eclipse.swt.widgets.Scale;
import org.eclipse.swt.widgets.Shell;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.parpe.core.text.Lang;
import org.parpe.gui.app.Gui;

/**
 * The Pose panel's sliders in a narrow pane (issue 38: the pseudo-language, the Diagram tab or the
 * docked tutorial beside the panel leave its slider side about 200 px): each slider stays wide
 * enough to be dragged, under its module's name and angle, and goes back between them where the
 * pane is wide. Real widgets under Xvfb.
 */
class JointSlidersGuiTest {
    private Shell shell;

    @AfterEach
    void close() {
        if (shell != null) {
            shell.dispose();
        }
        Lang.use(Locale.ENGLISH);
    }

    private JointSliders sliders(int width) {
        Lang.use(Lang.PSEUDO); // "[möđůłé 0 ~~~]": the longest names
        shell = new Shell(Gui.display());
        shell.setLayout(new FillLayout());
        JointSliders s = new JointSliders(shell, (module, degrees) -> { });
        s.show(new int[] {0, 1, 14, 15}, new double[] {-25, 20, -25, -60});
        shell.setSize(width, 300);
        shell.open();
        Gui.settle();
        return s;
    }

    @Test
    void aNarrowPanePutsEachSliderUnderItsNameAtAUsableWidth() {
        JointSliders s = sliders(220);
        for (int id : new int[] {0, 1, 14, 15}) {
            Scale scale = s.scale(id);
            Rectangle b = scale.getBounds();
            // before: 3 columns whatever the width, the slider squeezed to its knob (about 20 px) between name and angle
            assertTrue(b.width >= 100, "module " + id + "'s slider is " + b.width + " px wide");
            assertTrue(b.x + b.width <= scale.getParent().getClientArea().width, "module " + id + "'s slider fits the pane: " + b);
        }
        Rectangle name = name(s, 0);
        assertTrue(s.scale(0).getBounds().y >= name.y + name.height, "the slider is under its name: " + name + ", " + s.scale(0).getBounds());
    }

    /** The label of the {@code k}-th module's name: the first of its row's three widgets in either order. */
    private static Rectangle name(JointSliders s, int k) {
        return s.scale(0).getParent().getChildren()[3 * k].getBounds();
    }

    @Test
    void aWidePaneKeepsEachSliderBesideItsName() {
        JointSliders s = sliders(600);
        for (int k = 0; k < 4; k++) {
            Rectangle b = s.scale(new int[] {0, 1, 14, 15}[k]).getBounds();
            Rectangle name = name(s, k);
            assertTrue(b.x >= name.x + name.width && b.y < name.y + name.height && name.y < b.y + b.height,
                    "module " + k + "'s slider is beside its name: " + name + ", " + b);
        }
    }
}
