package org.parpe.core.xml;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.diag.DiagnosticList;

/** The reader of the small attribute-only XML files (robot configurations, hardware profiles). */
class FlatXmlFileTest {
    @TempDir
    Path dir;

    private FlatXmlFile read(String text, DiagnosticList d) throws Exception {
        Path f = dir.resolve("f.xml");
        Files.writeString(f, text);
        return FlatXmlFile.read(f, org.parpe.core.text.Message.verbatim("thing list"), "things",
                org.parpe.core.text.Message.verbatim("a <things> element with <thing> elements"), d);
    }

    private static List<String> lines(DiagnosticList d) {
        return d.all().stream().map(x -> x.pos().line() + ":" + x.pos().column() + " " + x.message()).toList();
    }

    @Test
    void rootAttributesAndChildrenKeepTheirPlaces() throws Exception {
        DiagnosticList d = new DiagnosticList();
        FlatXmlFile f = read("<things size=\" 3 \">\n  <thing a=\"1\" b=\"x\"/>\n  <other/>\n</things>\n", d);
        assertTrue(f.ok(), lines(d).toString());
        assertEquals(Map.of("size", "3"), f.rootAttributes());
        assertEquals(2, f.children().size());
        assertEquals("thing", f.children().get(0).name());
        assertEquals(Map.of("a", "1", "b", "x"), f.children().get(0).attributes());
        assertEquals(2, f.children().get(0).at().line());
        assertEquals("other", f.children().get(1).name());
        assertEquals(Map.of(), f.children().get(1).attributes());
        assertEquals(3, f.children().get(1).at().line());
    }

    @Test
    void nestedElementsAndTextAreErrorsAtTheirPlace() throws Exception {
        DiagnosticList d = new DiagnosticList();
        FlatXmlFile f = read("<things>\n  <thing a=\"1\"><inner/></thing>\n  <thing>words</thing>\n</things>\n", d);
        assertFalse(f.ok());
        assertEquals(List.of("2:16 <thing> may not contain <inner>", "3:3 <thing> may not contain text"), lines(d));
    }

    @Test
    void aScriptGivenInsteadIsNamed() throws Exception {
        DiagnosticList d = new DiagnosticList();
        FlatXmlFile f = read("<?xml version=\"1.0\"?>\n<program/>\n", d);
        assertNull(f.root());
        assertEquals(List.of("2:1 <program> is not a thing list but a PARSL script; expected a <things> element with"
                + " <thing> elements"), lines(d));
    }

    @Test
    void brokenXmlIsLocated() throws Exception {
        DiagnosticList d = new DiagnosticList();
        FlatXmlFile f = read("<things>\n  <thing a=\"1\">\n</things>\n", d);
        assertNull(f.root());
        assertEquals(1, d.all().size());
        assertTrue(d.all().get(0).message().startsWith("not well-formed XML"), lines(d).toString());
        assertEquals(3, d.all().get(0).pos().line());
    }

    @Test
    void attributeChecksNameTheValueAndTheBound() throws Exception {
        DiagnosticList d = new DiagnosticList();
        FlatXmlFile f = read("<things/>", d);
        Map<String, String> a = Map.of("n", "2.5", "x", "1d", "y", "700", "z", "-3");
        var at = f.start();
        assertEquals(7, f.number(a, "missing", 7, at, false, 0, 10));
        assertEquals(-3, f.number(a, "z", 0, at, true, -5, 5));
        assertEquals(1, f.number(a, "n", 1, at, true, 0, 10));
        assertEquals(1, f.number(a, "x", 1, at, false, 0, 10));
        assertEquals(1, f.number(a, "y", 1, at, false, 0, 600));
        assertFalse(f.known(Map.of("q", "1"), Set.of("n", "m"), "thing", at));
        assertFalse(f.required(Map.of("n", ""), at, "thing", "n"));
        assertEquals(List.of("1:1 n must be a whole number, got '2.5'", "1:1 x must be a number, got '1d'",
                "1:1 y must be in 0..600, got 700", "1:1 <thing> has no attribute 'q'; it takes m, n",
                "1:1 <thing> needs the attribute 'n'"), lines(d));
    }

    @Test
    void textInTheRootIsPlacedWhereItStandsNotAtTheNextElement() throws Exception {
        DiagnosticList d = new DiagnosticList();
        read("<things>\n  <thing a=\"1\"/>\n  stray words\n\n  <thing a=\"2\"/>\n</things>\n", d);
        assertEquals(List.of("3:3 <things> may not contain text"), lines(d));
    }

    @Test
    void anUndefinedEntityIsPlacedWhereItStandsWithoutTheParsersInternals() throws Exception {
        DiagnosticList d = new DiagnosticList();
        FlatXmlFile f = read("<things>\n  <thing a=\"1\"/>\n  <thing a=\"&nope;\"/>\n</things>\n", d);
        assertNull(f.root());
        assertEquals(1, d.all().size(), lines(d).toString());
        String line = lines(d).get(0);
        assertTrue(line.startsWith("3:"), line);
        assertFalse(line.contains("unknown-source") || line.contains("[row,col"), line);
        assertTrue(line.contains("nope"), line);
        DiagnosticList root = new DiagnosticList();
        read("<?xml version=\"1.0\"?>\n\n<things size=\"&big;\">\n</things>\n", root);
        assertEquals(1, root.all().size(), lines(root).toString());
        assertTrue(lines(root).get(0).startsWith("3:"), "an entity in the root's attribute at its line: " + lines(root));
        assertFalse(lines(root).get(0).contains("[row,col"), lines(root).toString());
    }

