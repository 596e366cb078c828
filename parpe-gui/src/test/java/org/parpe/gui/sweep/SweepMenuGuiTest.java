package org.parpe.gui.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Menu;
import org.eclipse.swt.widgets.MenuItem;
import org.eclipse.swt.widgets.Shell;
import org.junit.jupiter.api.Test;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;
import org.parpe.gui.prefs.Prefs;

/** Run → Sweep / Optimise… in the IDE window opens the dialog on the editor's script, once. */
class SweepMenuGuiTest {

    private static MenuItem item(Menu menu, String prefix) {
        return Arrays.stream(menu.getItems()).filter(i -> i.getText().replace("&", "").startsWith(prefix)).findFirst()
                .orElse(null);
    }

    private static Shell[] sweepShells(IdeWindow ide) {
        return Arrays.stream(IdeAccess.shell(ide).getShells()).filter(s -> !s.isDisposed() && s.getText().startsWith("Sweep / Optimise"))
                .toArray(Shell[]::new);
    }

    @Test
    void theRunMenuOpensOneDialogOnTheEditorsScript() throws Exception {
        Path home = Files.createTempDirectory("parpe-sweep-menu");
        IdeWindow ide = new IdeWindow(Ui.display(), new Prefs(home));
        try {
            ide.open(null, true);
            Ui.pump(() -> IdeAccess.validations(ide) > 0, "the first validation");
            MenuItem run = item(IdeAccess.shell(ide).getMenuBar(), "Run");
            assertNotNull(run, "no Run menu");
            MenuItem sweep = item(run.getMenu(), "Sweep / Optimise");
            assertNotNull(sweep, "no Run > Sweep / Optimise… item");
            sweep.notifyListeners(SWT.Selection, new Event());
            sweep.notifyListeners(SWT.Selection, new Event());
            Shell[] open = sweepShells(ide);
            assertEquals(1, open.length, "a second click brings the same dialog");
            assertEquals("Sweep / Optimise \u2014 untitled.xml", open[0].getText());
            assertTrue(open[0].isVisible());
            open[0].close();
            Ui.pump(() -> sweepShells(ide).length == 0, "the dialog to close");
        } finally {
            IdeAccess.shell(ide).dispose();
        }
    }

    /** The widgets of {@code c} and of its children, depth first. */
    private static java.util.List<org.eclipse.swt.widgets.Control> all(org.eclipse.swt.widgets.Composite c) {
        java.util.List<org.eclipse.swt.widgets.Control> out = new java.util.ArrayList<>();
        for (org.eclipse.swt.widgets.Control k : c.getChildren()) {
            out.add(k);
            if (k instanceof org.eclipse.swt.widgets.Composite m) {
                out.addAll(all(m));
            }
        }
        return out;
    }

    /** Issue 31, item 2: the dialog has a World choice, and it starts on the world of the window's runs. */
    @Test
    void theDialogStartsOnTheWorldOfTheWindowsRuns() throws Exception {
        IdeWindow ide = IdeAccess.openIde(Files.createTempDirectory("parpe-sweep-world"));
        try {
            Path world = Path.of(System.getProperty("parpe.examples", "../examples"), "worlds", "race-track.xml");
            IdeAccess.world(ide, world);
            item(item(IdeAccess.shell(ide).getMenuBar(), "Run").getMenu(), "Sweep / Optimise").notifyListeners(SWT.Selection, new Event());
            Shell dialog = sweepShells(ide)[0];
            org.eclipse.swt.widgets.Combo choice = all(dialog).stream()
                    .filter(c -> c instanceof org.eclipse.swt.widgets.Combo k && k.indexOf("flat floor") >= 0)
                    .map(c -> (org.eclipse.swt.widgets.Combo) c).findFirst()
                    .orElseThrow(() -> new AssertionError("the dialog has no World choice"));
            assertEquals("race-track.xml", choice.getText(), "the dialog starts on the window's world");
            dialog.close();
        } finally {
            IdeAccess.closeIde(ide);
        }
    }
}
