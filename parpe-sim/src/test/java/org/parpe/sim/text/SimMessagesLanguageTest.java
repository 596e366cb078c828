package org.parpe.sim.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.text.Lang;
import org.parpe.sim.SimTarget;
import org.parpe.sim.Simulator;
import org.parpe.sim.bridge.Export;
import org.parpe.sim.world.World;
import org.parpe.sim.world.WorldReader;
import org.parpe.sim.world.WorldScore;

/**
 * The simulator's messages in the user's language (issue 38: "error and warning messages of ...
 * the simulator ... and the export" come from the bundles): before, a robot that does not fit its
 * world, a score in words and a refused export folder were English whatever the language.
 */
class SimMessagesLanguageTest {
    @TempDir
    Path dir;

    @AfterEach
    void english() {
        Lang.use(Locale.ENGLISH);
    }

    @Test
    void aRobotThatDoesNotFitItsWorldIsAWarningInGerman() throws Exception {
        Path w = Files.writeString(dir.resolve("wall.xml"), """
                <world>
                  <wall x0="-1" y0="0" x1="1" y1="0" height="0.2" thickness="0.2"/>
                </world>
                """);
        DiagnosticList d = new DiagnosticList();
        World world = WorldReader.read(w, d);
        assertNotNull(world, d.all().toString());
        Lang.use(Locale.GERMAN);
        try (Simulator s = SimTarget.create("snake:n=4", new int[] {0, 1, 2, 3}, d, world)) {
            List<String> warnings = d.all().stream().map(x -> x.format()).toList();
            assertTrue(warnings.stream().anyMatch(m -> m.startsWith("simulated robot snake:n=4: warning: der Roboter passt nicht"
                    + " in die Welt wall.xml: er beginnt ") && m.endsWith(" mm tief in ihren Wänden, Rampen, Trümmern oder"
                    + " Gegenständen; wähle einen Roboter, der passt, oder eine Welt, die für ihn gemacht ist")), warnings.toString());
        }
    }

    /** The parts of a score as WorldScore's documentation shows them, and the same in German. */
    @Test
    void aScoreInWordsInEnglishAndGerman() {
        WorldScore s = new WorldScore(10, 31.2, 1.4, 2, 1, 2, "tilt");
        assertEquals("zone 31.2 s, path 1.40 m, 2 checkpoints, 1 delivered, 2 presses, disqualified (tilt)", s.inWords());
        Lang.use(Locale.GERMAN);
        assertEquals("Zielzone 31.2 s, Weg 1.40 m, 2 Kontrollpunkte, 1 abgeliefert, 2 Hebeldrücke, disqualifiziert (gekippt)",
                s.inWords());
        assertEquals("1 Kontrollpunkt, 1 Hebeldruck, disqualifiziert (Arena verlassen)",
                new WorldScore(0, Double.NaN, 0, 1, 0, 1, "arena").inWords());
    }

    @Test
    void anExportIntoAFileIsRefusedInGerman() throws IOException {
        Path file = Files.writeString(dir.resolve("out"), "x");
        assertEquals("'" + file + "' is a file, not a folder", Export.refusal(file, List.of("snake.xml")));
        Lang.use(Locale.GERMAN);
        assertEquals("'" + file + "' ist eine Datei, kein Ordner", Export.refusal(file, List.of("snake.xml")));
    }
}
