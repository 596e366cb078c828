package org.parpe.core.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;

/**
 * The pure parts of the C export: literals carry the exact double, the RAM estimate on an
 * ATmega328P equals {@code sizeof(parsl_rt)} as avr-gcc 5.4 laid it out for three examples
 * (317, 810 and 1 801 bytes, measured with avr-size), and what cannot be exported is refused
 * with a located error. The trace equality itself is proven in parpe-cli ({@code ExportEqualityTest}).
 */
class CExportTest {
    private static Program load(String text) {
        LoadResult r = ScriptLoader.loadText(Path.of("t.xml"), text, Map.of());
        assertNotNull(r.program(), () -> r.diagnostics().toString());
        return r.program();
    }

    static Program example(String name) {
        Path dir = Path.of("").toAbsolutePath();
        while (!dir.resolve("examples/" + name).toFile().isFile()) {
            dir = dir.getParent();
        }
        LoadResult r = ScriptLoader.load(dir.resolve("examples/" + name), Map.of());
        assertNotNull(r.program(), () -> r.diagnostics().toString());
        return r.program();
    }

    @Test
    void literalsAreExact() {
        SplittableRandom random = new SplittableRandom(3);
        for (int i = 0; i < 10_000; i++) {
            double v = Double.longBitsToDouble(random.nextLong());
            if (!Double.isFinite(v)) {
                continue;
            }
            String lit = CExpressions.literal(v);
            String inner = lit.substring(lit.startsWith("(") ? 1 : 0, lit.length() - (lit.endsWith(")") ? 1 : 0));
            assertEquals(Double.doubleToRawLongBits(v), Double.doubleToRawLongBits(Double.parseDouble(inner)), lit);
        }
        assertEquals("(-0.0)", CExpressions.literal(-0.0));
        assertEquals("0.0", CExpressions.literal(0.0));
    }

    @Test
    void unoStateEstimateEqualsWhatAvrGccLaysOut() {
        assertEquals(329, CExport.estimate(example("hello-snake.xml"), 0.01, Board.UNO).stateBytes());
        assertEquals(822, CExport.estimate(example("teleop-dirwave.xml"), 0.01, Board.UNO).stateBytes());
        assertEquals(1813, CExport.estimate(example("centipede-walk.xml"), 0.01, Board.UNO).stateBytes());
    }

    @Test
    void aProgramWithoutMainIsRefusedAtItsFile() {
        Program p = load("<program><robot><structure><g elements=\"0\"/></structure></robot></program>");
        DiagnosticList d = new DiagnosticList();
        assertNull(CExport.export(p, 0.01, Board.HOST, d));
        assertEquals("t.xml:1:1: error: the program has no <main>; an exported program needs one to run",
                d.all().get(0).format());
    }

    @Test
    void aProgramTooLargeForTheBoardIsRefusedAtTheRobot() {
        Program p = load("<program>\n<robot><structure><g elements=\"0..199\"/></structure></robot>\n"
                + "<main><go/></main><behaviors><go><w group=\"g\" phase=\"0.01\"/></go></behaviors>"
                + "<automata><w states=\"a, b\"/></automata><states><a angles=\"10\"/><b angles=\"-10\"/></states></program>");
        DiagnosticList d = new DiagnosticList();
        assertNull(CExport.export(p, 0.01, Board.UNO, d));
        assertTrue(d.all().get(0).format().startsWith("t.xml:2:2: error: the program needs about "), d.all().toString());
        assertNotNull(CExport.export(p, 0.01, Board.ESP32, new DiagnosticList()));
    }

    /**
     * Issue 21 item 7: on a board with 32-bit floats, export warns at each expression that applies
     * a periodic function to $time or $btime, with the error to expect, and at nothing else; a
     * board with 64-bit doubles gets no warning.
     */
    @Test
    void wavesOfTheClockAreWarnedAboutOnAnAvr() {
        Program p = load("<program>\n<robot><structure><g elements=\"0\"/><h elements=\"1\"/></structure></robot>\n"
                + "<main><go/></main><behaviors><go><w group=\"g\" period=\"1+$time/1000\"/><v group=\"h\"/></go></behaviors>\n"
                + "<automata><w states=\"a, b\"/><v states=\"c\"/></automata>\n<states><a angles=\"30*sin(2*pi*$time)\"/>"
                + "<b angles=\"mod($time, 2) + $btime % 3\"/>\n<c angles=\"30*sin(2*pi*$phase) + $time\"/></states></program>");
        DiagnosticList d = new DiagnosticList();
        assertNotNull(CExport.export(p, 0.01, Board.UNO, d));
        List<String> warnings = d.all().stream().map(Diagnostic::format).filter(w -> w.contains("$time and $btime")).toList();
        assertEquals(2, warnings.size(), d.all().toString());
        assertTrue(warnings.stream().allMatch(w -> w.startsWith("t.xml:5:")), warnings.toString());
        assertTrue(warnings.get(0).contains(": warning: on uno $time and $btime are 32-bit floats, with steps of 0.24 ms"
                + " after an hour, 7.8 ms after a day and 62.5 ms after a week"), warnings.get(0));
        DiagnosticList esp = new DiagnosticList();
        assertNotNull(CExport.export(p, 0.01, Board.ESP32, esp));
        assertTrue(esp.all().isEmpty(), esp.all().toString());
    }
}
