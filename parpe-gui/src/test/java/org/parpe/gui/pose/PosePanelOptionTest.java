package org.parpe.gui.pose;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.parpe.gui.automation.LaunchOptions;

/** {@code parpe gui FILE --pose-panel}: the option is parsed, documented, and makes the launch automated. */
class PosePanelOptionTest {
    @Test
    void posePanelIsAnOptionOfGui() {
        LaunchOptions o = LaunchOptions.parse(List.of("leg.xml", "--pose-panel", "--screenshot", "p.png", "--exit"));
        assertTrue(o.posePanel());
        assertTrue(o.automated());
        assertFalse(LaunchOptions.parse(List.of("leg.xml")).posePanel());
        assertTrue(LaunchOptions.usage().contains("--pose-panel"));
    }
}
