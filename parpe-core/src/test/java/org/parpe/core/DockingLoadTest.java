package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.export.Board;
import org.parpe.core.export.CExport;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.StateDef;
import org.parpe.core.print.ProgramPrinter;
import org.parpe.core.run.StimulusParser;

/**
 * PARSL 1.1 §14 in the loader: latch actuators, dock sensors and the plate actions of states,
 * their load errors located on the attribute or the instance, and plain runs that do not change
 * when a script gains them.
 */
class DockingLoadTest {
    private static final String ROBOT = "<robot><structure><g elements=\"0..3\"/><ends elements=\"0, 3\"/></structure>\n"
            + "<sensors><dock elements=\"ends\"/></sensors>\n<actuators><latch elements=\"ends\"/></actuators></robot>\n";

    private static String prog(String robot, String group, String states) {
        return "<program>\n" + robot + "<main><b/></main>\n<behaviors><b>\n<w group=\"" + group + "\"/>\n</b></behaviors>\n"
                + "<automata><w states=\"s\"/></automata>\n<states>\n" + states + "\n</states>\n</program>\n";
    }

    static Stream<Arguments> errors() {
        return Stream.of(
                Arguments.of("plate 2", prog(ROBOT, "ends", "<s angles=\"10\" latch=\"2\"/>"), 11,
                        "connection plates are 0 and 1"),
                Arguments.of("plate -1", prog(ROBOT, "ends", "<s angles=\"10\" unlatch=\"0, -1\"/>"), 11,
                        "lists '-1'"),
                Arguments.of("plate word", prog(ROBOT, "ends", "<s angles=\"10\" latch=\"left\"/>"), 11, "lists 'left'"),
                Arguments.of("empty plate", prog(ROBOT, "ends", "<s angles=\"10\" latch=\"0,\"/>"), 11, "empty item"),
                Arguments.of("both lists", prog(ROBOT, "ends", "<s angles=\"10\" latch=\"1, 0\" unlatch=\"1\"/>"), 11,
                        "both latches and unlatches plate 1"),
                Arguments.of("no latch actuator", prog(ROBOT, "g", "<s angles=\"10\" unlatch=\"1\"/>"), 7,
                        "module 1 of group 'g' has no latch actuator"),
                Arguments.of("no actuators at all", prog("<robot><structure><g elements=\"0, 1\"/></structure></robot>\n",
                        "g", "<s angles=\"10\" latch=\"0\"/>"), 5, "module 0 of group 'g' has no latch actuator"),
                Arguments.of("dock without the sensor", prog(ROBOT, "g", "<s angles=\"$_self_dock_0 * 10\"/>"), 7,
                        "to carry a dock sensor; module 1 has none"),
                Arguments.of("dock global without the sensor", prog(ROBOT, "g", "<s angles=\"$1_dock_1\"/>"), 11,
                        "module 1 has no dock sensor"),
                Arguments.of("dock without a plate", prog(ROBOT, "ends", "<s angles=\"$0_dock\"/>"), 11,
                        "dock needs a plate: _0 or _1"),
                Arguments.of("dock plate 2", prog(ROBOT, "ends", "<s angles=\"$0_dock_2\"/>"), 11,
                        "dock needs a plate: _0 or _1"),
                Arguments.of("unknown actuator", prog(ROBOT.replace("</actuators>", "<gripper elements=\"0\"/></actuators>"),
                        "ends", "<s angles=\"10\"/>"), 4, "actuator 'gripper' is not implemented; available: latch"),
                Arguments.of("latch on a module not in the robot", prog(ROBOT.replace("<latch elements=\"ends\"/>",
                        "<latch elements=\"7\"/>"), "ends", "<s angles=\"10\"/>"), 4,
                        "module 7 carries a latch actuator but is not in <structure>"),
                Arguments.of("latch declared twice", prog(ROBOT.replace("</actuators>", "<latch elements=\"0\"/></actuators>"),
                        "ends", "<s angles=\"10\"/>"), 4, "actuator 'latch' is declared twice in <actuators>"),
                Arguments.of("actuators twice", prog(ROBOT.replace("</robot>", "<actuators/></robot>"), "ends",
                        "<s angles=\"10\"/>"), 4, "<actuators> appears twice in <robot>"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("errors")
    void platesAndLatchesAreCheckedWhereTheyAreWritten(String name, String text, int line, String words) {
        LoadResult r = ScriptLoader.loadText(Path.of("dock.xml"), text, Map.of());
        assertFalse(r.ok(), name + " should not load");
        assertTrue(r.errors().stream().anyMatch(d -> d.pos().line() == line && d.message().contains(words)
                        && d.format().startsWith("dock.xml:" + line + ":")),
                () -> name + ": expected an error on line " + line + " containing '" + words + "', got "
                        + r.diagnostics().stream().map(Diagnostic::format).toList());
    }

    @Test
    void platesAreReadAscendingOnceAndPrintedBack() {
        String text = prog(ROBOT, "ends", "<s angles=\"10\" latch=\"1, 0, 1\"/>");
        LoadResult r = ScriptLoader.loadText(Path.of("dock.xml"), text, Map.of());
        assertTrue(r.ok(), () -> r.diagnostics().toString());
        StateDef s = r.program().automata().get(0).states().get(0);
        assertEquals(List.of(0, 1), s.latch());
        assertEquals(List.of(), s.unlatch());
        assertTrue(r.program().robot().actuates(3, "latch"));
        assertFalse(r.program().robot().actuates(1, "latch"));
        String printed = ProgramPrinter.print(r.program());
        assertTrue(printed.contains("latch=\"0, 1\""), printed);
        assertTrue(printed.contains("<latch elements=\"ends\"/>"), printed);
    }

    @Test
    void aStimulusSetsADockReadingOnlyWhereTheSensorIs() throws Exception {
        LoadResult r = ScriptLoader.loadText(Path.of("dock.xml"), prog(ROBOT, "ends", "<s angles=\"10\"/>"), Map.of());
        assertTrue(r.ok(), () -> r.diagnostics().toString());
        assertEquals(1, StimulusParser.parse("s.txt", "0.5 $3_dock_1=2\n", r.program()).size());
        StimulusParser.StimulusException e = assertThrows(StimulusParser.StimulusException.class,
                () -> StimulusParser.parse("s.txt", "# a module without the sensor\n1 $1_dock_0=2\n", r.program()));
        assertEquals("s.txt:2:1: error: module 1 has no dock sensor", e.getMessage());
        // the problem keeps its key and place, so it is shown in the user's language (issue 38)
        assertEquals(new org.parpe.core.diag.SourcePos("s.txt", 2, 1), e.diagnostic().pos());
        assertEquals("Modul 1 hat keinen Sensor dock", e.diagnostic().text().format(java.util.Locale.GERMAN));
        assertEquals("モジュール 1 には dock センサーがありません", e.diagnostic().text().format(java.util.Locale.JAPANESE));
        e = assertThrows(StimulusParser.StimulusException.class,
                () -> StimulusParser.parse("s.txt", "1 $0_dock_3=2\n", r.program()));
        assertTrue(e.getMessage().startsWith("s.txt:1:1: error: '$0_dock_3' is not a sensor reading"), e.getMessage());
    }

    @Test
    void theCExportRefusesPlateActionsAtTheState() {
        String text = prog(ROBOT, "ends", "<s angles=\"10\" latch=\"0\"/>");
        LoadResult r = ScriptLoader.loadText(Path.of("dock.xml"), text, Map.of());
        assertTrue(r.ok(), () -> r.diagnostics().toString());
        DiagnosticList d = new DiagnosticList();
        assertNull(CExport.export(r.program(), 0.02, Board.HOST, d));
        assertTrue(d.all().stream().anyMatch(x -> x.format().startsWith("dock.xml:11:2: error: state 's' arms connection plates")),
                () -> d.all().stream().map(Diagnostic::format).toList().toString());
        // without the plate actions the same robot, dock sensor included, exports
        LoadResult plain = ScriptLoader.loadText(Path.of("dock.xml"), prog(ROBOT, "ends", "<s angles=\"$_self_dock_0\"/>"),
                Map.of());
        assertNotNull(CExport.export(plain.program(), 0.02, Board.HOST, new DiagnosticList()));
    }

    /**
     * Issue 35's property: a plain run's trace does not change when a script gains latch
     * actuators and dock sensors on every module and a plate action on every named state.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("runCases")
    void plateActionsChangeNoPlainTrace(Path dir, @TempDir Path tmp) throws Exception {
        List<String> args = Conformance.args(dir);
        Conformance.Outcome before = Conformance.run(dir, args);
        Path copy = tmp.resolve(dir.getFileName());
        copyTree(dir, copy);
        Path program = copy.resolve(args.stream().filter(a -> a.endsWith(".xml")).findFirst().orElseThrow());
        String text = Files.readString(program);
        String docked = withDocking(text);
        Files.writeString(program, docked);
        Conformance.Outcome after = Conformance.run(copy, args);
        assertTrue(after.loaded(), () -> "does not load with docking: " + after.diagnostics() + "\n" + docked);
        assertEquals(before.trace(), after.trace());
    }

    static Stream<Path> runCases() throws Exception {
        List<Path> out = new ArrayList<>();
        for (Path c : Conformance.cases()) {
            List<String> args = Conformance.args(c);
            // cases whose robot lives in another file, or that declare sensors, keep their text
            String text = args.get(0).equals("check") ? "" : Files.readString(c.resolve(args.get(0)));
            if (text.contains("</structure>") && !text.contains("<sensors>") && !text.contains("<actuators>")) {
                out.add(c);
            }
        }
        assertTrue(out.size() >= 15, "too few conformance cases to transform: " + out.size());
        return out.stream();
    }

    /** {@code text} with a latch and a dock on every module and {@code latch="0, 1"} on every state. */
    static String withDocking(String text) {
        String robot = text.replace("</structure>", "</structure>\n    <sensors><dock elements=\"all\"/></sensors>\n"
                + "    <actuators><latch elements=\"all\"/></actuators>");
        int start = robot.indexOf("<states>");
        int end = robot.indexOf("</states>");
        if (start < 0 || end < 0) {
            return robot;
        }
        String states = robot.substring(start, end).replaceAll("(<[A-Za-z_][A-Za-z0-9_]*)(\\s+angles=\"[^\"]*\")", "$1$2 latch=\"0, 1\"");
        return robot.substring(0, start) + states + robot.substring(end);
    }

    private static void copyTree(Path from, Path to) throws Exception {
        try (Stream<Path> s = Files.walk(from)) {
            for (Path p : s.toList()) {
                Path t = to.resolve(from.relativize(p).toString());
                if (Files.isDirectory(p)) {
                    Files.createDirectories(t);
                } else {
                    Files.copy(p, t);
                }
            }
        }
    }
}
