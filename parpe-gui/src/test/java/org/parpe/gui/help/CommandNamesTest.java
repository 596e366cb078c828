package org.parpe.gui.help;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** The tutorial window showed installed users {@code ./parpe …} commands they cannot run (issue 22 §3). */
class CommandNamesTest {
    @Test
    void theInstalledPageSaysParpe() {
        assertEquals("```\nparpe run a.xml --sim snake\n```\nthen `parpe race a.xml b.xml`.",
                CommandNames.forInstall("```\n./parpe run a.xml --sim snake\n```\nthen `./parpe race a.xml b.xml`.", true));
    }

    @Test
    void otherPathsAndASourceCheckoutAreLeftAlone() {
        String text = "cd ~/src/parpe && ./parpe run a.xml; ls x/./parpe ./parpe-ide ./parpe.cmd";
        assertEquals(text, CommandNames.forInstall(text, false));
        assertEquals("cd ~/src/parpe && parpe run a.xml; ls x/./parpe ./parpe-ide ./parpe.cmd",
                CommandNames.forInstall(text, true));
    }

    @Test
    void lessonElevenAsInstalledHasNoDotSlashCommand() throws Exception {
        String lesson = Files.readString(Path.of("..", "docs", "tutorial", "11-optimise.md"));
        assertTrue(lesson.contains("./parpe optimize examples/tutorial/10-race-snake.xml"), "the lesson changed; update this test");
        String shown = CommandNames.forInstall(lesson, true);
        assertFalse(shown.contains("./parpe"), shown);
        assertTrue(shown.contains("\nparpe optimize examples/tutorial/10-race-snake.xml"), shown);
    }
}
