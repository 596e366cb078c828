package org.parpe.gui.diagram;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;

/**
 * Beside the docked tutorial the Diagram tab is narrow (about 375 px at 1366×768) and its rows
 * wrap. They never take more than half the tab (beyond that they scroll) and the live bar's
 * buttons stay inside the tab. Before, the rows pushed the drawing down to a few pixels in a
 * longer language and the live bar's buttons ran past the tab's right edge. Real widgets under
 * Xvfb, on a copy of {@code examples/centipede-walk.xml}.
 */
class DiagramNarrowTabGuiTest {
    private static IdeWindow ide;

    @BeforeAll
    static void openWindow() throws Exception {
        ide = DiagramWindow.open(Files.createTempDirectory("parpe-diagram-narrow")).ide();
        IdeAccess.dontSave(ide);
        IdeAccess.openTutorialDocked(ide);
        IdeAccess.diagram(ide).showTab();
        IdeAccess.settle();
    }

    @AfterAll
    static void closeWindow() {
        IdeAccess.closeIde(ide);
    }

    @Test
    void besideTheDockedTutorialTheDrawingKeepsHalfTheTabAndTheButtonsStayInside() {
        Composite tab = (Composite) IdeAccess.diagram(ide).control();
        int width = tab.getSize().x;
        assertTrue(width < 520, "the Diagram tab beside the docked tutorial is " + width + " px wide: not narrow");
        DiagramWindow.canvasHasHalfTheTab(ide);
        for (Control c : IdeAccess.allChildren(tab)) {
            if (c instanceof Button b && b.isVisible() && b.getParent().isVisible()) {
                Point right = tab.toControl(b.toDisplay(b.getSize().x, 0));
                assertTrue(right.x <= width, "'" + b.getText() + "' ends at " + right.x + " px, past the tab's " + width + " px");
            }
        }
    }
}
