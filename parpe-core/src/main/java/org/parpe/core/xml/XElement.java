package org.parpe.core.xml;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.diag.SourceSpan;

/**
 * An element of the parse tree: name, attributes and text, each with its place in the file.
 * Built once by {@link XmlReader} and not changed afterwards.
 */
public final class XElement {
    private final String name;
    /** Set again with the span once the element's end is read. */
    private SourcePos pos;
    private final SourceText source;
    private final int start;
    private int tagEnd;
    private final Map<String, SourceSpan.Range> valueRanges = new LinkedHashMap<>();
    private final Map<String, XAttr> attributes = new LinkedHashMap<>();
    private final List<XElement> children = new ArrayList<>();
    private final List<XText> texts = new ArrayList<>();

    XElement(String name, SourcePos pos, SourceText source, int start) {
        this.name = name;
        this.pos = pos;
        this.source = source;
        this.start = start;
    }

    /** An attribute with its name's place and its value's text. */
    public record XAttr(String name, SourcePos pos, XText value) {
    }

    /** The element name. */
    public String name() {
        return name;
    }

    /**
     * The place of the element name in its start tag, with the element's {@link SourceSpan}
     * (offsets of the element and of each attribute value in {@link #source()}'s text).
     */
    public SourcePos pos() {
        return pos;
    }

    /** The file the element comes from. */
    public SourceText source() {
        return source;
    }

    /** Attributes in document order. */
    public Map<String, XAttr> attributes() {
        return Collections.unmodifiableMap(attributes);
    }

    /** The attribute called {@code name}, or {@code null}. */
    public XAttr attr(String name) {
        return attributes.get(name);
    }

    /** Child elements in document order. */
    public List<XElement> children() {
        return Collections.unmodifiableList(children);
    }

    /** Non-blank text pieces directly inside this element. */
    public List<XText> texts() {
        return Collections.unmodifiableList(texts);
    }

    /** The element's offsets in its file (also carried by {@link #pos()}). */
    public SourceSpan span() {
        return pos.span();
    }

    void addAttribute(XAttr a, SourceSpan.Range value) {
        attributes.put(a.name(), a);
        valueRanges.put(a.name(), value);
    }

    void tagEnd(int offset) {
        tagEnd = offset;
    }

    /**
     * Records the element's end, whose end tag starts at {@code endTag} (the parser's offset of
     * the end event): its place gets its span.
     */
    void close(int endTag) {
        String s = source.text();
        int end = s.charAt(tagEnd) == '/' ? tagEnd + 2 : s.indexOf('>', endTag) + 1;
        pos = pos.withSpan(new SourceSpan(start, end, tagEnd, valueRanges));
    }

    void addChild(XElement e) {
        children.add(e);
    }

    void addText(XText t) {
        texts.add(t);
    }
}
