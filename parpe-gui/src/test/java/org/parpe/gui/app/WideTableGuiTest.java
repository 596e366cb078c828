package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collections;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.parpe.gui.grid.GridPane;

/**
 * Issue 23, item 14: a gait table with a row of 5 000 entries froze the IDE for over ten minutes
 * (the UI thread made a table column per entry). The grid now shows at most
 * {@link GridPane#MAX_COLUMNS} columns and says to edit a wider table in the text.
 */
class WideTableGuiTest {
    private IdeWindow ide;

    @AfterEach
    void close() {
        Gui.closeIde(ide);
    }

    @Test
    void aRowOfFiveThousandEntriesIsNotMadeIntoColumns() throws Exception {
        Path dir = Files.createTempDirectory("parpe-wide");
        String lesson = Files.readString(Gui.example("tutorial/02-gait-table-snake.xml"));
        String row = String.join(", ", Collections.nCopies(5000, "30"));
        String wide = lesson.replaceFirst("(?s)(<travel>\\s*<!--[^>]*-->)(.*?)(</travel>)", "$1\n" + row + "\n" + row + "\n$3");
        assertTrue(wide.contains(row), "the lesson's table was not replaced");
        Path script = dir.resolve("wide.xml");
        Files.writeString(script, wide);
        ide = Gui.openIde(dir.resolve("home"));
        Gui.open(ide, script);
        assertTrue(ide.grid.showTable("travel"));
        Gui.pump(() -> ide.grid.status().contains("more than the"), "the grid to say the table is too wide");
        assertTrue(ide.grid.widget().getColumnCount() <= GridPane.MAX_COLUMNS + 2,
                ide.grid.widget().getColumnCount() + " columns");
        assertTrue(ide.grid.status().contains("5000 columns"), ide.grid.status());
    }

    /** Issue 23, item 10: a table without times showed "1" in every row where lesson 2 teaches 0.5 s. */
    @Test
    void aTableWithoutTimesShowsEachRowsShareOfThePeriodInSeconds() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-times"));
        Gui.open(ide, Gui.example("tutorial/02-gait-table-snake.xml"));
        Gui.pump(() -> ide.program() != null, "lesson 2 to load");
        assertTrue(ide.grid.showTable("travel"));
        Gui.pump(() -> "0.5 s".equals(ide.grid.widget().getItem(0).getText(1)),
                "the times column to show 3 s / 6 rows = 0.5 s, not 1");
        for (int r = 0; r < 6; r++) {
            org.junit.jupiter.api.Assertions.assertEquals("0.5 s", ide.grid.widget().getItem(r).getText(1));
        }
    }
}
