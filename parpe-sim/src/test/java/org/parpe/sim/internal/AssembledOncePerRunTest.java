package org.parpe.sim.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.sim.SimTarget;

/**
 * Issue 19 item 9: a run assembled its robot two or three times (the robot guessed for the
 * script, the configuration checked, then the simulator's own). Now a run assembles it once, and
 * a sweep's blueprint once for all its runs.
 */
class AssembledOncePerRunTest {
    private static final String SCRIPT = """
            <program>
              <robot><structure><leftLeg elements="0..13"/><rightLeg elements="14..27"/><spine elements="28..54"/></structure></robot>
              <states><s angles="0"/></states>
              <automata><a states="s"/></automata>
              <behaviors><b><a group="spine"/></b></behaviors>
              <main><b/></main>
            </program>
            """;

    @Test
    void aRunOnTheGuessedRobotAssemblesItOnce() throws Exception {
        LoadResult r = ScriptLoader.loadText(Path.of("walker.xml"), SCRIPT, Map.of());
        assertTrue(r.ok(), r.diagnostics().toString());
        assertEquals("centipede", SimTarget.autoSpec(r.program()), "a robot that is not a snake is guessed");
        int before = Assembly.BUILT.get();
        DiagnosticList d = new DiagnosticList();
        Run run = Run.builder(r.program(), RunOptions.defaults(), d).attach(new SimTarget(SimTarget.AUTO))
                .duration(0.05).build();
        run.execute();
        assertEquals(1, Assembly.BUILT.get() - before);
    }

    @Test
    void aBlueprintAssemblesOnceForAllItsSimulators() throws Exception {
        int before = Assembly.BUILT.get();
        SimTarget.Blueprint b = SimTarget.blueprint("snake:n=4", new int[] {0, 1, 2, 3});
        for (int i = 0; i < 3; i++) {
            b.simulator().close();
        }
        assertEquals(1, Assembly.BUILT.get() - before);
    }
}
