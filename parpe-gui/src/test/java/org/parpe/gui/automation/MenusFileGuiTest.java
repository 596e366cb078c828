package org.parpe.gui.automation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.gui.app.Gui;
import org.parpe.gui.app.IdeWindow;

/**
 * {@code -Dparpe.menus=FILE}: the automated launch writes the menu bar's texts to FILE, which
 * the .deb's install test reads to see the language of the IDE's own widgets (issue 38).
 */
class MenusFileGuiTest {

    @Test
    void theMenuBarsTextsGoToTheFileThePropertyNames(@TempDir Path dir) throws Exception {
        IdeWindow ide = Gui.openIde(Files.createDirectories(dir.resolve("home")));
        Path menus = dir.resolve("menus.txt");
        System.setProperty(Automation.MENUS, menus.toString());
        try {
            Automation.start(ide.automated(), LaunchOptions.parse(List.of("../examples/tutorial/03-hello-snake.xml", "--screenshot",
                    dir.resolve("ide.png").toString())));
            Gui.pump(() -> Files.exists(menus), "the menus file", 30_000);
            List<String> texts = Files.readAllLines(menus, StandardCharsets.UTF_8);
            assertEquals("File", texts.get(0), "the mnemonic's & is left out: " + texts);
            assertTrue(texts.contains("Help"), texts.toString());
        } finally {
            System.clearProperty(Automation.MENUS);
            Gui.closeIde(ide);
        }
    }
}
