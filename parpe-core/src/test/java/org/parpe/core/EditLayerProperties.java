package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.edit.ElementWriter;
import org.parpe.core.edit.Replacement;
import org.parpe.core.edit.ScriptEdits;
import org.parpe.core.edit.TextEdit;
import org.parpe.core.xml.SourceText;
import org.parpe.core.xml.XElement;
import org.parpe.core.xml.XmlReader;

/**
 * The edit layer (issue 32) against the XML reader, which it did not write: what
 * {@link ElementWriter} writes reads back as the values it was given, and what
 * {@link ScriptEdits} changes through the spans reads back as the change, the rest of the
 * text untouched.
 */
class EditLayerProperties {
    @Provide
    Arbitrary<String> values() {
        // printable ASCII: XML turns tabs and line breaks in an attribute into spaces (XML 1.0 §3.3.3)
        return Arbitraries.strings().withCharRange(' ', '~').ofMaxLength(30);
    }

    static XElement read(String text) {
        XElement root = XmlReader.read(new SourceText("t.xml", text), new DiagnosticList());
        assertNotNull(root, text);
        return root;
    }

    @Property(tries = 300)
    void anElementReadsBackAsWritten(@ForAll("values") String a, @ForAll("values") String row) {
        String text = ElementWriter.tag("t").attr("a", a).attrIfGiven("b", a).lines("", List.of(ElementWriter.text(row)));
        XElement t = read(text);
        assertEquals(a, t.attr("a").value().value(), text);
        assertEquals(a.isBlank(), t.attr("b") == null, text);
    }

    @Property(tries = 300)
    void setAttributeChangesOnlyThatValueWhateverItsQuotes(@ForAll("values") String v, @ForAll boolean single) {
        String q = single ? "'" : "\"";
        String text = "<!-- c -->\n<program>\n  <x a=" + q + "1" + q + " b=\"2\"/>\n  <y/>\n</program>\n";
        XElement x = read(text).children().get(0);
        String after = ScriptEdits.setAttribute(text, x.pos(), "a", v).apply(text);
        XElement again = read(after).children().get(0);
        assertEquals(v, again.attr("a").value().value(), after);
        assertEquals("2", again.attr("b").value().value(), after);
        int from = x.span().value("a").offset();
        int tail = text.length() - x.span().value("a").end();
        assertEquals(text.substring(0, from), after.substring(0, from), "the text before the value stays");
        assertEquals(text.substring(text.length() - tail), after.substring(after.length() - tail), "the text after it stays");
    }

    @Property(tries = 200)
    void childrenGoFirstOrLastAndARenamedElementKeepsItsContent(@ForAll("names") String name) {
        String text = "<program>\n  <main>\n    <a/>\n  </main>\n  <t times=\"1\">\n    1, 2\n  </t>\n</program>\n";
        XElement root = read(text);
        XElement main = root.children().get(0);
        XElement t = root.children().get(1);
        String first = ScriptEdits.prependChild(text, main.span(), ElementWriter.tag(name).empty()).apply(text);
        assertEquals(List.of(name, "a"), read(first).children().get(0).children().stream().map(XElement::name).toList());
        String last = ScriptEdits.appendChild(text, main.span(), "main", main.children().get(0).span(),
                ElementWriter.tag(name).empty()).apply(text);
        assertEquals(List.of("a", name), read(last).children().get(0).children().stream().map(XElement::name).toList());
        assertEquals(text.replace("<a/>", "<a/>\n    <" + name + "/>"), last, "on a line of its own, indented as its sibling");
        String renamed = new TextEdit(ScriptEdits.rename(text, t.span(), "t", name)).apply(text);
        assertEquals(text.replace("<t ", "<" + name + " ").replace("</t>", "</" + name + ">"), renamed);
    }

    @Provide
    Arbitrary<String> names() {
        return Arbitraries.strings().withCharRange('a', 'z').ofMinLength(1).ofMaxLength(8);
    }

    @Test
    void theSmallestReplacementBetweenTwoTextsLeavesTheirCommonEndsAlone() {
        assertEquals(new Replacement(13, 1, "7"), Replacement.between(10, "1, 2, 3", "1, 7, 3"));
        assertEquals("ab7d", new Replacement(2, 1, "7").applyTo("abcd"));
        assertThrows(IllegalArgumentException.class, () -> ElementWriter.name("1x", "state"));
        assertEquals("a\"b&apos;", ElementWriter.attributeText("a\"b'", '\''));
        assertEquals("a&quot;b'", ElementWriter.attributeText("a\"b'", '"'));
    }

    /**
     * A child put into an element that holds only white space (a robot file just started:
     * {@code <robot-config>} and its end tag on the next line) goes on a line of its own between
     * the tags, the end tag staying on its line.
     */
    @Test
    void aChildOfAnElementHoldingOnlyWhiteSpaceGoesBetweenItsTags() {
        String text = "<?xml version=\"1.0\" ?>\n<robot-config>\n</robot-config>\n";
        XElement root = read(text);
        String after = ScriptEdits.appendChild(text, root.span(), "robot-config", null, "<part/>").apply(text);
        assertEquals("<?xml version=\"1.0\" ?>\n<robot-config>\n  <part/>\n</robot-config>\n", after);
        String indented = "<program>\n  <main>\n  </main>\n</program>\n";
        XElement main = read(indented).children().get(0);
        assertEquals("<program>\n  <main>\n    <a/>\n  </main>\n</program>\n",
                ScriptEdits.appendChild(indented, main.span(), "main", null, "<a/>").apply(indented));
    }

    @Property(tries = 200)
    void removeAttributeTakesTheAttributeAndTheSpaceBeforeIt(@ForAll("values") String v, @ForAll boolean single,
                                                             @ForAll boolean last) {
        String q = single ? "'" : "\"";
        String a = "a = " + q + ElementWriter.attributeText(v, q.charAt(0)) + q;
        String text = "<program>\n  <x " + (last ? "b=\"2\" " + a : a + "\n     b=\"2\"") + "/>\n</program>\n";
        XElement x = read(text).children().get(0);
        String after = ScriptEdits.removeAttribute(text, x.pos(), "a").apply(text);
        assertEquals("<program>\n  <x" + (last ? " b=\"2\"" : "\n     b=\"2\"") + "/>\n</program>\n", after);
        assertEquals(0, ScriptEdits.removeAttribute(after, read(after).children().get(0).pos(), "a").replacements().size(),
                "an attribute that is not written is not removed");
    }
}
