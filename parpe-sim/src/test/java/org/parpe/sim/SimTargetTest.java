package org.parpe.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;
import org.parpe.core.run.TargetException;

/** The simulator as a run target: the robot guessed for a script, and errors as diagnostics. */
class SimTargetTest {
    private static Program load(String file, String groups) {
        String text = "<program><robot><structure>" + groups + "</structure></robot></program>";
        LoadResult r = ScriptLoader.loadText(Path.of(file), text, Map.of());
        assertTrue(r.ok(), r.diagnostics().toString());
        return r.program();
    }

    @Test
    void aFourModuleScriptWithLeftAndRightGroupsIsNotACentipede() {
        Program p = load("walker.xml", "<leftLeg elements=\"0, 1\"/><rightLeg elements=\"2, 3\"/>");
        assertEquals("snake", SimTarget.autoSpec(p));
    }

    @Test
    void aScriptThatFillsTheCentipedeRunsOnIt() {
        Program p = load("walker.xml", "<leftLeg elements=\"0..13\"/><rightLeg elements=\"14..27\"/><spine elements=\"28..54\"/>");
        assertEquals("centipede", SimTarget.autoSpec(p));
    }

    @Test
    void aWheelScriptRunsOnAWheel() {
        Program p = load("roll.xml", "<wheel elements=\"0..5\"/>");
        assertEquals("wheel", SimTarget.autoSpec(p));
    }

    @Test
    void aCentipedeNamedScriptWithMoreModulesThanTheRobotFallsBackToASnake() {
        Program p = load("centipede-big.xml", "<body elements=\"0..80\"/>");
        assertEquals("snake", SimTarget.autoSpec(p));
    }

    @Test
    void aBadSpecificationThrowsWithItsLocatedErrors() {
        DiagnosticList warnings = new DiagnosticList();
        TargetException e = org.junit.jupiter.api.Assertions.assertThrows(TargetException.class,
                () -> SimTarget.create("snake:n=-3", new int[] {0, 1}, warnings));
        assertEquals(1, e.diagnostics().size(), e.diagnostics().toString());
        assertTrue(e.diagnostics().get(0).format().startsWith("--sim snake:n=-3:1:7: error: n must be in 1..1000"),
                e.diagnostics().toString());
        assertTrue(warnings.all().isEmpty());
    }
}
