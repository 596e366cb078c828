package org.parpe.core.xml;

import org.parpe.core.text.Key;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;
import com.ctc.wstx.exc.WstxLazyException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import javax.xml.stream.Location;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamException;
import org.codehaus.stax2.XMLStreamReader2;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.lang.Numbers;

/**
 * A small XML file made of one root element whose child elements carry only attributes (robot
 * configurations of the simulator, hardware profiles of servo buses, worlds), read with the
 * StAX parser (Woodstox) that reads scripts, so that every element keeps its place. The checks the readers of such
 * files share are here too: known and required attributes, numbers. Every problem goes to the
 * sink at {@code FILE:LINE:COL}, all of them, not only the first; {@link #ok} tells whether
 * there was one.
 */
public final class FlatXmlFile {
    /**
     * A child element of the root.
     *
     * @param name       its tag
     * @param attributes its attributes in document order, values trimmed
     * @param at         where it starts
     */
    public record Element(String name, Map<String, String> attributes, SourcePos at) {
    }

    /** Namespace-aware (an attribute of another namespace keeps its prefix); no DTDs, no external entities. */
    private static final XMLInputFactory FACTORY = XmlReader.factory(true);

    /** The place the StAX parser writes into its messages. */
    private static final java.util.regex.Pattern PARSER_PLACE =
            java.util.regex.Pattern.compile("\\s*at \\[row,col[^\\]]*\\]: \\[(-?\\d+),(-?\\d+)\\]");

    private final String file;
    private final DiagnosticSink diags;
    /** The text being read when it was given as text (then every element gets its span), else null. */
    private SourceText source;
    private final Map<String, String> rootAttributes = new LinkedHashMap<>();
    private final List<Element> children = new ArrayList<>();
    private SourcePos rootAt;
    private boolean ok = true;
    private int errors;

    private FlatXmlFile(String file, DiagnosticSink diags) {
        this.file = file;
        this.diags = diags;
    }

    /**
     * Reads {@code path}, a {@code what} (for example "hardware profile") whose root element is
     * {@code root}; {@code expected} describes the document for messages (for example "a
     * &lt;hardware&gt; element with &lt;servo&gt; elements"). Read errors and a wrong root are
     * reported; then {@link #root()} is null.
     */
    public static FlatXmlFile read(Path path, Message what, String root, Message expected, DiagnosticSink diags) {
        FlatXmlFile f = new FlatXmlFile(path.toString(), diags);
        try (InputStream in = InputFiles.open(path)) {
            f.parse(() -> (XMLStreamReader2) FACTORY.createXMLStreamReader(in), what, root, expected);
        } catch (IOException e) {
            f.error(f.start(), Msg.CANNOT_READ_THE, what, e.getMessage());
            f.rootAt = null;
        }
        return f;
    }

    /**
     * Reads {@code text}, the contents of {@code file} (for example an editor's text), as
     * {@link #read(Path, Message, String, Message, DiagnosticSink)} reads a file, with the same
     * checks and messages; the place of the root and of every child element also carries the
     * element's {@link org.parpe.core.diag.SourceSpan} and offset, so that an editor can change
     * it through the edit layer ({@code org.parpe.core.edit}).
     */
    public static FlatXmlFile read(String file, String text, Message what, String root, Message expected,
                                   DiagnosticSink diags) {
        FlatXmlFile f = new FlatXmlFile(file, diags);
        f.source = new SourceText(file, text);
        f.parse(() -> (XMLStreamReader2) FACTORY.createXMLStreamReader(new java.io.StringReader(text)), what, root, expected);
        return f;
    }

    /** Where a document is read from: a reader over a file or over text. */
    @FunctionalInterface
    private interface ReaderSource {
        XMLStreamReader2 open() throws XMLStreamException;
    }

    /** Reads the document {@code source} opens; a document that is not well formed is reported at its place. */
    private void parse(ReaderSource source, Message what, String root, Message expected) {
        try {
            XMLStreamReader2 r = source.open();
            try {
                document(r, what, root, expected);
            } finally {
                r.close();
            }
        } catch (XMLStreamException e) {
            notWellFormed(e);
            rootAt = null;
        } catch (WstxLazyException e) {
            // Woodstox defers some errors in text (an undefined entity) until the text is read
            notWellFormed((XMLStreamException) e.getCause());
            rootAt = null;
        }
    }

    /**
     * A parse error at its place, in the parser's words without its own note of the place
     * ("at [row,col {unknown-source}]: [3,18]"), which also gives the place when the exception
     * carries none.
     */
    private void notWellFormed(XMLStreamException e) {
        String message = e.getMessage() == null ? "" : e.getMessage();
        java.util.regex.Matcher m = PARSER_PLACE.matcher(message);
        SourcePos at = null;
        if (m.find()) {
            at = new SourcePos(file, Math.max(1, Integer.parseInt(m.group(1))), Math.max(1, Integer.parseInt(m.group(2))));
            message = (message.substring(0, m.start()) + message.substring(m.end())).trim();
        }
        Location l = e.getLocation();
        if (l != null && l.getLineNumber() > 0) {
            at = pos(l);
        }
        error(at == null ? start() : at, Msg.NOT_WELL_FORMED, message);
    }

