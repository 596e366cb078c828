package org.parpe.sim.build;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.diag.Diagnostic;
import org.parpe.sim.config.BadConfigs;

/**
 * Issue 33's bad configurations opened in the builder: {@link RobotDraft#of} never throws, and
 * its problems are those a run of the same file reports (the same reader, from text), each at
 * {@code FILE:LINE:COL}; a draft with problems has no bodies and refuses edits, saying why.
 */
class DraftProblemsTest {
    @TempDir
    Path dir;

    /** The draft's problems, checked against the file's as a run reads it. */
    private List<Diagnostic> problems(String name, String text) throws Exception {
        return problems(name, text, true);
    }

    /** The draft's problems; {@code asRun}: the same as a run's of the file (not for bytes that are no UTF-8 text). */
    private List<Diagnostic> problems(String name, String text, boolean asRun) throws Exception {
        Path f = dir.resolve(name);
        Files.writeString(f, text, StandardCharsets.ISO_8859_1);
        RobotDraft d = RobotDraft.of(f.toString(), text);
        List<Diagnostic> run = BadConfigs.runErrors(f);
        if (asRun) {
            assertEquals(run.stream().map(Diagnostic::format).toList(), d.problems().stream().map(Diagnostic::format).toList());
        }
        assertFalse(d.problems().isEmpty());
        for (Diagnostic p : d.problems()) {
            assertTrue(p.pos().line() > 0 && p.pos().file().equals(f.toString()), p.format());
        }
        assertTrue(d.bodies().isEmpty() && d.freePlates().isEmpty());
        return d.problems();
    }

    private RobotDraft draft(String name) throws Exception {
        Path f = dir.resolve(name);
        return RobotDraft.of(f.toString(), Files.readString(f));
    }

    @Test
    void overlappingParts() throws Exception {
        List<Diagnostic> p = problems("overlap.xml", BadConfigs.OVERLAP);
        assertTrue(p.get(0).format().contains("overlap.xml:6:3: error: part 'd' overlaps part 'body'"), p.toString());
        assertEquals("d", draft("overlap.xml").partAt(p.get(0).pos()).orElseThrow(), "the builder marks the part at fault");
    }

    @Test
    void aPlateUsedTwice() throws Exception {
        List<Diagnostic> p = problems("twice.xml", BadConfigs.PLATE_TWICE);
        assertTrue(p.get(0).format().endsWith("twice.xml:6:3: error: plate 1 of part 'a' is already connected (line 5);"
                + " a plate takes one connection"), p.toString());
        // what reads but does not assemble can be mended by the builder
        RobotDraft d = draft("twice.xml");
        assertEquals("c", d.partAt(p.get(0).pos()).orElseThrow(), "the part the second connection would attach");
        assertTrue(d.apply(d.remove("c")).problems().isEmpty());
    }

    @Test
    void aLoopThatDoesNotClose() throws Exception {
        List<Diagnostic> p = problems("open.xml", BadConfigs.OPEN_LOOP);
        assertTrue(p.get(0).message().contains("closes a loop but does not fit"), p.toString());
    }

    @Test
    void anUnknownPartType() throws Exception {
        String text = BadConfigs.UNKNOWN_TYPE;
        List<Diagnostic> p = problems("type.xml", text);
        assertTrue(p.get(0).format().endsWith("type.xml:2:3: error: unknown part type 'wheel'; expected segment, node,"
                + " foot or hub"), p.toString());
        assertEquals("w", draft("type.xml").partAt(p.get(0).pos()).orElseThrow());
        // what does not read cannot be edited by the builder, only in the text
        assertEquals("the configuration has problems; mend them first (see Problems)",
                RobotDraft.of("type.xml", text).remove("w").refusal());
    }

    @Test
    void tenThousandPartsFoldedOntoThemselves() throws Exception {
        List<Diagnostic> p = problems("folded.xml", BadConfigs.chain(true));
        assertEquals(21, p.size(), "the first 20 overlaps and a note that there are more");
    }

    @Test
    void binaryText() throws Exception {
        List<Diagnostic> p = problems("noise.xml", new String(BadConfigs.noise(), StandardCharsets.ISO_8859_1), false);
        assertTrue(p.get(0).pos().line() == 1, p.toString());
        assertEquals(1, p.size(), p.toString());
        assertTrue(p.get(0).message().startsWith("not well-formed XML"), p.toString());
    }

    @Test
    void anExternalEntity() throws Exception {
        Path secret = dir.resolve("secret.txt");
        Files.writeString(secret, "s3cr3t");
        List<Diagnostic> p = problems("xxe.xml", BadConfigs.externalEntity(secret));
        assertEquals(1, p.size(), p.toString());
        assertTrue(p.get(0).message().startsWith("DOCTYPE declarations are not allowed in a robot configuration"));
        assertFalse(p.toString().contains("s3cr3t"));
    }

    @Test
    void aRootPartThatIsNotDefinedIsReportedAtItsRootElement() throws Exception {
        List<Diagnostic> p = problems("root.xml", """
                <robot-config>
                  <part name="head" type="segment" id="0"/>
                  <root part="haed"/>
                </robot-config>
                """);
        assertTrue(p.get(0).format().endsWith("root.xml:3:3: error: root part 'haed' is not defined (did you mean 'head'?)"),
                p.toString());
    }
}
