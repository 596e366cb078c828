package org.parpe.core.xml;

import com.ctc.wstx.exc.WstxLazyException;
import com.ctc.wstx.stax.WstxInputFactory;
import java.io.StringReader;
import java.util.ArrayDeque;
import java.util.Deque;
import javax.xml.stream.Location;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamException;
import org.codehaus.stax2.XMLStreamReader2;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;

/**
 * Reads a PARSL file into an {@link XElement} tree with StAX (Woodstox). DTDs and external
 * entities are disabled. Woodstox checks well-formedness and gives the offset of every start
 * tag and text; a small scanner over the raw text then places each attribute value and each of
 * its characters, which StAX does not report.
 */
public final class XmlReader {
    private static final XMLInputFactory FACTORY = factory(false);

    private XmlReader() {
    }

    /**
     * The Woodstox factory of PARPE's XML readers: no DTDs, no external entities, text coalesced;
     * {@code namespaceAware} for the configuration files ({@link FlatXmlFile}), whose attributes
     * of another namespace keep their prefix.
     */
    static XMLInputFactory factory(boolean namespaceAware) {
        XMLInputFactory f = new WstxInputFactory();
        f.setProperty(XMLInputFactory.SUPPORT_DTD, false);
        f.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, false);
        f.setProperty(XMLInputFactory.IS_NAMESPACE_AWARE, namespaceAware);
        f.setProperty(XMLInputFactory.IS_COALESCING, true);
        return f;
    }

    /**
     * Whether {@code text} holds no element: only white space (and a byte order mark), an XML
     * declaration, comments or processing instructions.
     */
    public static boolean noElement(String text) {
        return firstElement(text) == text.length();
    }

    /**
     * The name of the root element of {@code text} as written, found without parsing (so that a
     * command can tell a challenge from a script), or "" when there is none or it is not at the
     * start of the document.
     */
    public static String rootName(String text) {
        int i = firstElement(text);
        if (i < 0 || i >= text.length() || text.charAt(i) != '<') {
            return "";
        }
        int j = i + 1;
        while (j < text.length() && (Character.isLetterOrDigit(text.charAt(j)) || "_-.:".indexOf(text.charAt(j)) >= 0)) {
            j++;
        }
        return text.substring(i + 1, j);
    }

    /** Where the first thing after white space, the declaration, comments and processing instructions is; -1 if unclosed. */
    private static int firstElement(String text) {
        int i = 0;
        int n = text.length();
        while (true) {
            while (i < n && (Character.isWhitespace(text.charAt(i)) || text.charAt(i) == '\uFEFF')) {
                i++;
            }
            if (i == n) {
                return n;
            }
            String close = text.startsWith("<?", i) ? "?>" : text.startsWith("<!--", i) ? "-->" : null;
            if (close == null) {
                return i;
            }
            int end = text.indexOf(close, i + 2);
            if (end < 0) {
                return -1;
            }
            i = end + close.length();
        }
    }

    /** Parses {@code source}; returns the root element, or {@code null} after reporting an error. */
    public static XElement read(SourceText source, DiagnosticSink diags) {
        try {
            return parse(source, diags);
        } catch (XMLStreamException e) {
            report(source, diags, e);
        } catch (WstxLazyException e) {
            // Woodstox defers some errors in text until the text is read
            report(source, diags, (XMLStreamException) e.getCause());
        }
        return null;
    }

    private static XElement parse(SourceText source, DiagnosticSink diags) throws XMLStreamException {
        String text = source.text();
        XMLStreamReader2 r = (XMLStreamReader2) FACTORY.createXMLStreamReader(new StringReader(text));
        Deque<XElement> open = new ArrayDeque<>();
        XElement root = null;
        while (r.hasNext()) {
            int ev = r.next();
            int offset = (int) r.getLocationInfo().getStartingCharOffset();
            if (ev == XMLStreamConstants.START_ELEMENT) {
                XElement e = TagScanner.element(source, offset, r.getLocalName());
                if (open.isEmpty()) {
                    root = e;
                } else {
                    open.peek().addChild(e);
                }
                open.push(e);
            } else if (ev == XMLStreamConstants.END_ELEMENT) {
                open.pop().close(offset);
            } else if ((ev == XMLStreamConstants.CHARACTERS || ev == XMLStreamConstants.CDATA)
                    && !open.isEmpty() && !r.getText().isBlank()) {
                open.peek().addText(TagScanner.text(source, offset, r.getText()));
            } else if (ev == XMLStreamConstants.DTD) {
                diags.error(source.pos(offset), Msg.NO_DOCTYPE);
                return null;
            }
        }
        r.close();
        return root;
    }

    private static void report(SourceText source, DiagnosticSink diags, XMLStreamException e) {
        Location loc = e.getLocation();
        String msg = e.getMessage() == null ? Msg.MALFORMED_XML_UNKNOWN.text() : e.getMessage();
        int cut = msg.indexOf("\n at [");
        msg = (cut >= 0 ? msg.substring(0, cut) : msg).replace('\n', ' ').trim();
        if (msg.startsWith("ParseError at [")) {
            msg = msg.substring(msg.indexOf("Message:") + 8).trim();
        }
        diags.error(loc == null ? source.pos(0) : source.pos(loc.getLineNumber(), loc.getColumnNumber()),
                Msg.MALFORMED_XML, msg,
                loc == null ? Message.EMPTY : unquoted(source.text(), loc.getLineNumber(), loc.getColumnNumber(), msg));
    }

    /**
     * What to type instead when the parser wanted a quote: an attribute value without quotes, as
     * {@code period=1}; empty otherwise.
     */
    static Message unquoted(String text, int line, int column, String msg) {
        if (!msg.contains("Expected a quote")) {
            return Message.EMPTY;
        }
        int at = 0;
        for (int l = 1; l < line && at >= 0; l++) {
            at = text.indexOf('\n', at) + 1;
            if (at == 0) {
                return Message.EMPTY;
            }
        }
        int end = Math.min(text.length(), at + Math.max(0, column - 1));
        // The parser stops at the value's first character or just after it: go back to the '='.
        int eq = text.lastIndexOf('=', end);
        if (eq < 0 || eq < text.lastIndexOf('<', end)) {
            return Message.EMPTY;
        }
        int nameEnd = eq;
        while (nameEnd > 0 && Character.isWhitespace(text.charAt(nameEnd - 1))) {
            nameEnd--;
        }
        int nameStart = nameEnd;
        while (nameStart > 0 && isNameChar(text.charAt(nameStart - 1))) {
            nameStart--;
        }
        int valueStart = eq + 1;
        while (valueStart < text.length() && Character.isWhitespace(text.charAt(valueStart))) {
            valueStart++;
        }
        int valueEnd = valueStart;
        while (valueEnd < text.length() && !Character.isWhitespace(text.charAt(valueEnd)) && text.charAt(valueEnd) != '>'
                && !(text.charAt(valueEnd) == '/' && valueEnd + 1 < text.length() && text.charAt(valueEnd + 1) == '>')) {
            valueEnd++;
        }
        if (nameStart == nameEnd || valueStart == valueEnd) {
            return Message.EMPTY;
        }
        String name = text.substring(nameStart, nameEnd);
        return Message.of(Msg.QUOTE_THE_VALUE, name, text.substring(valueStart, valueEnd));
    }

    private static boolean isNameChar(char c) {
        return Character.isLetterOrDigit(c) || c == '_' || c == '-' || c == '.' || c == ':';
    }
}