    /** Where the root element starts; null when the file could not be read or has another root. */
    public SourcePos root() {
        return rootAt;
    }

    /** The root's attributes, values trimmed. */
    public Map<String, String> rootAttributes() {
        return rootAttributes;
    }

    /** The root's child elements in document order. */
    public List<Element> children() {
        return children;
    }

    /** The file's first position. */
    public SourcePos start() {
        return new SourcePos(file, 1, 1);
    }

    /** Whether no problem was reported, by the reading or by a check. */
    public boolean ok() {
        return ok;
    }

    /** Reports an error at {@code at}, the text of {@code key} with {@code args}; {@link #ok} turns false. */
    public void error(SourcePos at, Key key, Object... args) {
        diags.error(at, key, args);
        ok = false;
        errors++;
    }

    /** How many problems were reported so far (a reader compares counts to tell whether a step failed). */
    public int errors() {
        return errors;
    }

    /** Whether every attribute of {@code a} is in {@code allowed}; each other one is an error. */
    public boolean known(Map<String, String> a, Set<String> allowed, String element, SourcePos at) {
        boolean good = true;
        for (String k : a.keySet()) {
            if (!allowed.contains(k)) {
                error(at, Msg.HAS_NO_ATTRIBUTE, element, k, String.join(", ", allowed.stream().sorted().toList()));
                good = false;
            }
        }
        return good;
    }

    /** Whether each of {@code keys} is given and not empty; each missing one is an error. */
    public boolean required(Map<String, String> a, SourcePos at, String element, String... keys) {
        boolean good = true;
        for (String k : keys) {
            if (!a.containsKey(k) || a.get(k).isEmpty()) {
                error(at, Msg.NEEDS_THE_ATTRIBUTE, element, k);
                good = false;
            }
        }
        return good;
    }

    /**
     * Attribute {@code key} as a number ({@code whole}: a whole one) in {@code lo…hi}, or
     * {@code fallback} when it is not given or after an error. The plain decimals of scripts:
     * {@code Double.parseDouble} would take "1d", "0x1p3" or "NaN".
     */
    public double number(Map<String, String> a, String key, double fallback, SourcePos at, boolean whole,
                         double lo, double hi) {
        String v = a.get(key);
        if (v == null) {
            return fallback;
        }
        Double d = Numbers.parsePlain(v);
        if (d == null || whole && d != Math.rint(d)) {
            error(at, whole ? Msg.MUST_BE_WHOLE : Msg.MUST_BE_NUMBER, key, v);
            return fallback;
        }
        if (d < lo || d > hi) {
            error(at, Msg.MUST_BE_IN_RANGE, key, plain(lo), plain(hi), v);
            return fallback;
        }
        return d;
    }

    /** {@code d} as a whole number when it is one, else with two decimals. */
    public static String plain(double d) {
        return d == Math.rint(d) ? String.valueOf((long) d) : String.format(Locale.ROOT, "%.2f", d);
    }

    private void document(XMLStreamReader2 r, Message what, String root, Message expected) throws XMLStreamException {
        int ev = r.next();
        while (ev != XMLStreamConstants.START_ELEMENT && ev != XMLStreamConstants.END_DOCUMENT) {
            if (ev == XMLStreamConstants.DTD) {
                // as XmlReader says for scripts: the parser reads no DTD, so its entities would
                // only be "undeclared" later on; say what is refused, where it is
                error(here(r), Msg.NO_DOCTYPE_IN, what);
                return;
            }
            ev = r.next();
        }
        if (ev != XMLStreamConstants.START_ELEMENT) {
            error(start(), Msg.EXPECTED_ROOT, expected);
            return;
        }
        SourcePos at = here(r);
        String rootName = r.getLocalName();
        if (!root.equals(rootName)) {
            error(at, "program".equals(rootName) ? Msg.NOT_THIS_KIND_BUT_SCRIPT : Msg.NOT_THIS_KIND, rootName, what, expected);
            return;
        }
        Spanned rootSpan = spanned(r, rootName);
        rootAt = at;
        rootAttributes.putAll(attributes(r));
        Text text = new Text();
        for (ev = r.next(); ev != XMLStreamConstants.END_ELEMENT; ev = r.next()) {
            if (ev == XMLStreamConstants.START_ELEMENT) {
                text.reportIfAny(root);
                text = new Text();
                child(r);
            } else {
                text.add(r, ev);
            }
        }
        text.reportIfAny(root);
        rootAt = rootSpan.at(r, at);
        // What follows the root is read to the end, as XmlReader reads a script: the parser
        // refuses a second element or text there, so every file PARPE reads has one rule.
        while (r.hasNext()) {
            r.next();
        }
    }

