package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;

/**
 * One case per kind of load-time diagnostic: the script marks the offending line with
 * {@code <!--E-->}; the error must be reported on that line, with the given words.
 */
class DiagnosticsTest {
    static final String ROBOT = "<robot><structure><g elements=\"0, 1, 2\"/><h elements=\"3, 4\"/></structure>"
            + "<sensors><touch elements=\"0, 1\"/></sensors></robot>\n";
    static final String REST = "<main><b/></main>\n<behaviors><b><w group=\"g\"/></b></behaviors>\n"
            + "<automata><w states=\"s\"/></automata>\n<states><s angles=\"10\"/></states>\n";

    static String prog(String body) {
        return "<program>\n" + body + "\n</program>\n";
    }

    static Stream<Arguments> cases() {
        return Stream.of(
            c("malformed XML", "<robot><structure><g elements=\"0\"/></structure></robot>\n<main><b></main> <!--E-->\n", "malformed XML"),
            // Issue 23, item 12: beginners' mistakes get what to type instead.
            c("unquoted attribute value", ROBOT + "<parameters>\n<period value=1/> <!--E-->\n</parameters>" + REST,
                    "an attribute's value goes in quotes: write value=\"1\""),
            c("letter O for zero", ROBOT + "<main><b/></main>\n<behaviors><b>\n<w group=\"g\" period=\"3O\"/> <!--E-->\n"
                    + "</b></behaviors>\n<automata><w states=\"s\"/></automata>\n<states><s angles=\"10\"/></states>\n",
                    "missing operator before 'O': is it the letter O where the digit 0 (zero) is meant? Write 30"),
            c("decimal comma", ROBOT + "<main><b/></main>\n<behaviors><b>\n<w group=\"g\" period=\"0,25\"/> <!--E-->\n"
                    + "</b></behaviors>\n<automata><w states=\"s\"/></automata>\n<states><s angles=\"10\"/></states>\n",
                    "a decimal number takes a point: write 0.25, not 0,25"),
            c("unknown section", ROBOT + REST + "<behaviours/> <!--E-->", "did you mean <behaviors>"),
            c("duplicate section", ROBOT + REST + "<states/> <!--E-->", "appears twice"),
            c("root attribute", null, "takes no attributes"),
            c("unknown attribute", ROBOT + "<main><b/></main><behaviors><b>\n<w group=\"g\" phaze=\"1\"/> <!--E-->\n</b></behaviors>"
                    + "<automata><w states=\"s\"/></automata><states><s angles=\"10\"/></states>", "did you mean 'phase'"),
            c("text where none allowed", ROBOT + REST + "<parameters>\nhello <!--E-->\n</parameters>", "text is not allowed"),
            c("missing robot", "", "no <robot>"),
            c("missing structure", "<robot> <!--E-->\n</robot>" + REST, "needs a <structure>"),
            c("missing attribute", "<robot><structure>\n<g/> <!--E-->\n</structure></robot>" + REST, "needs a 'elements'"),
            c("invalid name", ROBOT + "<parameters>\n<my-amp value=\"1\"/> <!--E-->\n</parameters>" + REST, "invalid name"),
            c("reserved word", ROBOT + "<parameters>\n<sin value=\"1\"/> <!--E-->\n</parameters>" + REST, "reserved word"),
            c("name clash", ROBOT + "<parameters>\n<g value=\"1\"/> <!--E-->\n</parameters>" + REST, "clashes with the group 'g'"),
            c("later group", "<robot><structure>\n<a elements=\"b\"/> <!--E-->\n<b elements=\"1\"/></structure></robot>"
                    + REST.replace("\"g\"", "\"a\""), "defined later"),
            c("undefined group in structure", "<robot><structure>\n<a elements=\"0, zz\"/> <!--E-->\n</structure></robot>"
                    + REST.replace("\"g\"", "\"a\""), "group 'zz' is not defined"),
            c("all in structure", "<robot><structure>\n<a elements=\"all\"/> <!--E-->\n</structure></robot>"
                    + REST.replace("\"g\"", "\"a\""), "'all' cannot be used"),
            c("module twice", "<robot><structure>\n<a elements=\"1, 2, 1\"/> <!--E-->\n</structure></robot>"
                    + REST.replace("\"g\"", "\"a\""), "appears twice"),
            c("module ID too large", "<robot><structure>\n<a elements=\"70000\"/> <!--E-->\n</structure></robot>"
                    + REST.replace("\"g\"", "\"a\""), "too large"),
            c("module ID 65536 names the value and the bound", "<robot><structure>\n<a elements=\"1,\n 65536\"/> <!--E-->\n"
                    + "</structure></robot>" + REST.replace("\"g\"", "\"a\""), "module ID 65536 is too large: module IDs are whole numbers 0..65535"),
            c("range past the largest module ID", "<robot><structure>\n<a elements=\"65530..65536\"/> <!--E-->\n</structure></robot>"
                    + REST.replace("\"g\"", "\"a\""), "is module ID 65536, too large: module IDs are whole numbers 0..65535"),
            c("empty item", "<robot><structure>\n<a elements=\"1, , 2\"/> <!--E-->\n</structure></robot>"
                    + REST.replace("\"g\"", "\"a\""), "empty item"),
            c("range over non-parameter", "<robot><structure>\n<a elements=\"0..$time\"/> <!--E-->\n</structure></robot>"
                    + REST.replace("\"g\"", "\"a\""), "not available here"),
            c("range end not whole", "<robot><structure>\n<a elements=\"0..2.5\"/> <!--E-->\n</structure></robot>"
                    + REST.replace("\"g\"", "\"a\""), "whole number"),
            c("unknown sensor", "<robot><structure><g elements=\"0\"/></structure><sensors>\n<sonar elements=\"0\"/> <!--E-->\n"
                    + "</sensors></robot>" + REST, "not implemented; available: angle, accel, touch"),
            c("sensor twice", "<robot><structure><g elements=\"0\"/></structure><sensors><angle elements=\"0\"/>\n"
                    + "<angle elements=\"0\"/> <!--E-->\n</sensors></robot>" + REST, "declared twice"),
            c("sensor on unknown module", "<robot><structure><g elements=\"0\"/></structure><sensors>\n"
                    + "<angle elements=\"7\"/> <!--E-->\n</sensors></robot>" + REST, "not in <structure>"),
            c("actuator", "<robot><structure><g elements=\"0\"/></structure><actuators>\n<gripper elements=\"0\"/> <!--E-->\n"
                    + "</actuators></robot>" + REST, "not implemented"),
            c("parameter not a number", ROBOT + "<parameters>\n<a value=\"ten\"/> <!--E-->\n</parameters>" + REST, "plain number"),
            c("parameter min > max", ROBOT + "<parameters>\n<a value=\"1\" min=\"5\" max=\"2\"/> <!--E-->\n</parameters>" + REST, "greater than max"),
            c("parameter outside range", ROBOT + "<parameters>\n<a value=\"9\" min=\"0\" max=\"5\"/> <!--E-->\n</parameters>" + REST, "within [0, 5]"),
            c("control type", ROBOT + "<controls>\n<c type=\"knob\" value=\"1\"/> <!--E-->\n</controls>" + REST, "slider, text or radio"),
            c("slider step", ROBOT + "<controls>\n<c type=\"slider\" min=\"0\" max=\"1\" value=\"0\" step=\"0\"/> <!--E-->\n</controls>" + REST, "step"),
            c("slider keys", ROBOT + "<controls>\n<c type=\"slider\" min=\"0\" max=\"1\" value=\"0\" keys=\"Up\"/> <!--E-->\n</controls>" + REST, "two keys"),
            c("unknown key", ROBOT + "<controls>\n<c type=\"radio\" values=\"a, b\" keys=\"q, F1\"/> <!--E-->\n</controls>" + REST, "unknown key 'F1'"),
            c("radio value", ROBOT + "<controls>\n<c type=\"radio\" values=\"a, b\" value=\"z\"/> <!--E-->\n</controls>" + REST, "one of a, b"),
            c("radio word twice", ROBOT + "<controls>\n<c type=\"radio\" values=\"a, a\"/> <!--E-->\n</controls>" + REST, "twice"),
            c("text control attribute", ROBOT + "<controls>\n<c type=\"text\" value=\"1\" min=\"0\"/> <!--E-->\n</controls>" + REST, "unknown attribute 'min'"),
            c("control named like a variable", ROBOT + "<controls>\n<time value=\"1\"/> <!--E-->\n</controls>" + REST, "logical variable"),
            c("radio word clash", ROBOT + "<parameters><left value=\"1\"/></parameters><controls>\n"
                    + "<turn type=\"radio\" values=\"left, right\"/> <!--E-->\n</controls>" + REST, "clashes with the parameter"),
            c("interp", ROBOT + "<main><b/></main><behaviors><b><w group=\"g\"/></b></behaviors><automata><w states=\"s\"/></automata>"
                    + "<states>\n<s angles=\"1\" interp=\"cubic\"/> <!--E-->\n</states>", "linear, step or smooth"),
            c("undefined state", ROBOT + "<main><b/></main><behaviors><b><w group=\"g\"/></b></behaviors><automata>\n"
                    + "<w states=\"s, upp\"/> <!--E-->\n</automata><states><s angles=\"1\"/><up angles=\"2\"/></states>", "did you mean 'up'"),
            c("states and table", ROBOT + "<main><b/></main><behaviors><b><w group=\"g\"/></b></behaviors><automata>\n"
                    + "<w states=\"s\">1; 2</w> <!--E-->\n</automata><states><s angles=\"1\"/></states>", "both"),
            c("no states", ROBOT + "<main><b/></main><behaviors><b><w group=\"g\"/></b></behaviors><automata>\n"
                    + "<w/> <!--E-->\n</automata>", "needs states"),
            c("times count", ROBOT + "<main><b/></main><behaviors><b><w group=\"g\"/></b></behaviors><automata>\n"
                    + "<w states=\"s\" times=\"1, 2\"/> <!--E-->\n</automata><states><s angles=\"1\"/></states>", "2 entries but it has 1 state"),
            c("exit syntax", ROBOT + "<main><b/></main><behaviors><b><w group=\"g\"/></b></behaviors><automata>\n"
                    + "<w states=\"s\" times=\"1[$time &gt; 1\"/> <!--E-->\n</automata><states><s angles=\"1\"/></states>", "T[E]"),
            c("unexpected character", ROBOT + exprCase("10 # 2"), "unexpected character '#'"),
            c("single =", ROBOT + exprCase("$time = 1"), "use '=='"),
            c("unterminated string", ROBOT + exprCase("\"abc"), "unterminated"),
            c("incomplete expression", ROBOT + exprCase("1 +"), "incomplete expression"),
            c("missing parenthesis", ROBOT + exprCase("(1 + 2"), "missing ')'"),
            c("unmatched parenthesis", ROBOT + exprCase("1 + 2)"), "no matching '('"),
            c("implicit multiplication", ROBOT + exprCase("2 pi"), "missing operator"),
            c("number too large", ROBOT + exprCase("1e400"), "too large"),
            c("unknown function", ROBOT + exprCase("sine(1)"), "did you mean 'sin'"),
            c("arity", ROBOT + exprCase("atan2(1)"), "takes 2 arguments, got 1"),
            c("sum without arguments", ROBOT + exprCase("sum()"), "at least one"),
            c("unknown name", ROBOT + "<parameters><speed value=\"1\"/></parameters>" + exprCase("speedx * 2"), "did you mean 'speed'"),
            c("group in expression", ROBOT + exprCase("g + 1"), "is a group"),
            c("control without dollar", ROBOT + "<controls><k value=\"1\"/></controls>" + exprCase("k * 2"), "'$k'"),
            c("unknown dollar name", ROBOT + exprCase("$tim"), "did you mean '$time'"),
            c("string not a radio word", ROBOT + exprCase("\"north\""), "not a radio word"),
            c("sensor not carried", ROBOT + exprCase("$3_touch_left"), "module 3 has no touch sensor"),
            c("sensor module missing", ROBOT + exprCase("$9_angle"), "not part of the robot"),
            c("sensor argument", ROBOT + "<robot/>".substring(0, 0) + exprCase("$0_touch"), "_left or _right"),
            c("local sensor outside module", ROBOT + "<main>\n<b exit=\"$_self_touch_left\"/> <!--E-->\n</main>"
                    + "<behaviors><b><w group=\"g\"/></b></behaviors><automata><w states=\"s\"/></automata><states><s angles=\"1\"/></states>", "only allowed in states"),
            c("$index outside module", ROBOT + "<main><b/></main><behaviors><b>\n<w group=\"g\" phase=\"$index\"/> <!--E-->\n</b></behaviors>"
                    + "<automata><w states=\"s\"/></automata><states><s angles=\"1\"/></states>", "not available here"),
            c("undefined automaton", ROBOT + "<main><b/></main><behaviors><b>\n<wave group=\"g\"/> <!--E-->\n</b></behaviors>"
                    + "<automata><w states=\"s\"/></automata><states><s angles=\"1\"/></states>", "automaton 'wave' is not defined"),
            c("undefined group", ROBOT + "<main><b/></main><behaviors><b>\n<w group=\"gg\"/> <!--E-->\n</b></behaviors>"
                    + "<automata><w states=\"s\"/></automata><states><s angles=\"1\"/></states>", "did you mean 'g'"),
            c("overlap", ROBOT.replace("\"3, 4\"", "\"2, 3\"") + "<main><b/></main><behaviors><b><w group=\"g\"/>\n<w group=\"h\"/> <!--E-->\n"
                    + "</b></behaviors><automata><w states=\"s\"/></automata><states><s angles=\"1\"/></states>", "overlaps group 'g'"),
            c("vector length", ROBOT + "<main><b/></main><behaviors><b>\n<w group=\"h\"/> <!--E-->\n</b></behaviors>"
                    + "<automata><w states=\"s\"/></automata><states><s angles=\"1, 2, 3\"/></states>", "3 angles but group 'h' has 2"),
            c("local sensor position", ROBOT + "<main><b/></main><behaviors><b>\n<w group=\"h\"/> <!--E-->\n</b></behaviors>"
                    + "<automata><w states=\"s\"/></automata><states><s angles=\"$_2_angle\"/></states>", "more than 2 modules"),
            c("local sensor carried", ROBOT + "<main><b/></main><behaviors><b>\n<w group=\"g\"/> <!--E-->\n</b></behaviors>"
                    + "<automata><w states=\"s\"/></automata><states><s angles=\"$_self_touch_left\"/></states>", "module 2 has none"),
            c("macro named time", ROBOT + "<main><b/></main><behaviors>\n<b macros=\"time\"> <!--E-->\n<w group=\"g\"/></b></behaviors>"
                    + "<automata><w states=\"s\"/></automata><states><s angles=\"1\"/></states>", "cannot be named 'time'"),
            c("group macro in arithmetic", ROBOT + "<main><b m=\"g\"/></main><behaviors><b macros=\"m\">\n<w group=\"m\" phase=\"m * 2\"/> <!--E-->\n"
                    + "</b></behaviors><automata><w states=\"s\"/></automata><states><s angles=\"1\"/></states>", "names a group"),
            c("missing macro value", ROBOT + "<main>\n<b/> <!--E-->\n</main><behaviors><b macros=\"d\"><w group=\"g\" phase=\"d\"/>"
                    + "</b></behaviors><automata><w states=\"s\"/></automata><states><s angles=\"1\"/></states>", "macro 'd'"),
            c("macro value not a group", ROBOT + "<main>\n<b m=\"legs\"/> <!--E-->\n</main><behaviors><b macros=\"m\"><w group=\"m\"/>"
                    + "</b></behaviors><automata><w states=\"s\"/></automata><states><s angles=\"1\"/></states>", "is not a group"),
            c("overlap through macros", ROBOT.replace("\"3, 4\"", "\"2, 3\"") + "<main>\n<b m=\"h\"/>\n</main><behaviors><b macros=\"m\">"
                    + "<w group=\"g\"/>\n<w group=\"m\"/> <!--E-->\n</b></behaviors><automata><w states=\"s\"/></automata>"
                    + "<states><s angles=\"1\"/></states>", "in this invocation"),
            c("undefined behavior", ROBOT + "<main>\n<walk/> <!--E-->\n</main><behaviors><b><w group=\"g\"/></b></behaviors>"
                    + "<automata><w states=\"s\"/></automata><states><s angles=\"1\"/></states>", "behavior 'walk' is not defined"),
            c("main cycles", ROBOT + "<main cycles=\"1.5\"> <!--E-->\n<b/></main><behaviors><b><w group=\"g\"/></b></behaviors>"
                    + "<automata><w states=\"s\"/></automata><states><s angles=\"1\"/></states>", "whole number"),
            c("include unreadable", ROBOT + REST + "<include file=\"no/such.xml\"/> <!--E-->", "cannot read included file"),
            c("robot file unreadable", "<robot file=\"no/robot.xml\"/> <!--E-->\n" + REST, "cannot read robot file"),
            c("dollar before a parameter", ROBOT + "<parameters><amp value=\"1\"/></parameters>" + exprCase("2 * $amp"),
                    "parameter 'amp' is written without '$': amp"),
            c("robot file with children", "<robot file=\"r.xml\"> <!--E-->\n<structure/></robot>" + REST, "cannot also contain"));
    }

