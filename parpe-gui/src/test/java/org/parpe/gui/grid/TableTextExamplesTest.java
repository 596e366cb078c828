package org.parpe.gui.grid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.parpe.core.expr.Expression;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Automaton;

/**
 * The grid reads every gait table of the examples as the core's loader does: the same rows,
 * the same entries (and each entry's range in the file holds its text).
 */
class TableTextExamplesTest {

    static List<Path> scripts() throws IOException {
        Path dir = Path.of(System.getProperty("parpe.examples", "../examples"));
        try (Stream<Path> s = Stream.concat(Files.list(dir), Files.list(dir.resolve("tutorial")))) {
            return s.filter(p -> p.toString().endsWith(".xml")).sorted().toList();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scripts")
    void tablesMatchTheLoader(Path script) throws IOException {
        String text = Files.readString(script);
        LoadResult r = ScriptLoader.loadText(script, text, Map.of());
        List<GaitTable> tables = TableText.find(text);
        assertNotNull(tables, script + " is not well-formed for the grid");
        if (r.program() == null) {
            return;
        }
        List<Automaton> loaded = r.program().automata().stream().filter(Automaton::table).toList();
        assertEquals(loaded.stream().map(Automaton::name).toList(), tables.stream().map(GaitTable::name).toList());
        for (int i = 0; i < tables.size(); i++) {
            GaitTable t = tables.get(i);
            List<List<String>> expected = loaded.get(i).states().stream()
                    .map(s -> s.angles().stream().map(Expression::text).toList()).toList();
            assertEquals(expected, t.texts(), t.name() + " in " + script);
            for (List<Cell> row : t.rows()) {
                for (Cell c : row) {
                    assertEquals(c.text(), Entities.decode(text.substring(c.start(), c.end())));
                }
            }
        }
    }

    @Test
    void theFig4TableIsEightRowsOfTwelve() throws IOException {
        Path fig4 = scripts().stream().filter(p -> p.endsWith("gait-table-12.xml")).findFirst().orElseThrow();
        GaitTable t = TableText.find(Files.readString(fig4)).get(0);
        assertEquals(8, t.rows().size());
        assertTrue(t.rows().stream().allMatch(r -> r.size() == 12));
        assertFalse(t.readOnly() != null, "the Fig. 4 table is editable");
    }
}
