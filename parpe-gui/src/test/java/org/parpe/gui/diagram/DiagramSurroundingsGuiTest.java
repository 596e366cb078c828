package org.parpe.gui.diagram;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.graphics.RGB;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Text;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;
import org.parpe.gui.panels.Theme;

/**
 * Issue 31, minors of the Diagram tab: the drawing stayed white with a dark theme, the joint-angle
 * plot was blank while the Diagram tab was shown, and tool tips covered the open lists of its
 * choosers. Real widgets under Xvfb at 1366×768 on a copy of {@code examples/centipede-walk.xml};
 * the colours are checked against the theme the test runs with (run it with
 * {@code GTK_THEME=Adwaita:dark} for the dark one, as scripts/ide-screenshots does).
 */
class DiagramSurroundingsGuiTest {
    private static IdeWindow ide;

    @BeforeAll
    static void openWindow() throws Exception {
        ide = DiagramWindow.open(Files.createTempDirectory("parpe-diagram-around")).ide();
        IdeAccess.dontSave(ide);
    }

    @AfterAll
    static void closeWindow() {
        IdeAccess.closeIde(ide);
    }

    @Test
    void theDrawingIsOnTheThemesPaper() {
        IdeAccess.settle();
        Control canvas = IdeAccess.diagram(ide).canvas();
        Image image = new Image(canvas.getDisplay(), canvas.getSize().x, canvas.getSize().y);
        try {
            GC gc = new GC(image);
            try {
                canvas.print(gc);
            } finally {
                gc.dispose();
            }
            var data = image.getImageData();
            RGB corner = data.palette.getRGB(data.getPixel(2, 2));
            assertEquals(Theme.paper().getRGB(), corner, "the drawing's paper (the theme is " + (Theme.dark() ? "dark" : "light") + ")");
        } finally {
            image.dispose();
        }
    }

    /** The chart draws its axes only when its plot area is 20 pixels high between its title line and its legend rows. */
    @Test
    void theJointAnglePlotHasRoomToDrawBesideTheDiagram() {
        IdeAccess.settle();
        Control chart = IdeAccess.plotChart(ide);
        GC gc = new GC(chart);
        int line;
        try {
            line = gc.getFontMetrics().getHeight();
        } finally {
            gc.dispose();
        }
        int h = ((org.eclipse.swt.widgets.Scrollable) chart).getClientArea().height;
        assertTrue(h - line * 4 - line * 3 / 2 >= 20, "the plot is " + h + " px high, too low for lines of " + line + " px");
        DiagramWindow.canvasHasHalfTheTab(ide);
    }

    @Test
    void noChooserOrFieldOfTheDiagramHasAToolTipOverItsList() {
        IdeAccess.diagram(ide).palette().full(true);
        for (String item : IdeAccess.diagram(ide).palette().items()) {
            IdeAccess.diagram(ide).palette().choose(item);
            for (Control c : all((Composite) IdeAccess.diagram(ide).control())) {
                if (c instanceof Combo || c instanceof Text) {
                    assertEquals(null, c.getToolTipText(), item + ": " + c + " " + c.getData("field"));
                }
            }
        }
        IdeAccess.diagram(ide).palette().full(false);
    }

    private static List<Control> all(Composite c) {
        List<Control> out = new ArrayList<>();
        for (Control k : c.getChildren()) {
            out.add(k);
            if (k instanceof Composite kc) {
                out.addAll(all(kc));
            }
        }
        return out;
    }
}
