package org.parpe.cli.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * {@code examples/race-snake-optimised.xml}, written by {@code parpe optimize} from lesson 10's
 * race snake, wins the race against the hand-written script under the race's rules.
 */
class OptimisedExampleTest {
    @Test
    void theOptimisedGaitBeatsTheHandWrittenOneInTheRace() {
        SweepCommandTest.Result r = SweepCommandTest.cli("race", "../examples/tutorial/10-race-snake.xml",
                "../examples/race-snake-optimised.xml", "--sim", "snake:n=8", "--duration", "30");
        assertEquals(0, r.code(), r.err());
        List<String> lines = r.out().lines().toList();
        assertTrue(lines.get(1).startsWith("1     ../examples/race-snake-optimised.xml"), r.out());
        assertTrue(lines.get(2).startsWith("2     ../examples/tutorial/10-race-snake.xml"), r.out());
        double optimised = forward(lines.get(1));
        double handWritten = forward(lines.get(2));
        assertTrue(optimised > 3 * handWritten, optimised + " m vs " + handWritten + " m");
    }

    /** The "forward (m)" column of a ranking line. */
    private static double forward(String line) {
        return Double.parseDouble(line.trim().split("\\s+")[3]);
    }
}
