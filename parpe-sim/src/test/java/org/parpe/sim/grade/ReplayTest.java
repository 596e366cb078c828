package org.parpe.sim.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.sim.SimTarget;
import org.parpe.sim.world.Challenge;
import org.parpe.sim.world.World;
import org.parpe.sim.world.WorldReader;

/**
 * A graded run played back from its trace moves the robot as the run did: the centre of mass
 * the replay reaches at each tick is the one the run's trace recorded there (com_x, com_y,
 * printed with six decimals), although the script is not run again.
 */
class ReplayTest {
    @TempDir
    Path dir;

    @Test
    void theReplayFollowsTheRunsRecordedPath() throws Exception {
        Path worldFile = Path.of("../examples/worlds/race-track.xml").toAbsolutePath().normalize();
        DiagnosticList found = new DiagnosticList();
        World world = WorldReader.read(worldFile, found);
        Challenge c = new Challenge(dir.resolve("c.xml"), worldFile, "snake:n=8", 3, 0.01, Map.of(), 8, java.util.Set.of(),
                Challenge.TieBreak.DISTANCE);
        String script = "<program>\n  <robot><structure><body elements=\"0..7\"/></structure></robot>\n"
                + "  <main><race/></main>\n"
                + "  <behaviors><race><wave group=\"body\" phase=\"0.2\" period=\"1.5\"/></race></behaviors>\n"
                + "  <automata><wave states=\"up, down\"/></automata>\n"
                + "  <states><up angles=\"40\" interp=\"smooth\"/><down angles=\"-40\" interp=\"smooth\"/></states>\n"
                + "</program>\n";
        LoadResult r = ScriptLoader.loadText(dir.resolve("s.xml"), script, Map.of());
        Path trace = dir.resolve("t.csv");
        try (Writer w = Files.newBufferedWriter(trace, StandardCharsets.UTF_8)) {
            Run.Builder run = Run.builder(r.program(), new RunOptions(c.tick(), 0, List.of()), new DiagnosticList())
                    .duration(c.duration()).trace(w);
            new SimTarget(c.robot(), world).attach(run);
            run.build().execute();
        }
        List<String> lines = Files.readAllLines(trace);
        List<String> header = List.of(lines.get(0).split(","));
        int x = header.indexOf("com_x");
        int y = header.indexOf("com_y");
        try (Replay replay = Replay.of(c, world, trace)) {
            assertEquals(lines.size() - 1, replay.ticks());
            double moved = 0;
            for (int k = 1; k < lines.size(); k++) {
                assertTrue(replay.advance());
                String[] row = lines.get(k + 1 < lines.size() ? k + 1 : k).split(",");
                if (k + 1 < lines.size()) { // row k+1 holds the centre of mass after k ticks
                    double[] com = replay.com();
                    assertEquals(Double.parseDouble(row[x]), com[0], 2e-6, "com_x after " + k + " ticks");
                    assertEquals(Double.parseDouble(row[y]), com[1], 2e-6, "com_y after " + k + " ticks");
                    moved = Math.max(moved, Math.abs(com[0] - Double.parseDouble(lines.get(1).split(",")[x])));
                }
            }
            assertFalse(replay.advance());
            assertTrue(moved > 0.01, "the robot moved in the replay, got " + moved + " m");
        }
    }

    @Test
    void aFileThatIsNoTraceIsRefusedWithItsName() throws Exception {
        Path worldFile = Path.of("../examples/worlds/race-track.xml").toAbsolutePath().normalize();
        World world = WorldReader.read(worldFile, new DiagnosticList());
        Challenge c = new Challenge(dir.resolve("c.xml"), worldFile, "snake:n=8", 3, 0.01, Map.of(), 8, java.util.Set.of(),
                Challenge.TieBreak.DISTANCE);
        Path bad = Files.writeString(dir.resolve("bad.csv"), "time,m0\n0.000000,x\n");
        Exception e = assertThrows(java.io.IOException.class, () -> Replay.of(c, world, bad));
        assertEquals(bad + ":2: not a row of numbers", e.getMessage());
    }
}
