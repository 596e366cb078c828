package org.parpe.core.xml;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.dataformat.xml.XmlFactory;
import com.fasterxml.jackson.dataformat.xml.deser.FromXmlParser;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamReader;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.lang.Numbers;

/**
 * A small XML file made of one root element whose child elements carry only attributes (robot
 * configurations of the simulator, hardware profiles of servo buses), read with Jackson's
 * streaming XML parser so that every element keeps its place. The checks the readers of such
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

    /** The place the StAX parser writes into its messages. */
    private static final java.util.regex.Pattern PARSER_PLACE =
            java.util.regex.Pattern.compile("\\s*at \\[row,col[^\\]]*\\]: \\[(-?\\d+),(-?\\d+)\\]");

    private final String file;
    private final DiagnosticSink diags;
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
    public static FlatXmlFile read(Path path, String what, String root, String expected, DiagnosticSink diags) {
        FlatXmlFile f = new FlatXmlFile(path.toString(), diags);
        try (InputStream in = InputFiles.open(path);
             JsonParser p = new XmlFactory().createParser(in)) {
            f.document(p, what, root, expected);
        } catch (JsonProcessingException e) {
            f.notWellFormed(e);
            f.rootAt = null;
        } catch (IOException e) {
            f.error(f.start(), "cannot read the " + what + ": " + e.getMessage());
            f.rootAt = null;
        }
        return f;
    }

    /**
     * A parse error at its place, in the parser's words without its own note of the place
     * ("at [row,col {unknown-source}]: [3,18]"), which also gives the place when the exception
     * carries none.
     */
    private void notWellFormed(JsonProcessingException e) {
        String message = e.getOriginalMessage() == null ? "" : e.getOriginalMessage();
        java.util.regex.Matcher m = PARSER_PLACE.matcher(message);
        SourcePos at = null;
        if (m.find()) {
            at = new SourcePos(file, Math.max(1, Integer.parseInt(m.group(1))), Math.max(1, Integer.parseInt(m.group(2))));
            message = (message.substring(0, m.start()) + message.substring(m.end())).trim();
        }
        JsonLocation l = e.getLocation();
        if (l != null && l.getLineNr() > 0) {
            at = pos(l);
        }
        error(at == null ? start() : at, "not well-formed XML: " + message);
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

    /** Reports an error at {@code at}; {@link #ok} turns false. */
    public void error(SourcePos at, String message) {
        diags.error(at, message);
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
                error(at, "<" + element + "> has no attribute '" + k + "'; it takes "
                        + String.join(", ", allowed.stream().sorted().toList()));
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
                error(at, "<" + element + "> needs the attribute '" + k + "'");
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
            error(at, key + " must be " + (whole ? "a whole number" : "a number") + ", got '" + v + "'");
            return fallback;
        }
        if (d < lo || d > hi) {
            error(at, key + " must be in " + plain(lo) + ".." + plain(hi) + ", got " + v);
            return fallback;
        }
        return d;
    }

    /** {@code d} as a whole number when it is one, else with two decimals. */
    public static String plain(double d) {
        return d == Math.rint(d) ? String.valueOf((long) d) : String.format(Locale.ROOT, "%.2f", d);
    }

    private void document(JsonParser p, String what, String root, String expected) throws IOException {
        if (p.nextToken() != JsonToken.START_OBJECT) {
            error(start(), "expected " + expected);
            return;
        }
        SourcePos at = pos(p.currentTokenLocation());
        String rootName = p instanceof FromXmlParser x ? x.getStaxReader().getLocalName() : root;
        if (!root.equals(rootName)) {
            error(at, "<" + rootName + "> is not a " + what + ("program".equals(rootName) ? " but a PARSL script" : "")
                    + "; expected " + expected);
            return;
        }
        rootAt = at;
        rootAttributes.putAll(staxAttributes(p));
        JsonLocation after = p.currentLocation();
        while (p.nextToken() == JsonToken.FIELD_NAME) {
            String name = p.currentName();
            SourcePos here = pos(p.currentTokenLocation());
            boolean element = isElement(p, name);
            Map<String, String> attrs = element ? staxAttributes(p) : null;
            JsonToken t = p.nextToken();
            if (t == JsonToken.START_OBJECT) {
                children.add(new Element(name, attributes(p, name, attrs), here));
            } else if (name.isEmpty()) {
                if (!p.getText().isBlank()) {
                    error(textStart(after, p.getText()), "<" + root + "> may not contain text");
                }
            } else if (t == JsonToken.START_ARRAY) {
                error(here, "<" + name + "> may not contain elements");
                p.skipChildren();
            } else if (element) {
                // An element without attributes: empty, or with text only.
                if (p.getText() != null && !p.getText().isBlank()) {
                    error(here, "<" + name + "> may not contain text");
                }
                children.add(new Element(name, Map.of(), here));
            }
            // Other fields are the root's attributes, taken from the StAX reader above.
            after = p.currentLocation();
        }
    }

    /**
     * The attributes of the element the StAX reader stands on, values trimmed; one of another
     * namespace keeps its prefix ({@code x:protocol}), so that it cannot stand in for ours.
     */
    private static Map<String, String> staxAttributes(JsonParser p) {
        Map<String, String> attrs = new LinkedHashMap<>();
        if (p instanceof FromXmlParser x && x.getStaxReader().getEventType() == XMLStreamConstants.START_ELEMENT) {
            XMLStreamReader r = x.getStaxReader();
            for (int i = 0; i < r.getAttributeCount(); i++) {
                String prefix = r.getAttributePrefix(i);
                String local = r.getAttributeLocalName(i);
                attrs.put(prefix == null || prefix.isEmpty() ? local : prefix + ":" + local,
                        r.getAttributeValue(i).trim());
            }
        }
        return attrs;
    }

    /** Where the first non-blank character of {@code text}, which began at {@code from}, stands. */
    private SourcePos textStart(JsonLocation from, String text) {
        int line = Math.max(1, from.getLineNr());
        int col = Math.max(1, from.getColumnNr());
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

    /** Whether the field just read is a child element (an empty one looks like an attribute otherwise). */
    private static boolean isElement(JsonParser p, String name) {
        if (!(p instanceof FromXmlParser x)) {
            return false;
        }
        XMLStreamReader r = x.getStaxReader();
        return r.getEventType() == XMLStreamConstants.START_ELEMENT && name.equals(r.getLocalName());
    }

    /** The current element's {@code attrs} (read from StAX); nested elements and text are errors. */
    private Map<String, String> attributes(JsonParser p, String element, Map<String, String> attrs) throws IOException {
        while (p.nextToken() == JsonToken.FIELD_NAME) {
            String key = p.currentName();
            SourcePos at = pos(p.currentTokenLocation());
            boolean nested = isElement(p, key);
            JsonToken t = p.nextToken();
            if (nested || t == JsonToken.START_OBJECT || t == JsonToken.START_ARRAY) {
                error(at, "<" + element + "> may not contain <" + key + ">");
                p.skipChildren();
            } else if (key.isEmpty() && !p.getText().isBlank()) {
                error(at, "<" + element + "> may not contain text");
            }
        }
        return attrs;
    }

    private SourcePos pos(JsonLocation l) {
        return new SourcePos(file, Math.max(1, l.getLineNr()), Math.max(1, l.getColumnNr()));
    }
}
