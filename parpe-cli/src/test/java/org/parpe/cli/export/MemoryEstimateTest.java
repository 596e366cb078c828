package org.parpe.cli.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.parpe.cli.Cli;

/**
 * The RAM estimate printed by {@code parpe export} is the real size of the runtime's state: for
 * examples with and without sensors, controls and several entries, it equals
 * {@code sizeof(parsl_rt)} as gcc lays the struct out on this machine.
 */
class MemoryEstimateTest {
    static final Pattern STATE = Pattern.compile("memory \\(host\\): (\\d+) bytes of state");

    @TempDir
    Path tmp;

    @BeforeAll
    static void compilerInstalled() {
        HostCompiler.require("gcc");
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"hello-snake", "centipede-walk", "teleop-dirwave", "sensor-exit", "standup-walk"})
    void stateEstimateEqualsSizeofParslRt(String example) throws Exception {
        Cli export = Cli.run(List.of("export",
                ExportEqualityTest.ROOT.resolve("examples/" + example + ".xml").toString(), "--out", tmp.toString()));
        assertEquals(0, export.code, () -> "export: " + export);
        Matcher m = STATE.matcher(export.out);
        assertTrue(m.find(), export.out);
        Files.writeString(tmp.resolve("size.c"), "#include \"parsl_rt.h\"\n#include <stdio.h>\n"
                + "int main(void)\n{\n    printf(\"%zu\\n\", sizeof(parsl_rt));\n    return 0;\n}\n");
        HostCompiler.Result cc = HostCompiler.run(tmp, List.of("gcc", "-std=c99", "-o", "size", "size.c"), 60);
        assertEquals(0, cc.code(), cc.err());
        HostCompiler.Result size = HostCompiler.run(tmp, List.of(tmp.resolve("size").toString()), 30);
        assertEquals(size.out().trim(), m.group(1), "bytes of state of " + example);
    }
}