    private static String exprCase(String angle) {
        return "<main><b/></main><behaviors><b><w group=\"g\"/></b></behaviors><automata><w states=\"s\"/></automata><states>\n"
                + "<s angles=\"" + angle.replace("\"", "&quot;") + "\"/> <!--E-->\n</states>";
    }

    private static Arguments c(String name, String body, String words) {
        String text = body == null ? "<program version=\"1\"> <!--E-->\n" + ROBOT + REST + "</program>\n"
                : body.isEmpty() ? "<program> <!--E-->\n" + REST + "</program>\n" : prog(body);
        return Arguments.of(name, text, words);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void reportedOnItsLine(String name, String text, String words) {
        List<String> lines = List.of(text.split("\n", -1));
        LoadResult r = ScriptLoader.loadText(Path.of("case.xml"), text, Map.of());
        assertFalse(r.ok(), name + " should not load");
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).contains("<!--E-->")) {
                int line = i + 1;
                assertTrue(r.errors().stream().anyMatch(d -> d.pos().line() == line && d.message().contains(words)
                                && d.format().startsWith("case.xml:" + line + ":")),
                        () -> name + ": expected an error on line " + line + " containing '" + words + "', got "
                                + r.diagnostics().stream().map(Diagnostic::format).toList() + "\n" + text);
            }
        }
    }

    @org.junit.jupiter.api.Test
    void aParameterOutsideItsBoundsIsReportedOnceNotAgainAtItsUses() {
        String text = prog(ROBOT + "<parameters>\n<amp value=\"90\" min=\"0\" max=\"45\"/>\n</parameters>"
                + exprCase("amp"));
        LoadResult r = ScriptLoader.loadText(Path.of("case.xml"), text, Map.of());
        assertFalse(r.ok());
        org.junit.jupiter.api.Assertions.assertEquals(1, r.errors().size(),
                () -> r.diagnostics().stream().map(Diagnostic::format).toList().toString());
        assertTrue(r.errors().get(0).message().contains("must be within [0, 45], got 90"), r.errors().toString());
    }
}
