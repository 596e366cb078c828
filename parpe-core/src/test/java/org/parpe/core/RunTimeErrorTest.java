package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;
import org.parpe.core.run.Engine;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.ScriptRuntimeError;
import org.parpe.core.run.TraceWriter;

/** Run-time errors stop the run with a located message; warnings of overlapping instances. */
class RunTimeErrorTest {
    static Program load(String text) {
        LoadResult r = ScriptLoader.loadText(Path.of("rt.xml"), text, Map.of());
        assertTrue(r.ok(), () -> r.diagnostics().toString());
        return r.program();
    }

    static String wave(String angle, String instanceAttrs) {
        return "<program>\n<robot><structure><g elements=\"0, 1\"/></structure></robot>\n"
                + "<controls><k type=\"slider\" min=\"-1\" max=\"1\" value=\"1\"/></controls>\n"
                + "<main><b/></main>\n<behaviors><b><w group=\"g\"" + instanceAttrs + "/></b></behaviors>\n"
                + "<automata><w states=\"s, t\"/></automata>\n"
                + "<states>\n<s angles=\"" + angle + "\"/>\n<t angles=\"0\"/></states>\n</program>\n";
    }

    @Test
    void divisionByZeroNamesTheExpressionAndTheTick() {
        Program p = load(wave("10 / ($time - 0.5)", ""));
        Engine e = new Engine(p, RunOptions.defaults());
        StringWriter trace = new StringWriter();
        e.addObserver(new TraceWriter(trace));
        e.start();
        ScriptRuntimeError err = assertThrows(ScriptRuntimeError.class, () -> {
            for (int i = 0; i < 200; i++) {
                e.step();
            }
        });
        assertTrue(err.getMessage().startsWith("rt.xml:8:12: error: division by zero in '10 / ($time - 0.5)'"), err.getMessage());
        assertTrue(err.getMessage().contains("t=0.500000"), err.getMessage());
        assertEquals(51, trace.toString().split("\n").length, "header plus ticks 0..0.49: the failing tick is not written");
    }

    @Test
    void aPeriodThatBecomesNegativeStopsTheRun() {
        Program p = load(wave("10", " period=\"$k\""));
        Engine e = new Engine(p, RunOptions.defaults());
        e.start();
        e.step();
        e.setControl("k", -0.5);
        ScriptRuntimeError err = assertThrows(ScriptRuntimeError.class, e::step);
        assertTrue(err.getMessage().contains("period of automaton 'w' must be > 0, got -0.5"), err.getMessage());
    }

    @Test
    void overlappingConditionalInstancesWarnOncePerPair() {
        String text = "<program><robot><structure><g elements=\"0, 1\"/><h elements=\"1, 2\"/></structure></robot>"
                + "<main><b/></main><behaviors><b><if cond=\"1\"><w group=\"g\"/></if><if cond=\"1\"><w group=\"h\"/></if></b></behaviors>"
                + "<automata><w states=\"s\"/></automata><states><s angles=\"10\"/></states></program>";
        Engine e = new Engine(load(text), RunOptions.defaults());
        List<Diagnostic> warnings = new ArrayList<>();
        e.setWarningSink(warnings::add);
        e.start();
        for (int i = 0; i < 100; i++) {
            e.step();
        }
        assertEquals(1, warnings.size(), warnings.toString());
        assertTrue(warnings.get(0).message().contains("both drive module 1"), warnings.toString());
    }

    @Test
    void statesFarShorterThanTheTickStopTheRunInsteadOfSpinning() {
        String text = wave("10", "").replace("<w states=\"s, t\"/>", "<w states=\"s, t\" times=\"1e-7, 1e-7\"/>");
        Engine e = new Engine(load(text), RunOptions.defaults());
        e.start();
        e.step();
        ScriptRuntimeError err = assertThrows(ScriptRuntimeError.class, e::step);
        assertTrue(err.getMessage().contains("more than 10000 state changes in one tick"), err.getMessage());
    }

    @Test
    void controlsAreCheckedWhenSet() {
        Engine e = new Engine(load(wave("10", "")), RunOptions.defaults());
        assertThrows(IllegalArgumentException.class, () -> e.setControl("k", 5));
        assertThrows(IllegalArgumentException.class, () -> e.setControl("nope", 0));
    }

    @Test
    void aNegativeDurationIsARunTimeErrorNamingAutomatonStateAndValue() {
        // PARSL 1.0.1 §13 rule 21: the duration becomes negative at t = 0.3, the run stops there
        String text = wave("10", "").replace("<w states=\"s, t\"/>", "<w states=\"s, t\" times=\"1, 0.25 - $time\"/>");
        Engine e = new Engine(load(text), RunOptions.defaults());
        StringWriter trace = new StringWriter();
        e.addObserver(new TraceWriter(trace));
        e.start();
        ScriptRuntimeError err = assertThrows(ScriptRuntimeError.class, () -> {
            for (int i = 0; i < 100; i++) {
                e.step();
            }
        });
        assertTrue(err.getMessage().startsWith("rt.xml:6:38: error: "), err.getMessage()); // at the times expression
        assertTrue(err.getMessage().contains("state 't' of automaton 'w' has a negative duration: -0.01 s"), err.getMessage());
        assertTrue(err.getMessage().contains("t=0.260000"), err.getMessage());
    }

    @Test
    void anInstanceWithCyclesZeroEvaluatesNothingAndDrivesNothing() {
        // PARSL 1.0.1 §13 rule 19: durations that would be an error are never evaluated
        String text = wave("10", " cycles=\"0\"").replace("<w states=\"s, t\"/>", "<w states=\"s, t\" times=\"-1, 0\"/>")
                .replace("<main><b/></main>", "<main><b time=\"0.05\"/></main>");
        Engine e = new Engine(load(text), RunOptions.defaults());
        StringWriter trace = new StringWriter();
        e.addObserver(new TraceWriter(trace));
        e.start();
        while (e.step()) {
            // runs to the entry's end
        }
        assertEquals("time,m0,m1\n0.000000,0.000000,0.000000\n0.010000,0.000000,0.000000\n", trace.toString());
    }

    @Test
    void anInstanceWithCyclesZeroUnderAnIfCausesNoOverlapWarning() {
        // PARSL 1.0.1 §13 rule 19: it never drives its modules, so it never competes for one
        String text = "<program><robot><structure><g elements=\"0, 1\"/><h elements=\"1, 2\"/></structure></robot>"
                + "<main><b/></main><behaviors><b><w group=\"g\"/><if cond=\"1\"><w group=\"h\" cycles=\"-0.0\"/></if>"
                + "<if cond=\"1\"><w group=\"h\" cycles=\"0\"/></if></b></behaviors>"
                + "<automata><w states=\"s\"/></automata><states><s angles=\"10\" interp=\"step\"/></states></program>";
        Engine e = new Engine(load(text), RunOptions.defaults());
        List<Diagnostic> warnings = new ArrayList<>();
        e.setWarningSink(warnings::add);
        StringWriter trace = new StringWriter();
        e.addObserver(new TraceWriter(trace));
        e.start();
        for (int i = 0; i < 3; i++) {
            e.step();
        }
        assertEquals(List.of(), warnings);
        assertTrue(trace.toString().endsWith("0.020000,10.000000,10.000000,0.000000\n"), trace.toString());
    }
}
