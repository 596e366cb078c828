package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import org.eclipse.swt.widgets.Menu;
import org.eclipse.swt.widgets.MenuItem;
import org.junit.jupiter.api.Test;

/**
 * Issue 31: the Run menu showed no key for Emergency Stop. SWT on GTK shows the text after a
 * menu item's tab only when it can read it as a key (MenuItem.getMaskKeysym of SWT 3.124's GTK
 * port: Ctrl, Shift and Alt joined by '+' to one character, Enter or F1 to F12); "Esc" and
 * "Ctrl+Space" it drops without a word. Every key a menu names must be one it shows.
 */
class MenuKeysGuiTest {
    private static final Pattern SHOWN = Pattern.compile("((Ctrl|Shift|Alt)\\+)*(.|Enter|F([1-9]|1[0-2]))");

    @Test
    void everyKeyAMenuNamesIsShownAndEscIsNamedForTheEmergencyStop() throws Exception {
        IdeWindow ide = Gui.openIde(Files.createTempDirectory("parpe-menu-keys"));
        try {
            List<String> hidden = new ArrayList<>();
            List<MenuItem> all = new ArrayList<>();
            items(ide.shell.getMenuBar(), all);
            for (MenuItem it : all) {
                String text = it.getText();
                int tab = text.indexOf('\t');
                if (tab >= 0 && !SHOWN.matcher(text.substring(tab + 1)).matches()) {
                    hidden.add(text.replace("\t", " \\t "));
                }
            }
            assertEquals(List.of(), hidden, "menu items whose key GTK does not show");
            MenuItem stop = all.stream().filter(i -> i.getText().startsWith("&Emergency Stop")).findFirst().orElseThrow();
            assertTrue(stop.getText().contains("Esc"), stop.getText());
        } finally {
            Gui.closeIde(ide);
        }
    }

    private static void items(Menu menu, List<MenuItem> out) {
        for (MenuItem it : menu.getItems()) {
            out.add(it);
            if (it.getMenu() != null) {
                items(it.getMenu(), out);
            }
        }
    }
}
