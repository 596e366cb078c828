package org.parpe.gui.grid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.parpe.gui.automation.LaunchOptions;

/** {@code parpe gui FILE --grid NAME}, the option that shows a table in the grid for screenshots. */
class GridOptionTest {

    @Test
    void gridNamesATableAndIsAnAutomationOption() {
        LaunchOptions o = LaunchOptions.parse(List.of("examples/gait-table-12.xml", "--grid", "travel", "--screenshot", "g.png"));
        assertEquals("travel", o.grid());
        assertTrue(o.automated());
        assertNull(LaunchOptions.parse(List.of("a.xml")).grid());
        assertTrue(LaunchOptions.parse(List.of("--grid", "t")).automated(), "--grid alone is automated too");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> LaunchOptions.parse(List.of("a.xml", "--grid")));
        assertEquals("Missing required parameter for option '--grid' (NAME)", e.getMessage());
        assertTrue(LaunchOptions.usage().contains("--grid=NAME"), LaunchOptions.usage());
    }
}
