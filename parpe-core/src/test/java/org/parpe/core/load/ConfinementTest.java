package org.parpe.core.load;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.diag.Diagnostic;

/**
 * Issue 37, item 3: a script loaded confined to a folder reads no include or robot file outside
 * it (by name, by "..", by an absolute path or through a link); each one is a located error that
 * names the rule. Inside the folder, includes and robot files load as always.
 */
class ConfinementTest {
    private static final String GAIT = """
            <program>
              <behaviors><go><wave group="body" phase="0.2" period="1"/></go></behaviors>
              <automata><wave states="up"/></automata>
              <states><up angles="30"/></states>
            </program>
            """;
    private static final String ROBOT = "<robot><structure><body elements=\"0..3\"/></structure></robot>";

    @TempDir
    Path dir;
    private Path alice;

    @BeforeEach
    void folders() throws Exception {
        alice = Files.createDirectories(dir.resolve("alice"));
        Path bob = Files.createDirectories(dir.resolve("bob"));
        Files.writeString(alice.resolve("gait.xml"), GAIT);
        Files.writeString(alice.resolve("body.xml"), ROBOT);
        Files.writeString(bob.resolve("gait.xml"), GAIT);
        Files.writeString(bob.resolve("body.xml"), ROBOT);
        Files.createSymbolicLink(alice.resolve("link.xml"), bob.resolve("gait.xml"));
    }

    private List<Diagnostic> load(String robot, String include, Path root) throws Exception {
        Path main = alice.resolve("main.xml");
        Files.writeString(main, "<program>\n  <robot file=\"" + robot + "\"/>\n  <include file=\"" + include + "\"/>\n"
                + "  <main><go/></main>\n</program>\n");
        LoadResult r = ScriptLoader.load(main, Map.of(), root);
        if (r.program() != null) {
            assertTrue(r.errors().isEmpty());
            return List.of();
        }
        // what an include refused leaves undefined ('go') follows; the refusals are what is tested
        return r.errors().stream().filter(d -> d.message().contains("confinement")).toList();
    }

    @Test
    void filesInsideTheFolderLoad() throws Exception {
        assertEquals(List.of(), load("body.xml", "gait.xml", alice));
        assertNotNull(ScriptLoader.load(alice.resolve("main.xml"), Map.of(), alice).program());
    }

    @Test
    void anIncludeOutsideIsALocatedErrorNamingTheRule() throws Exception {
        List<Diagnostic> e = load("body.xml", "../bob/gait.xml", alice);
        assertEquals(1, e.size(), e.toString());
        assertTrue(e.get(0).format().matches(".*main\\.xml:3:18: error: cannot include '\\.\\./bob/gait\\.xml': a graded script"
                + " may only read files inside its own folder 'alice' \\(the confinement rule of parpe grade\\)"), e.get(0).format());
    }

    @Test
    void aRobotFileOutsideByAbsoluteNameIsRefused() throws Exception {
        List<Diagnostic> e = load("/etc/passwd", "gait.xml", alice);
        assertEquals(1, e.size(), e.toString());
        assertTrue(e.get(0).format().contains("main.xml:2:16: error: cannot read robot file '/etc/passwd': a graded script"
                + " may only read files inside its own folder 'alice'"), e.get(0).format());
    }

    @Test
    void aLinkInsideThatLeadsOutsideIsRefused() throws Exception {
        List<Diagnostic> e = load("body.xml", "link.xml", alice);
        assertEquals(1, e.size(), e.toString());
        assertTrue(e.get(0).message().contains("confinement rule"), e.get(0).format());
    }

    @Test
    void aLoneScriptReadsNoOtherFile() throws Exception {
        List<Diagnostic> e = load("body.xml", "gait.xml", alice.resolve("main.xml"));
        assertEquals(2, e.size(), e.toString());
        e.forEach(d -> assertTrue(d.message().contains("a graded script handed in as a lone file may read no other file"),
                d.format()));
    }

    @Test
    void withoutConfinementEverythingLoadsAsBefore() throws Exception {
        assertEquals(List.of(), load("../bob/body.xml", "../bob/gait.xml", null));
    }

    @Test
    void aMainScriptThatIsALinkOutOfTheFolderIsNotRead() throws Exception {
        Files.createSymbolicLink(alice.resolve("copied.xml"), dir.resolve("bob/gait.xml"));
        LoadResult r = ScriptLoader.load(alice.resolve("copied.xml"), Map.of(), alice);
        assertEquals(1, r.errors().size(), r.errors().toString());
        assertTrue(r.errors().get(0).format().matches(".*copied\\.xml:1:1: error: cannot read file '.*copied\\.xml': a graded"
                + " script may only read files inside its own folder 'alice' \\(the confinement rule of parpe grade\\)"),
                r.errors().get(0).format());
    }
}
