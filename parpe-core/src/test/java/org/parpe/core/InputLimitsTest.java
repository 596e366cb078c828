package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;

/**
 * Bad input the loader must survive with a located error: other scripts' digits, included and
 * robot files that are devices, FIFOs or too large, and include chains too deep to recurse.
 */
class InputLimitsTest {
    @TempDir
    Path dir;

    static final String REST = "<main><b/></main>\n<behaviors><b><w group=\"g\" phase=\"PHASE\"/></b></behaviors>\n"
            + "<automata><w states=\"s\"/></automata>\n<states><s angles=\"10\"/></states>\n";
    static final String ROBOT = "<robot><structure><g elements=\"0, 1\"/></structure></robot>\n";

    private LoadResult load(String name, String text) throws Exception {
        Path f = dir.resolve(name);
        Files.writeString(f, text);
        return assertTimeoutPreemptively(Duration.ofSeconds(30), () -> ScriptLoader.load(f, Map.of()));
    }

    private static String errors(LoadResult r) {
        assertNull(r.program(), "the script should not load");
        return String.join("\n", r.errors().stream().map(Diagnostic::format).toList());
    }

    @Test
    void nonAsciiDigitsAreLocatedErrors() throws Exception {
        for (String digit : List.of("\u0663", "\u096A", "\uFF13")) { // Arabic-Indic, Devanagari, fullwidth
            String e = errors(load("digit.xml", "<program>\n" + ROBOT + REST.replace("PHASE", digit) + "</program>\n"));
            assertTrue(e.contains("digit.xml:4:35: error: '" + digit + "'") && e.contains("is not an ASCII digit"), e);
        }
        String range = errors(load("range.xml", "<program>\n<robot><structure><g elements=\"0..\u0663\"/>"
                + "</structure></robot>\n" + REST.replace("PHASE", "0") + "</program>\n"));
        assertTrue(range.contains("range.xml:2:35: error:") && range.contains("not an ASCII digit"), range);
    }

    @Test
    void includeChainsDeeperThanTheLimitAreLocatedAtTheInclude() throws Exception {
        int depth = 3000;
        for (int i = 1; i < depth; i++) {
            Files.writeString(dir.resolve("inc" + i + ".xml"), "<lib>\n  <include file=\"inc" + (i + 1) + ".xml\"/>\n</lib>\n");
        }
        Files.writeString(dir.resolve("inc" + depth + ".xml"), "<lib/>\n");
        String e = errors(load("deep.xml", "<program>\n" + ROBOT + REST.replace("PHASE", "0")
                + "<include file=\"inc1.xml\"/>\n</program>\n"));
        assertTrue(e.contains("inc64.xml:2:18: error: this include would nest 65 levels deep; includes nest at most 64"
                + " levels"), e);
        assertEquals(1, e.lines().count(), e);
    }

    @Test
    void includedAndRobotFilesThatAreDevicesFifosOrHugeAreRefused() throws Exception {
        Path fifo = dir.resolve("fifo.xml");
        new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor();
        Files.write(dir.resolve("big.xml"), new byte[(16 << 20) + 1]);
        for (String target : List.of("/dev/zero", "fifo.xml", "big.xml")) {
            String e = errors(load("inc.xml", "<program>\n" + ROBOT + REST.replace("PHASE", "0")
                    + "<include file=\"" + target + "\"/>\n</program>\n"));
            assertTrue(e.contains("inc.xml:7:16: error: cannot read included file"), e);
            String robot = errors(load("rob.xml", "<program>\n<robot file=\"" + target + "\"/>\n"
                    + REST.replace("PHASE", "0") + "</program>\n"));
            assertTrue(robot.contains("rob.xml:2:14: error: cannot read robot file"), robot);
            assertTrue(e.contains(target.equals("big.xml") ? "larger than the limit of 16 MiB" : "not a regular file"), e);
        }
    }
}
