package org.parpe.gui.grid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.gui.grid.TableEdits.At;

/** Finding gait tables in a text and editing them without touching the rest of the file. */
class TableEditsTest {
    static final String DOC = String.join("\n",
            "<program>",
            "  <automata>",
            "    <!-- module: 1   2   3 -->",
            "    <travel>",
            "       15,  15, -15",
            "      -15,  15,  15",
            "    </travel>",
            "    <two times=\"1, 2\">1, 2; max(3, 4), 5</two>",
            "    <w states=\"a\"/>",
            "  </automata>",
            "</program>",
            "");

    private static GaitTable table(String doc, int i) {
        List<GaitTable> all = TableText.find(doc);
        assertNotNull(all, "not well-formed");
        return all.get(i);
    }

    @Test
    void findsTablesRowsAndCellsWithTheirPlaces() {
        List<GaitTable> all = TableText.find(DOC);
        assertEquals(List.of("travel", "two"), all.stream().map(GaitTable::name).toList());
        GaitTable t = all.get(0);
        assertEquals(List.of(List.of("15", "15", "-15"), List.of("-15", "15", "15")), t.texts());
        assertEquals("-15", DOC.substring(t.cell(0, 2).start(), t.cell(0, 2).end()));
        assertNull(t.times());
        assertEquals(4, t.line());
        GaitTable two = all.get(1);
        assertEquals(List.of(List.of("1", "2"), List.of("max(3, 4)", "5")), two.texts());
        assertEquals(List.of("1", "2"), two.timeTexts());
        assertNull(TableText.find("<program><automata>"), "a text that is not well-formed has no tables");
    }

    @Test
    void aCellEditKeepsTheColumnsAlignedAndTheRestOfTheFile() {
        GaitTable t = table(DOC, 0);
        String after = TableEdits.setCells(DOC, t, Map.of(new At(1, 1), "-7.5")).applyTo(DOC);
        assertTrue(after.contains("\n     -15, -7.5,  15\n") || after.contains("\n      -15, -7.5,  15\n"), after);
        assertTrue(after.contains("    <!-- module: 1   2   3 -->\n"));
        assertEquals(DOC.substring(0, t.start()), after.substring(0, t.start()));
        assertEquals(DOC.substring(t.end()), after.substring(after.length() - (DOC.length() - t.end())));
        String shorter = TableEdits.setCells(DOC, t, Map.of(new At(0, 2), "5")).applyTo(DOC);
        assertTrue(shorter.contains("\n       15,  15,   5\n"), shorter);
        assertEquals(List.of("15", "15", "5"), table(shorter, 0).texts().get(0));
    }

    @Test
    void rowsAndColumnsAreAddedAndRemovedAligned() {
        GaitTable t = table(DOC, 0);
        String more = TableEdits.insertRow(DOC, t, 1, 0).applyTo(DOC);
        assertEquals(List.of(List.of("15", "15", "-15"), List.of("15", "15", "-15"), List.of("-15", "15", "15")),
                table(more, 0).texts());
        assertTrue(more.contains("<travel>\n       15, 15, -15\n       15, 15, -15\n      -15, 15,  15\n    </travel>"), more);
        String fewer = TableEdits.deleteColumns(DOC, t, 0, 1).applyTo(DOC);
        assertEquals(List.of(List.of("-15"), List.of("15")), table(fewer, 0).texts());
        String wider = TableEdits.insertColumn(DOC, t, 3, 2).applyTo(DOC);
        assertEquals(List.of("-15", "15", "15", "15"), table(wider, 0).texts().get(1));
        GaitTable two = table(DOC, 1);
        String oneRow = TableEdits.deleteRows(DOC, two, 0, 0).applyTo(DOC);
        assertEquals(List.of("2"), table(oneRow, 1).timeTexts(), "a removed row takes its time with it");
        assertEquals(1, table(oneRow, 1).rows().size());
    }

    @Test
    void timesAreWrittenIntoTheAttributeOrAddedWhenAbsent() {
        String doc = TableEdits.setCells(DOC, table(DOC, 0), Map.of(new At(TableEdits.TIMES, 1), "0.5")).applyTo(DOC);
        assertTrue(doc.contains("<travel times=\"1, 0.5\">\n       15,  15, -15\n"), "the rows are left as they were: " + doc);
        String two = TableEdits.setCells(DOC, table(DOC, 1), Map.of(new At(TableEdits.TIMES, 0), "3")).applyTo(DOC);
        assertTrue(two.contains("<two times=\"3, 2\">"), two);
    }

    @Test
    void entitiesAreDecodedForTheGridAndEncodedBack() {
        String doc = "<program><automata><t>if(1 &lt; 2, 5, 0), 1</t></automata></program>";
        GaitTable t = table(doc, 0);
        assertEquals("if(1 < 2, 5, 0)", t.cell(0, 0).text());
        String after = TableEdits.setCells(doc, t, Map.of(new At(0, 1), "3 & 4 > 2")).applyTo(doc);
        assertTrue(after.contains("if(1 &lt; 2, 5, 0), 3 &amp; 4 &gt; 2</t>"), after);
    }

    @Test
    void rowsHoldingAComment() {
        String doc = "<program><automata><t>1, 2\n<!-- x -->\n3, 4</t></automata></program>";
        assertNotNull(table(doc, 0).readOnly(), "rows interrupted by a comment are left to the text");
        assertNull(table(DOC, 0).readOnly());
    }
}
