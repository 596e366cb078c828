package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.Engine;
import org.parpe.core.run.PlateSink;
import org.parpe.core.run.PlatesByHand;
import org.parpe.core.run.RunOptions;

/**
 * When plate actions happen (PARSL.md §14): on entering a state (placement, time-driven and exit
 * transitions, wraps), in document order of the instances, only while an instance is not frozen
 * by its {@code <if>}; and a robot without latches tells the user once per plate and action.
 */
class PlateActionsTest {
    /** One recorded action: tick, module ID, plate, action and the line of the state. */
    record Act(long tick, int id, int plate, byte act, int line) {
    }

    private static List<Act> run(String text, int ticks, double dt) {
        LoadResult r = ScriptLoader.loadText(Path.of("plates.xml"), text, Map.of());
        assertTrue(r.ok(), () -> r.diagnostics().stream().map(Diagnostic::format).toList().toString());
        Engine e = new Engine(r.program(), new RunOptions(dt, 0, List.of()));
        int[] ids = e.moduleIds();
        List<Act> out = new ArrayList<>();
        e.addPlateSink((tick, time, acts, where) -> {
            for (int j = 0; j < acts.length; j++) {
                if (acts[j] != PlateSink.NONE) {
                    out.add(new Act(tick, ids[j >> 1], j & 1, acts[j], where[j].line()));
                }
            }
        });
        e.start();
        for (int i = 0; i < ticks && e.step(); i++) {
            // run
        }
        return out;
    }

    private static String prog(String robot, String main, String behaviors, String automata, String states) {
        return "<program>\n<robot><structure>" + robot + "</structure>\n<actuators><latch elements=\"all\"/></actuators></robot>\n"
                + "<main>" + main + "</main>\n<behaviors>" + behaviors + "</behaviors>\n<automata>" + automata
                + "</automata>\n<states>\n" + states + "</states>\n</program>\n";
    }

    @Test
    void placementTransitionsAndWrapsEnterStates() {
        // states a (line 8) arms plate 0, b (line 9) releases it and arms plate 1; 1 s each, tick 0.5 s; the entry
        // ends at tick 9 without entering a state
        String text = prog("<g elements=\"3\"/>", "<b time=\"4.5\"/>", "<b><w group=\"g\"/></b>", "<w states=\"a, b\"/>",
                "<a angles=\"0\" latch=\"0\"/>\n<b angles=\"10\" unlatch=\"0\" latch=\"1\"/>\n");
        List<Act> acts = run(text, 100, 0.5);
        assertEquals(List.of(
                new Act(0, 3, 0, PlateSink.ARM, 8),
                new Act(2, 3, 0, PlateSink.RELEASE, 9), new Act(2, 3, 1, PlateSink.ARM, 9),
                new Act(4, 3, 0, PlateSink.ARM, 8),
                new Act(6, 3, 0, PlateSink.RELEASE, 9), new Act(6, 3, 1, PlateSink.ARM, 9),
                new Act(8, 3, 0, PlateSink.ARM, 8)), acts);
    }

    @Test
    void theLastStateEnteredInATickDecides() {
        // each tick of 1 s passes from a through b (0.25 s, arms plate 0) and c (0.25 s, releases it) into a, which
        // has no action: c's release is the tick's action
        String text = prog("<g elements=\"0\"/>", "<b time=\"2.5\"/>", "<b><w group=\"g\"/></b>",
                "<w states=\"a, b, c\" times=\"0.5, 0.25, 0.25\"/>",
                "<a angles=\"0\"/>\n<b angles=\"10\" latch=\"0\"/>\n<c angles=\"5\" unlatch=\"0\"/>\n");
        assertEquals(List.of(new Act(1, 0, 0, PlateSink.RELEASE, 10), new Act(2, 0, 0, PlateSink.RELEASE, 10)),
                run(text, 10, 1));
    }

    @Test
    void theLaterInstanceWinsAndAFrozenInstanceEntersNothing() {
        String text = prog("<g elements=\"0, 1\"/><h elements=\"1\"/>", "<b time=\"1\"/>",
                "<b><w group=\"g\"/><if cond=\"1\"><u group=\"h\"/></if><if cond=\"0\"><w group=\"h\"/></if></b>",
                "<w states=\"a\"/><u states=\"c\"/>", "<a angles=\"0\" latch=\"0, 1\"/>\n<c angles=\"5\" unlatch=\"0\"/>\n");
        List<Act> acts = run(text, 1, 0.1);
        assertEquals(List.of(
                new Act(0, 0, 0, PlateSink.ARM, 8), new Act(0, 0, 1, PlateSink.ARM, 8),
                new Act(0, 1, 0, PlateSink.RELEASE, 9), new Act(0, 1, 1, PlateSink.ARM, 8)), acts);
    }

    @Test
    void aRobotWithoutLatchesIsToldOncePerPlateAndAction() {
        String text = prog("<g elements=\"4, 9\"/>", "<b time=\"10\"/>", "<b><w group=\"g\"/></b>", "<w states=\"a, b\"/>",
                "<a angles=\"0\" latch=\"0\"/>\n<b angles=\"10\" unlatch=\"0\"/>\n");
        LoadResult r = ScriptLoader.loadText(Path.of("plates.xml"), text, Map.of());
        Engine e = new Engine(r.program(), new RunOptions(0.1, 0, List.of()));
        DiagnosticList told = new DiagnosticList();
        e.addPlateSink(new PlatesByHand(told, e.moduleIds(), "these servos"));
        e.start();
        while (e.step()) {
            // ten cycles of arming and releasing
        }
        List<String> lines = told.all().stream().map(Diagnostic::format).toList();
        assertEquals(List.of(
                "plates.xml:8:2: warning: at t=0.000 s module 4 arms plate 0, but these servos have no latching plates:"
                        + " join that plate to the plate it meets by hand (told once per plate)",
                "plates.xml:8:2: warning: at t=0.000 s module 9 arms plate 0, but these servos have no latching plates:"
                        + " join that plate to the plate it meets by hand (told once per plate)",
                "plates.xml:9:2: warning: at t=1.000 s module 4 releases plate 0, but these servos have no latching"
                        + " plates: part that plate from the one it holds by hand (told once per plate)",
                "plates.xml:9:2: warning: at t=1.000 s module 9 releases plate 0, but these servos have no latching"
                        + " plates: part that plate from the one it holds by hand (told once per plate)"), lines);
    }
}