    /**
     * A child of the root, the reader on its start tag: its attributes; nested elements and text
     * are errors at their place, in document order (text at the element's own start tag when it
     * has neither attributes nor elements).
     */
    private void child(XMLStreamReader2 r) throws XMLStreamException {
        String name = r.getLocalName();
        SourcePos at = here(r);
        Spanned spanned = spanned(r, name);
        Map<String, String> attrs = attributes(r);
        List<SourcePos> places = new ArrayList<>();
        List<String> inner = new ArrayList<>(); // null for text
        Text text = new Text();
        for (int ev = r.next(); ev != XMLStreamConstants.END_ELEMENT; ev = r.next()) {
            if (ev == XMLStreamConstants.START_ELEMENT) {
                text.addTo(places, inner);
                text = new Text();
                places.add(here(r));
                inner.add(r.getLocalName());
                r.skipElement();
            } else {
                text.add(r, ev);
            }
        }
        text.addTo(places, inner);
        // without attributes and elements the element is text only: the text is placed at the element
        boolean bare = attrs.isEmpty() && inner.stream().allMatch(java.util.Objects::isNull);
        for (int i = 0; i < places.size(); i++) {
            SourcePos where = inner.get(i) != null ? places.get(i) : bare ? at : places.get(i);
            if (inner.get(i) == null) {
                error(where, Msg.MAY_NOT_CONTAIN_TEXT, name);
            } else {
                error(where, Msg.MAY_NOT_CONTAIN_ELEMENT, name, inner.get(i));
            }
        }
        children.add(new Element(name, attrs, spanned.at(r, at)));
    }

    /** The start tag the reader stands on, scanned for its span when the file was given as text; else null. */
    private Spanned spanned(XMLStreamReader2 r, String name) {
        return new Spanned(source == null ? null
                : TagScanner.element(source, (int) r.getLocationInfo().getStartingCharOffset(), name));
    }

    /** An element whose span is known once the reader reaches its end tag ({@code tag} null: not read from text). */
    private record Spanned(XElement tag) {
        /** {@code at} with the element's span and offset, the reader on the element's end. */
        SourcePos at(XMLStreamReader2 r, SourcePos at) {
            if (tag == null) {
                return at;
            }
            tag.close((int) r.getLocationInfo().getStartingCharOffset());
            return new SourcePos(at.file(), at.line(), at.column(), tag.span(), tag.span().start());
        }
    }

    /** Text between two tags: where its first non-blank character stands, if it has one. */
    private final class Text {
        SourcePos first;

        void add(XMLStreamReader2 r, int ev) throws XMLStreamException {
            if (first == null && (ev == XMLStreamConstants.CHARACTERS || ev == XMLStreamConstants.CDATA)
                    && !r.getText().isBlank()) {
                first = textStart(r.getLocationInfo().getStartLocation(), r.getText());
            }
        }

        /** Adds the text's place (and {@code null} for "text") when it is not blank. */
        void addTo(List<SourcePos> places, List<String> what) {
            if (first != null) {
                places.add(first);
                what.add(null);
            }
        }

        void reportIfAny(String element) {
            if (first != null) {
                error(first, Msg.MAY_NOT_CONTAIN_TEXT, element);
            }
        }
    }

    /**
     * The attributes of the element the reader stands on, values trimmed; one of another
     * namespace keeps its prefix ({@code x:protocol}), so that it cannot stand in for ours.
     */
    private static Map<String, String> attributes(XMLStreamReader2 r) {
        Map<String, String> attrs = new LinkedHashMap<>();
        for (int i = 0; i < r.getAttributeCount(); i++) {
            String prefix = r.getAttributePrefix(i);
            String local = r.getAttributeLocalName(i);
            attrs.put(prefix == null || prefix.isEmpty() ? local : prefix + ":" + local, r.getAttributeValue(i).trim());
        }
        return attrs;
    }

    /** Where the first non-blank character of {@code text}, which began at {@code from}, stands. */
    private SourcePos textStart(Location from, String text) {
        int line = Math.max(1, from.getLineNumber());
        int col = Math.max(1, from.getColumnNumber());
        for (int i = 0; i < text.length() && Character.isWhitespace(text.charAt(i)); i++) {
            if (text.charAt(i) == '\n') {
                line++;
                col = 1;
            } else {
                col++;
            }
        }
        return new SourcePos(file, line, col);
    }

    /** Where the event the reader stands on starts. */
    private SourcePos here(XMLStreamReader2 r) throws XMLStreamException {
        return pos(r.getLocationInfo().getStartLocation());
    }

    private SourcePos pos(Location l) {
        return new SourcePos(file, Math.max(1, l.getLineNumber()), Math.max(1, l.getColumnNumber()));
    }
}
