package org.parpe.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code parpe lesson.xml} answered "unknown command" instead of opening the IDE (issue 22 §6).
 * The installed PARPE runs the IDE in the same process (checked by packaging/test-deb-install.sh);
 * this module's class path has no IDE, which is the command-line jar of a source checkout.
 */
class IdeLaunchTest {
    @TempDir
    Path dir;

    @Test
    void aScriptFileAloneOrGuiAsksForTheIde() throws Exception {
        Path lesson = Files.writeString(dir.resolve("lesson.xml"), CliContractTest.GOOD);
        Path parsl = Files.writeString(dir.resolve("Team.PARSL"), CliContractTest.GOOD);
        assertTrue(Ide.wanted(new String[] {lesson.toString()}));
        assertTrue(Ide.wanted(new String[] {parsl.toString()}));
        assertTrue(Ide.wanted(new String[] {"gui", lesson.toString(), "--exit"}));
        assertTrue(Ide.wanted(new String[0]));
    }

    @Test
    void commandsAndMissingFilesAreNotTheIde() throws Exception {
        Path notes = Files.writeString(dir.resolve("notes.txt"), "x");
        assertFalse(Ide.wanted(new String[] {"check", "lesson.xml"}));
        assertFalse(Ide.wanted(new String[] {dir.resolve("missing.xml").toString()}));
        assertFalse(Ide.wanted(new String[] {notes.toString()}));
        assertFalse(Ide.wanted(new String[] {dir.toString()}));
    }

    @Test
    void withoutTheIdeAScriptFileSaysHowToOpenIt() throws Exception {
        assertFalse(Ide.present());
        Path lesson = Files.writeString(dir.resolve("lesson.xml"), CliContractTest.GOOD);
        BadInputTest.Result r = BadInputTest.parpe(lesson.toString());
        assertEquals(2, r.code(), r.err());
        assertFalse(r.err().contains("unknown command"), r.err());
        assertTrue(r.err().contains("./parpe gui " + lesson), r.err());
    }

    @Test
    void withoutTheIdeNoArgumentsPrintTheUsage() {
        BadInputTest.Result r = BadInputTest.parpe();
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("Usage: parpe"), r.out());
    }

    @Test
    void versionIsThePomVersion() {
        BadInputTest.Result r = BadInputTest.parpe("--version");
        assertEquals("PARPE " + org.parpe.core.Version.NUMBER, r.out().strip());
    }
}
