package org.parpe.core.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;

/**
 * Issue 36 item 3: the exported C computes a sub-expression of an angle that depends on
 * {@code $index $count $id} only once per module instead of at every tick (perf on the 1 000-module
 * benchmark snake: {@code cos(pi*$index/$count)} was 13 % of its time). Which sub-expressions are
 * kept, where the values live, and that AVR boards (and the flash estimate) see none of it; that
 * the kept program's trace is the interpreter's is ExportEqualityTest's ({@code kept-values},
 * {@code kept-divide-by-zero}).
 */
class ModuleConstantsTest {
    private static final Pattern KEPT = Pattern.compile("parsl_kept\\[(\\d+)\\]\\[r->group_off \\+ r->index\\] = (t\\d+);");

    private static Program program(String states) {
        String text = "<program><robot><structure><body elements=\"0..9\"/><tail elements=\"10..12\"/></structure></robot>"
                + "<main><go/></main><behaviors><go><w group=\"body\" phase=\"1/$count\" period=\"2\"/>"
                + "<w group=\"tail\" phase=\"0.1\" period=\"2\"/></go></behaviors>"
                + "<automata><w states=\"a, b\"/></automata><states>" + states + "</states></program>";
        LoadResult r = ScriptLoader.loadText(Path.of("kept.xml"), text, Map.of());
        assertNotNull(r.program(), () -> r.diagnostics().toString());
        return r.program();
    }

    private static CProgram translate(String states) {
        return CProgram.of(program(states), 0.01);
    }

    private static int kept(String source) {
        Matcher m = KEPT.matcher(source);
        int n = 0;
        while (m.find()) {
            assertEquals(String.valueOf(n), m.group(1), "kept values are numbered in order");
            n++;
        }
        return n;
    }

    @Test
    void theBenchmarksCosineOfTheIndexIsKeptAndItsWaveIsNot() {
        CProgram c = translate("<a angles=\"30*sin(2*pi*$phase) + 2*cos(pi*$index/$count)\"/>"
                + "<b angles=\"-30*sin(2*pi*($phase + $index/$count)) - 5*$cycle/($cycle+1)\"/>");
        String source = c.source();
        assertEquals(2, kept(source), "cos(pi*$index/$count), and $index/$count in the second wave:\n" + source);
        // one value per position of every instance's group: 10 + 3
        assertTrue(source.contains("static double parsl_kept[2][13];"), source);
        assertTrue(source.contains("#if !defined(__AVR__)\n"), "not compiled for AVR boards");
        assertEquals(26, c.keptValues());
        assertFalse(source.contains("parsl_kept[0][r->group_off + r->index] = t2;"), "sin($phase) is not kept");
    }

    @Test
    void nothingIsKeptWhereNothingIsWorthIt() {
        // the clock, the phase, a control-free product of the index (cheaper than reading a kept value)
        CProgram c = translate("<a angles=\"3*$index + $time\"/><b angles=\"sin($phase*$index)\"/>");
        String source = c.source();
        assertEquals(0, kept(source), source);
        assertFalse(source.contains("PARSL_KEEP"), "no trace of keeping in a program that keeps nothing");
        assertEquals(0, c.keptValues());
    }

    @Test
    void anAvrBoardsEstimateIsThatOfTheCodeItCompilesAndAnEsp32CountsTheKeptValues() {
        // the same statements but for $index and $phase: only the first keeps a value
        String keeping = "<a angles=\"2*cos(pi*$index/$count) + $time\"/><b angles=\"-20\"/>";
        String plain = "<a angles=\"2*cos(pi*$phase/$count) + $time\"/><b angles=\"-20\"/>";
        assertEquals(1, kept(translate(keeping).source()));
        assertEquals(0, kept(translate(plain).source()));
        MemoryReport uno = CExport.estimate(program(keeping), 0.01, Board.UNO);
        assertEquals(CExport.estimate(program(plain), 0.01, Board.UNO), uno, "AVR compiles the same code");
        MemoryReport esp32 = CExport.estimate(program(keeping), 0.01, Board.ESP32);
        assertEquals(esp32.stateBytes() + esp32.boardBytes() + 13 * (8 + 1), esp32.ramBytes(),
                "ESP32: a double and a flag for each of the 13 positions");
        assertTrue(esp32.format().contains(", kept values 117)"), esp32.format());
    }

    /** The root of the expression {@code text} in a state's angle. */
    private static org.parpe.core.expr.Node angle(String text) {
        return program("<a angles=\"" + text + "\"/><b angles=\"0\"/>").automata().get(0).states().get(0).angles()
                .get(0).root();
    }

    @Test
    void partsTheSameForEveryModuleInATickAreShared() {
        // the benchmark's second wave: the same for every module with the same cycle count
        assertTrue(ModuleConstants.worthSharing(angle("5*$cycle/($cycle+1)")));
        assertTrue(ModuleConstants.readsCycle(angle("5*$cycle/($cycle+1)")));
        assertTrue(ModuleConstants.worthSharing(angle("sin(2*pi*$time)")));
        assertFalse(ModuleConstants.readsCycle(angle("sin(2*pi*$time)")));
        assertFalse(ModuleConstants.worthSharing(angle("$cycle + $time")), "no costly operation: cheaper to compute");
        assertFalse(ModuleConstants.worthSharing(angle("sin($phase)")), "$phase is the module's");
        assertFalse(ModuleConstants.worthSharing(angle("sin($time + $index)")), "$index is the module's");
    }

    @Test
    void theCommonCaseIsGeneratedForOneAngleWithoutExitAndNotForAVR() {
        String source = translate("<a angles=\"30*sin(2*pi*$phase) + 5*$cycle/($cycle+1)\"/>"
                + "<b angles=\"rand()\"/>").source();
        String fast = source.substring(source.indexOf("#ifdef PARSL_FAST"));
        assertTrue(fast.contains("case 0: a = f"), "state a, one angle, has the common case:\n" + fast);
        assertFalse(fast.contains("case 1: a = f"), "state b draws a random number: parsl_advance runs it:\n" + fast);
        assertTrue(fast.contains("memo[0].ok && parsl_same(memo[0].cycle, m->cycle)"), fast);
        assertFalse(fast.contains("parsl_raise"), "the unchecked form raises nothing itself:\n" + fast);
    }
}
