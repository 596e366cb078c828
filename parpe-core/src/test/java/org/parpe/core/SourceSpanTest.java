package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.diag.SourceSpan;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.BehaviorItem;
import org.parpe.core.model.Conditional;
import org.parpe.core.model.Program;
import org.parpe.core.xml.SourceText;
import org.parpe.core.xml.XElement;
import org.parpe.core.xml.XmlReader;
import org.w3c.dom.Element;
import org.w3c.dom.NamedNodeMap;
import org.xml.sax.InputSource;

/**
 * The spans the reader records (issue 19 item 3), checked against the JDK's own DOM parser,
 * which we did not write: each element's span parsed alone is that element with the same
 * attributes, and each attribute's value range, decoded by the DOM parser, is the value.
 */
class SourceSpanTest {
    static List<Path> scripts() throws Exception {
        return Scripts.all();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scripts")
    void everyElementAndAttributeSpanHoldsItsText(Path file) throws Exception {
        String text = Files.readString(file);
        XElement root = XmlReader.read(new SourceText(file.toString(), text), new DiagnosticList());
        assertNotNull(root, "well-formed");
        int[] count = {0};
        walk(root, text, count);
        assertTrue(count[0] > 0);
    }

    private static void walk(XElement e, String text, int[] count) throws Exception {
        SourceSpan s = e.span();
        assertNotNull(s, e.pos() + ": no span");
        String raw = text.substring(s.start(), s.end());
        Element dom = dom(raw);
        assertEquals(e.name(), dom.getTagName(), e.pos() + ": " + raw);
        NamedNodeMap attrs = dom.getAttributes();
        assertEquals(attrs.getLength(), s.values().size(), e.pos() + ": attributes of " + raw);
        for (int i = 0; i < attrs.getLength(); i++) {
            String name = attrs.item(i).getNodeName();
            SourceSpan.Range r = s.value(name);
            assertNotNull(r, e.pos() + ": no range for " + name);
            char quote = text.charAt(r.offset() - 1);
            assertEquals(quote, text.charAt(r.end()), e.pos() + ": " + name + " is not quoted by its range");
            assertEquals(attrs.item(i).getNodeValue(), dom("<x a=" + quote + r.of(text) + quote + "/>").getAttribute("a"),
                    e.pos() + ": value of " + name);
            count[0]++;
        }
        for (XElement c : e.children()) {
            assertTrue(c.span().start() > s.start() && c.span().end() <= s.end(), c.pos() + " lies inside its parent");
            walk(c, text, count);
        }
    }

    private static Element dom(String xml) throws Exception {
        return DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(new InputSource(new StringReader(xml))).getDocumentElement();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scripts")
    void theModelsNodesCarryTheirElementsSpan(Path file) throws Exception {
        LoadResult r = ScriptLoader.load(file, Map.of());
        if (r.program() == null) {
            return; // a case that checks diagnostics: the XML-level test covers its spans
        }
        Program p = r.program();
        List<SourcePos> nodes = new ArrayList<>();
        p.robot().groups().stream().filter(g -> !g.implicit()).forEach(g -> nodes.add(g.pos()));
        p.states().forEach(s -> nodes.add(s.pos()));
        p.automata().stream().filter(a -> !a.table()).forEach(a -> nodes.add(a.pos()));
        for (Behavior b : p.behaviors()) {
            nodes.add(b.pos());
            items(b.items(), nodes);
        }
        p.mainDef().ifPresent(m -> {
            nodes.add(m.pos());
            m.entries().forEach(e -> nodes.add(e.pos()));
        });
        for (SourcePos at : nodes) {
            assertNotNull(at.span(), at + ": no span");
            String text = Files.readString(Path.of(at.file()));
            SourcePos start = new SourceText(at.file(), text).pos(at.span().start() + 1);
            assertEquals(at, start, "the span starts at the node's element");
        }
    }

    private static void items(List<BehaviorItem> items, List<SourcePos> out) {
        for (BehaviorItem i : items) {
            out.add(i.pos());
            if (i instanceof Conditional c) {
                items(c.items(), out);
            }
        }
    }

    @Test
    void aSpanIsNoPartOfAPlacesEquality() throws Exception {
        String text = "<program>\n  <a x=\"1\"/>\n</program>";
        XElement a = XmlReader.read(new SourceText("t.xml", text), new DiagnosticList()).children().get(0);
        SourcePos plain = new SourcePos("t.xml", 2, 4);
        assertNotNull(a.pos().span());
        assertEquals(plain, a.pos());
        assertEquals(plain.hashCode(), a.pos().hashCode());
        assertEquals("t.xml:2:4", a.pos().toString());
        assertTrue(!plain.equals(new SourcePos("t.xml", 2, 5)) && !plain.equals(new SourcePos("u.xml", 2, 4)));
    }

    @Test
    void entitiesAndOtherQuotesAreCoveredByTheRawRange() throws Exception {
        String text = "<program>\n  <a x='1 &lt; 2' y=\"&#65;b\"\n     z = \"q\" />\n  <b>t</b>\n</program>";
        XElement root = XmlReader.read(new SourceText("t.xml", text), new DiagnosticList());
        XElement a = root.children().get(0);
        assertEquals("1 &lt; 2", a.span().value("x").of(text));
        assertEquals("&#65;b", a.span().value("y").of(text));
        assertEquals("q", a.span().value("z").of(text));
        assertEquals("<b>t</b>", text.substring(root.children().get(1).span().start(), root.children().get(1).span().end()));
        assertTrue(a.span().empty());
        assertEquals(text.length(), root.span().end());
    }
}
