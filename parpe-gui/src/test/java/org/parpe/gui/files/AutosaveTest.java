package org.parpe.gui.files;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Autosave copies are per file and per IDE instance; nothing a live IDE owns is deleted or offered. */
class AutosaveTest {
    @TempDir
    Path home;

    private static List<String> texts(List<Autosave.Copy> copies) {
        return copies.stream().map(Autosave.Copy::text).sorted().toList();
    }

    @Test
    void twoLiveInstancesKeepTheirOwnCopiesOfTheSameFile() throws IOException {
        Path script = home.resolve("walk.xml");
        try (Autosave a = new Autosave(home); Autosave b = new Autosave(home)) {
            assertNotEquals(a.instanceId(), b.instanceId());
            String slot = Autosave.slotFor(script);
            a.write(slot, script, "text of A");
            b.write(slot, script, "text of B");
            a.write(a.untitledSlot(), null, "untitled of A");
            assertEquals(List.of("text of A", "untitled of A"), texts(a.own()));
            assertEquals(List.of(), b.orphans(), "a live IDE's copies must not be offered for recovery");
            assertEquals(List.of(), a.orphans());

            a.clear(slot);
            assertEquals(List.of("text of B"), texts(b.own()), "clearing A's copy deleted B's");
            for (Autosave.Copy c : List.copyOf(a.own())) {
                b.discard(c);
            }
            assertEquals(List.of("untitled of A"), texts(a.own()), "B discarded a copy of the live A");
            assertThrows(IOException.class, () -> b.adopt(a.own().get(0)));
        }
    }

    @Test
    void copiesOfAnIdeThatIsGoneAreOfferedAndAdoptedOnce() throws IOException {
        Path script = home.resolve("walk.xml");
        Autosave gone = new Autosave(home);
        gone.write(Autosave.slotFor(script), script, "unsaved work");
        gone.close(); // as if killed: the lock is free, the copy stays
        try (Autosave b = new Autosave(home); Autosave c = new Autosave(home)) {
            List<Autosave.Copy> offered = b.orphans();
            assertEquals(List.of("unsaved work"), texts(offered));
            assertEquals(script.toAbsolutePath().normalize(), offered.get(0).file());
            String slot = b.adopt(offered.get(0));
            assertEquals(Autosave.slotFor(script), slot);
            assertEquals(List.of("unsaved work"), texts(b.own()));
            assertEquals(List.of(), c.orphans(), "a recovered copy now belongs to the live IDE that recovered it");
            assertEquals(List.of(), b.orphans());
        }
        try (Autosave later = new Autosave(home)) {
            assertEquals(List.of("unsaved work"), texts(later.orphans()),
                    "the recovered copy was neither saved nor discarded: it must still be there");
            later.discard(later.orphans().get(0));
            assertEquals(List.of(), later.orphans());
        }
        try (var s = Files.list(home.resolve("autosave"))) {
            assertTrue(s.count() <= 1, "folders of finished IDEs were left behind");
        }
    }
}
