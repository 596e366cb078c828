package org.parpe.core.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;

/**
 * The tables' layout is declared once (issue 19 item 7): in {@link CLayout}, from which the translation writes
 * the rows and {@code parsl_program.h} gets the names the runtime reads them by. Before, the runtime's
 * {@code parsl_rt.h} declared the widths and column indices itself and {@link CTables} wrote rows by position,
 * so a column added on one side compiled and read the wrong cell on the other.
 */
class CLayoutTest {
    private static final Pattern ENUM = Pattern.compile("enum\\s*\\{([^}]*)\\}");
    private static final Pattern DEFINE = Pattern.compile("(?m)^\\s*#\\s*define\\s+(\\w+)");
    private static final Pattern LAYOUT_NAME = Pattern.compile("\\bPARSL_(?:[CEVIAS]_[A-Z]+|[A-Z]+_COLS)\\b");

    /** The runtime's C files, as exported. */
    private static List<String> runtimeSources() {
        List<String> all = new ArrayList<>(CRuntime.RUNTIME);
        all.add(CRuntime.HOST_MAIN);
        return all.stream().map(CRuntime::read).toList();
    }

    /** The enum members and macros a C text declares. */
    private static Set<String> declared(String c) {
        Set<String> names = new TreeSet<>();
        Matcher m = ENUM.matcher(c);
        while (m.find()) {
            for (String member : m.group(1).split(",")) {
                String name = member.replaceAll("/\\*.*?\\*/", "").split("=")[0].trim();
                if (!name.isEmpty()) {
                    names.add(name);
                }
            }
        }
        Matcher d = DEFINE.matcher(c);
        while (d.find()) {
            names.add(d.group(1));
        }
        return names;
    }

    private static CProgram translated() {
        return CProgram.of(CExportTest.example("teleop-dirwave.xml"), 0.01);
    }

    @Test
    void theRuntimeDeclaresNoneOfTheGeneratedLayoutNames() {
        Set<String> generated = declared(translated().header());
        for (CLayout.Table t : CLayout.TABLES) {
            assertTrue(generated.contains(t.width()), t.width());
        }
        for (String source : runtimeSources()) {
            Set<String> own = declared(source);
            own.retainAll(generated);
            assertEquals(Set.of(), own, "declared both in the runtime and in parsl_program.h");
        }
    }

    @Test
    void everyLayoutNameTheRuntimeReadsIsDeclaredOnce() {
        Set<String> generated = declared(translated().header());
        Set<String> runtime = new HashSet<>();
        runtimeSources().forEach(s -> runtime.addAll(declared(s)));
        for (String source : runtimeSources()) {
            Matcher m = LAYOUT_NAME.matcher(source);
            while (m.find()) {
                String name = m.group();
                assertTrue(generated.contains(name) ^ runtime.contains(name), name + " must be declared exactly once");
            }
        }
    }

    @Test
    void aRowWithAColumnLeftUnsetIsRefused() {
        CLayout.Row<CLayout.AutCol> row = new CLayout.Row<>(CLayout.AutCol.class).set(CLayout.AutCol.NS, 2)
                .set(CLayout.AutCol.STATES, 0);
        IllegalStateException e = assertThrows(IllegalStateException.class, row::done);
        assertTrue(e.getMessage().contains("PERMODULE"), e.getMessage());
        assertEquals(List.of(2, 0, 1), java.util.Arrays.stream(row.set(CLayout.AutCol.PERMODULE, 1).done()).boxed()
                .toList());
    }

    /** Expression-valued macros (the {@code parsl_varg} table), which no example has. */
    private static final String MACROS = """
            <program>
              <robot><structure><left elements="0, 1, 2"/></structure></robot>
              <main><step d="0.25 + 0.1" time="2"/></main>
              <behaviors><step macros="d"><swing group="left" phase="d" period="1"/></step></behaviors>
              <automata><swing states="fore, aft" times="1, 1.5"/></automata>
              <states><fore angles="30"/><aft angles="-10"/></states>
            </program>
            """;

    @Test
    void everyWrittenRowHasItsTablesWidth() {
        LoadResult r = ScriptLoader.loadText(Path.of("macros.xml"), MACROS, Map.of());
        assertNotNull(r.program(), () -> r.diagnostics().toString());
        String c = translated().source() + CProgram.of(r.program(), 0.01).source();
        for (CLayout.Table t : CLayout.TABLES) {
            Matcher m = Pattern.compile("\\[\\]\\[" + t.width() + "\\] = \\{(.*?)\\};", Pattern.DOTALL).matcher(c);
            int rows = 0;
            while (m.find()) {
                Matcher row = Pattern.compile("\\{([^{}]*)\\}").matcher(m.group(1));
                while (row.find()) {
                    if (!row.group(1).equals("0")) {
                        assertEquals(t.cols(), row.group(1).split(",").length, t.width() + ": {" + row.group(1) + "}");
                        rows++;
                    }
                }
            }
            assertTrue(rows > 0, "no row written for " + t.width());
        }
    }
}
