package org.parpe.sim.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.diag.DiagnosticList;

/** A class's kit: read from its file, and robots checked against it at the part beyond it. */
class KitTest {
    @TempDir
    Path dir;

    private static RobotConfig robot(String spec) {
        DiagnosticList d = new DiagnosticList();
        RobotConfig c = RobotConfigs.resolve(spec, new int[0], d);
        assertFalse(d.hasErrors(), d.all().toString());
        return c;
    }

    @Test
    void aKitFileIsReadAndARobotBeyondItIsLocatedAtTheFirstPartTooMany() throws IOException {
        Path f = dir.resolve("kit.xml");
        Files.writeString(f, """
                <kit>
                  <part type="segment" count="4"/>
                  <part type="node" count="1"/>
                  <part type="foot" count="2"/>
                </kit>
                """);
        DiagnosticList d = new DiagnosticList();
        Kit kit = Kit.read(f, d);
        assertFalse(d.hasErrors(), d.all().toString());
        RobotConfig tee = robot("../examples/configs/tee-snake.xml");
        assertFalse(kit.check(tee, d));
        assertEquals(1, d.all().size(), d.all().toString());
        assertEquals(Path.of("..", "examples", "configs", "tee-snake.xml") + ":11:3: error: segment 'right' is beyond"
                + " the kit: the robot uses 5 segments, kit " + f + " has 4 (line 2)", d.all().get(0).toString());
        assertEquals(Map.of(PartType.SEGMENT, -1, PartType.NODE, 0, PartType.FOOT, 0, PartType.HUB, 0), kit.left(tee));
    }

    @Test
    void aTypeTheKitDoesNotNameIsOneTheClassLacks() {
        Kit kit = Kit.of("class 4B", Map.of(PartType.SEGMENT, 8, PartType.FOOT, 8));
        DiagnosticList d = new DiagnosticList();
        assertFalse(kit.check(robot("wheel"), d));
        assertTrue(d.all().toString().contains("hub 'hub' is beyond the kit: the robot uses 1 hub,"
                + " kit class 4B has 0"), d.all().toString());
        DiagnosticList fine = new DiagnosticList();
        assertTrue(kit.check(robot("snake:n=8"), fine));
        assertTrue(fine.all().isEmpty());
    }

    @Test
    void badKitFilesAreLocated() throws IOException {
        Path f = dir.resolve("bad.xml");
        Files.writeString(f, """
                <kit size="big">
                  <part type="segmnt" count="4"/>
                  <part type="foot" count="-1"/>
                  <part type="node" count="2"/>
                  <part type="node" count="3"/>
                  <box/>
                </kit>
                """);
        DiagnosticList d = new DiagnosticList();
        assertNull(Kit.read(f, d));
        String all = d.all().toString();
        assertTrue(all.contains(f + ":1:1: error: unexpected 'size' in <kit>"), all);
        assertTrue(all.contains(f + ":2:3: error: unknown part type 'segmnt'; expected one of segment, node, foot, hub"
                + " (did you mean 'segment'?)"), all);
        assertTrue(all.contains(f + ":3:3: error: count must be in 0..100000, got -1"), all);
        assertTrue(all.contains(f + ":5:3: error: the kit gives node twice (first on line 4)"), all);
        assertTrue(all.contains(f + ":6:3: error: unknown element <box>"), all);
    }
}
