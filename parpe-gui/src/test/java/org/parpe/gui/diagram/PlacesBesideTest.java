package org.parpe.gui.diagram;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The layout file beside a script, on real files (no display): read, written, never written
 * over something that is not ours, and what cannot be written said once.
 */
class PlacesBesideTest {
    @TempDir
    Path dir;

    private final List<String> said = new ArrayList<>();
    private final PlacesBeside places = new PlacesBeside(said::add);

    @Test
    void aPlaceIsWrittenBesideTheScriptAndReadBackForTheNextDocument() throws Exception {
        Path script = Files.writeString(dir.resolve("walk.xml"), "<program/>");
        places.documentSwitched(script);
        places.put("program", "idle", 12.34, 56, List.of("idle"));
        assertEquals("parpe-layout 1\nprogram idle 12.3 56\n", Files.readString(dir.resolve("walk.xml.layout")));
        assertEquals("<program/>", Files.readString(script));
        PlacesBeside other = new PlacesBeside(said::add);
        other.documentSwitched(script);
        assertArrayEquals(new double[] {12.3, 56}, other.places().at("program", "idle"));
        assertEquals(List.of(), said);
    }

    @Test
    void aFolderOfTheLayoutsNameIsNotOursAndIsSaidOnceWhenAPlaceWouldBeWritten() throws Exception {
        Path script = Files.writeString(dir.resolve("walk.xml"), "<program/>");
        Files.createDirectory(dir.resolve("walk.xml.layout"));
        places.documentSwitched(script);
        assertEquals(List.of(), said, "nothing to say until a place would be written");
        places.put("program", "idle", 1, 2, List.of("idle"));
        places.put("program", "idle", 3, 4, List.of("idle"));
        assertEquals(1, said.size(), said.toString());
        assertTrue(said.get(0).contains("walk.xml.layout is not a PARPE layout file"), said.get(0));
        assertTrue(Files.isDirectory(dir.resolve("walk.xml.layout")));
        assertArrayEquals(new double[] {3, 4}, places.places().at("program", "idle"), "kept in memory");
    }

    @Test
    void aFolderThatCannotBeWrittenKeepsPlacesInMemoryAndSaysSoOnce() {
        Path script = dir.resolve("gone").resolve("walk.xml");
        places.documentSwitched(script);
        places.put("program", "idle", 1, 2, List.of("idle"));
        places.put("program", "idle", 3, 4, List.of("idle"));
        assertEquals(1, said.size(), said.toString());
        assertTrue(said.get(0).startsWith("Cannot write " + dir.resolve("gone").resolve("walk.xml.layout")), said.get(0));
        assertArrayEquals(new double[] {3, 4}, places.places().at("program", "idle"));
        assertFalse(Files.exists(dir.resolve("gone")));
    }

    @Test
    void anUntitledDocumentWritesNothingUntilSaveAsGivesItAFile() throws Exception {
        places.documentSwitched(null);
        places.put("lanes", "spare", 5, 6, List.of("spare"));
        try (var files = Files.list(dir)) {
            assertEquals(0, files.count());
        }
        Path script = Files.writeString(dir.resolve("new.xml"), "<program/>");
        places.documentRenamed(script);
        assertEquals("parpe-layout 1\nlanes spare 5 6\n", Files.readString(dir.resolve("new.xml.layout")));
    }

    @Test
    void saveAsOverAForeignLayoutLeavesItAndSaysWhy() throws Exception {
        places.documentSwitched(null);
        places.put("program", "idle", 1, 2, List.of("idle"));
        Path script = Files.writeString(dir.resolve("new.xml"), "<program/>");
        Files.writeString(dir.resolve("new.xml.layout"), "[window]\nx=3\n");
        places.documentRenamed(script);
        assertEquals("[window]\nx=3\n", Files.readString(dir.resolve("new.xml.layout")));
        assertEquals(1, said.size());
        places.put("program", "idle", 7, 8, List.of("idle"));
        assertEquals("[window]\nx=3\n", Files.readString(dir.resolve("new.xml.layout")));
        assertEquals(1, said.size(), "said once: " + said);
    }

    @Test
    void aLayoutWithABadLineIsReadForItsGoodLinesAndTheBadOneNamed() throws Exception {
        Path script = Files.writeString(dir.resolve("walk.xml"), "<program/>");
        Files.writeString(dir.resolve("walk.xml.layout"), "parpe-layout 1\nprogram idle 1 2\nprogram broken\n");
        places.documentSwitched(script);
        assertArrayEquals(new double[] {1, 2}, places.places().at("program", "idle"));
        assertEquals(List.of(dir.resolve("walk.xml.layout") + ":3: expected VIEW NAME X Y, got \"program broken\";"
                + " those nodes get a free place"), said);
        places.put("program", "idle", 4, 5, List.of("idle"));
        assertEquals("parpe-layout 1\nprogram idle 4 5\n", Files.readString(dir.resolve("walk.xml.layout")),
                "written again, the layout is mended");
    }
}
