package org.parpe.cli.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.parpe.cli.Cli;

/**
 * The example worlds on the command line: each is deterministic (the same trace bit for bit,
 * also from a sweep on several threads), its script scores, {@code race} ranks by score, and a
 * malformed world is a located usage error.
 */
class WorldCommandLineTest {
    static final String WORLDS = "../examples/worlds/";

    @TempDir
    Path tmp;

    /** Each example world with its script. */
    static Stream<Arguments> worlds() {
        return Stream.of(Arguments.of("race-track", "race-track-snake"), Arguments.of("rubble", "../tutorial/12-rubble-snake"),
                Arguments.of("slot-machine", "../tutorial/13-slot-machine-snake"));
    }

    private byte[] trace(String world, String script, String name) throws IOException {
        Path t = tmp.resolve(name);
        Cli r = Cli.run("run", WORLDS + script + ".xml", "--sim", "snake:n=8", "--world", WORLDS + world + ".xml",
                "--duration", "6", "--trace", t.toString());
        assertEquals(0, r.code, r.toString());
        return Files.readAllBytes(t);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("worlds")
    void theSameRunGivesTheSameTraceBitForBit(String world, String script) throws IOException {
        byte[] a = trace(world, script, "a.csv");
        byte[] b = trace(world, script, "b.csv");
        assertTrue(a.length > 1000);
        assertArrayEquals(a, b, world + ": two runs differ");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("worlds")
    void aSweepInTheWorldGivesTheSameScoresOnOneThreadAndOnTwo(String world, String script) throws IOException {
        String[] base = {"sweep", WORLDS + script + ".xml", "--sim", "snake:n=8", "--world", WORLDS + world + ".xml",
            "--duration", "4", "--objective", "score"};
        List<String> one = new java.util.ArrayList<>(List.of(base));
        one.addAll(List.of("--vary", "bend=30,40"));
        List<String> two = new java.util.ArrayList<>(one);
        one.addAll(List.of("--jobs", "1", "--out", tmp.resolve("one.csv").toString()));
        two.addAll(List.of("--jobs", "2", "--out", tmp.resolve("two.csv").toString()));
        Cli r1 = Cli.run(one);
        assertEquals(0, r1.code, r1.toString());
        Cli r2 = Cli.run(two);
        assertEquals(0, r2.code, r2.toString());
        List<String> a = Files.readAllLines(tmp.resolve("one.csv"));
        assertTrue(a.get(0).endsWith(",score"), a.get(0));
        assertEquals(3, a.size(), a.toString());
        assertEquals(a, Files.readAllLines(tmp.resolve("two.csv")));
        for (String row : a.subList(1, a.size())) {
            assertFalse(row.endsWith(","), "every run has a score: " + row);
        }
    }

    @Test
    void theSlotMachineScriptDeliversTheChipAndPressesTheLever() throws IOException {
        Path m = tmp.resolve("m.json");
        Cli r = Cli.run("run", "../examples/tutorial/13-slot-machine-snake.xml", "--sim", "snake:n=8", "--world",
                WORLDS + "slot-machine.xml", "--metrics", m.toString());
        assertEquals(0, r.code, r.toString());
        String json = Files.readString(m);
        // the world's time limit is the run's duration; 50 for the chip in the slot, 25 for a press
        assertTrue(json.contains("\"duration\": 40.000000"), json);
        assertTrue(json.contains("\"delivered\": 1"), json);
        assertTrue(json.contains("\"presses\": 1"), json);
        assertTrue(json.contains("\"score\": 75.000000"), json);
    }

    @Test
    void raceInAWorldRanksByScore() {
        Cli r = Cli.run("race", "../examples/tutorial/04-waves-snake.xml", WORLDS + "race-track-snake.xml", "--sim",
                "snake:n=8", "--world", WORLDS + "race-track.xml", "--duration", "20");
        assertEquals(0, r.code, r.toString());
        List<String> lines = r.out.lines().toList();
        assertTrue(lines.get(0).contains("score") && lines.get(0).contains("parts"), r.out);
        double first = Double.parseDouble(lines.get(1).trim().split("\\s{2,}")[7]);
        double second = Double.parseDouble(lines.get(2).trim().split("\\s{2,}")[7]);
        assertTrue(first >= second, r.out);
        assertTrue(lines.get(1).contains("path"), r.out);
    }

    @Test
    void aMalformedWorldIsALocatedUsageError() throws IOException {
        Path w = tmp.resolve("bad.xml");
        Files.writeString(w, "<world>\n  <ramp x=\"1\" y=\"0\" length=\"1\" width=\"0.5\" slope=\"steep\"/>\n</world>\n");
        Cli r = Cli.run("run", WORLDS + "race-track-snake.xml", "--sim", "snake:n=8", "--world", w.toString(),
                "--duration", "1");
        assertEquals(2, r.code, r.toString());
        assertTrue(r.err.contains(w + ":2:3: error: slope must be a number, got 'steep'"), r.err);
        assertFalse(r.err.contains("Exception"), r.err);
        Cli race = Cli.run("race", WORLDS + "race-track-snake.xml", "--world", w.toString());
        assertEquals(2, race.code, race.toString());
        assertTrue(race.err.contains(w + ":2:3: error: slope must be a number"), race.err);
        Cli sweep = Cli.run("sweep", WORLDS + "race-track-snake.xml", "--vary", "bend=30,40", "--objective", "score",
                "--out", tmp.resolve("s.csv").toString());
        assertEquals(2, sweep.code, sweep.toString());
        assertTrue(sweep.err.contains("--objective score needs --world"), sweep.err);
        Cli noSim = Cli.run("run", WORLDS + "race-track-snake.xml", "--world", WORLDS + "race-track.xml");
        assertEquals(2, noSim.code, noSim.toString());
    }

    /** Issue 31 item 5: a tiny movable object ended in ODE4j's mass assertion, an internal error (exit 4). */
    @Test
    void aTinyMovableObjectIsALocatedError() throws IOException {
        for (String kind : List.of("cup", "chip")) {
            Path w = tmp.resolve(kind + ".xml");
            Files.writeString(w, "<world>\n  <" + kind + " name=\"o\" x=\"0.5\" y=\"0\" radius=\"1e-9\"/>\n</world>\n");
            Cli r = Cli.run("run", WORLDS + "race-track-snake.xml", "--sim", "snake:n=8", "--world", w.toString(),
                    "--duration", "0.1");
            assertEquals(2, r.code, r.toString());
            assertEquals(w + ":2:3: error: radius must be at least 0.001 m (1 mm), got 1e-9\nparpe: the world file '" + w
                    + "' has errors (above)\n", r.err);
        }
    }
}
