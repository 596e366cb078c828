package org.parpe.sim.build;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;

/** How a robot fits a script: the modules one has and the other lacks, and each module's group. */
class ScriptFitTest {
    @Test
    void missingUnusedAndTheGroupOfEachModule() throws Exception {
        String script = Files.readString(Path.of("../examples/wheel.xml"))
                .replace("<wheel elements=\"0,1,2,3,4,5,6,7\" />", "<wheel elements=\"0,1,2\" />\n      <arms elements=\"3, 7\"/>");
        LoadResult r = ScriptLoader.loadText(Path.of("fit.xml"), script, Map.of());
        assertTrue(r.ok(), () -> r.diagnostics().toString());
        Path tee = Path.of("../examples/configs/tee-snake.xml");
        RobotDraft robot = RobotDraft.of(tee.toString(), Files.readString(tee));
        ScriptFit fit = ScriptFit.of(r.program(), robot.config());
        assertEquals(List.of(7), fit.missing(), "the script's module 7 is not on the robot");
        assertEquals(List.of(4), fit.unused(), "robot module 4 is in no group");
        assertEquals(Map.of(0, "wheel", 1, "wheel", 2, "wheel", 3, "arms", 7, "arms"), fit.groupOf());
    }
}
