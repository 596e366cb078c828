package org.parpe.gui.app;

import org.parpe.gui.help.HelpText;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import org.junit.jupiter.api.Test;

/** The main window had no icon and About showed no PARPE version (issue 22 §6). */
class IdentityGuiTest {
    @Test
    void theWindowHasPARPEsIconAndAboutItsVersion() throws Exception {
        IdeWindow ide = Gui.openIde(Files.createTempDirectory("parpe-identity-home"));
        try {
            assertNotNull(ide.shell.getImage(), "the main window has no icon");
            assertTrue(ide.shell.getImage().getBounds().width >= 48, "icon " + ide.shell.getImage().getBounds());
        } finally {
            Gui.closeIde(ide);
        }
        // Version.NUMBER is the pom's version (VersionTest)
        assertTrue(HelpText.about().startsWith("PARPE " + org.parpe.core.Version.NUMBER + ":"), HelpText.about());
    }
}