    @Test
    void attributesOfAnotherNamespaceDoNotStandInForOurs() throws Exception {
        DiagnosticList d = new DiagnosticList();
        FlatXmlFile f = read("<things xmlns:x=\"urn:other\" size=\"3\" x:size=\"9\">\n  <thing x:a=\"7\" a=\"1\"/>\n"
                + "</things>\n", d);
        assertEquals("3", f.rootAttributes().get("size"));
        assertEquals("9", f.rootAttributes().get("x:size"));
        assertEquals(Map.of("x:a", "7", "a", "1"), f.children().get(0).attributes());
    }

    /**
     * Issue 19, item 10 (read with StAX, not Jackson): text in an element with attributes is
     * placed where it stands, as text in the root is, not where it ends (Jackson's place).
     */
    @Test
    void textInAChildIsPlacedWhereItStands() throws Exception {
        DiagnosticList d = new DiagnosticList();
        read("<things>\n  <thing a=\"1\">  some text</thing>\n  <thing a=\"2\">x<inner/>y</thing>\n</things>\n", d);
        assertEquals(List.of("2:18 <thing> may not contain text", "3:16 <thing> may not contain text",
                "3:17 <thing> may not contain <inner>", "3:25 <thing> may not contain text"), lines(d));
    }

    /** The place of a parse error is the parser's own, not one column to its right (as through Jackson). */
    @Test
    void aParseErrorStandsAtTheCharacterTheParserStoppedAt() throws Exception {
        DiagnosticList d = new DiagnosticList();
        read("<things>\n  <thing a=1/>\n</things>\n", d);
        assertEquals(1, d.all().size(), lines(d).toString());
        assertTrue(lines(d).get(0).startsWith("2:12 not well-formed XML: Unexpected character '1'"), lines(d).toString());
    }

    /**
     * Issue 31 item 5: robot configurations, profiles and worlds took anything after the root
     * element, which the script reader refuses; both now refuse it at the same place with the
     * parser's words. A comment or processing instruction after the root stays allowed in both.
     */
    @Test
    void contentAfterTheRootIsRefusedAsInAScript() throws Exception {
        for (String after : List.of("<thing a=\"2\"/>\n", "stray text\n", "</things>\n")) {
            DiagnosticList d = new DiagnosticList();
            FlatXmlFile f = read("<things>\n  <thing a=\"1\"/>\n</things>\n" + after, d);
            assertNull(f.root(), after);
            DiagnosticList script = new DiagnosticList();
            assertNull(XmlReader.read(new SourceText("s.xml", "<program>\n  <main/>\n</program>\n" + after), script));
            assertEquals(1, d.all().size(), lines(d).toString());
            assertEquals(lines(script).get(0).replace("malformed XML", "not well-formed XML"), lines(d).get(0));
        }
        DiagnosticList d = new DiagnosticList();
        assertTrue(read("<things/>\n<!-- a note -->\n<?pi x?>\n", d).ok(), lines(d).toString());
    }

    /**
     * Read from text (a builder's), a file gives the same places and messages as from disk, and
     * every element's place carries its span: the element's characters and each value's, with
     * Windows line ends too.
     */
    @Test
    void textGivesEveryElementItsSpanAndTheMessagesOfTheFile() throws Exception {
        for (String nl : List.of("\n", "\r\n")) {
            String text = ("<?xml version=\"1.0\"?>\n<!-- c -->\n<things size='3'>\n  <thing a=\"&lt;1\" b = 'x' />\n"
                    + "  <other></other>\n  <bad x=\"1\"><in/></bad>\n</things>\n").replace("\n", nl);
            DiagnosticList fromFile = new DiagnosticList();
            read(text, fromFile);
            DiagnosticList fromText = new DiagnosticList();
            FlatXmlFile f = FlatXmlFile.read(dir.resolve("f.xml").toString(), text,
                    org.parpe.core.text.Message.verbatim("thing list"), "things",
                    org.parpe.core.text.Message.verbatim("a <things> element with <thing> elements"), fromText);
            assertEquals(lines(fromFile), lines(fromText));
            assertEquals(1, fromText.all().size(), lines(fromText).toString());
            var root = f.root().span();
            assertEquals(text.indexOf("<things"), root.start());
            assertEquals(text.indexOf("</things>") + 9, root.end());
            assertEquals("3", root.value("size").of(text));
            var thing = f.children().get(0).at();
            assertEquals(text.indexOf("<thing "), thing.span().start());
            assertEquals(thing.span().start(), thing.offset());
            assertEquals("<thing a=\"&lt;1\" b = 'x' />", text.substring(thing.span().start(), thing.span().end()));
            assertEquals("&lt;1", thing.span().value("a").of(text));
            assertEquals("x", thing.span().value("b").of(text));
            var other = f.children().get(1).at().span();
            assertEquals("<other></other>", text.substring(other.start(), other.end()));
            assertEquals(4, f.children().get(0).at().line());
        }
    }
}
