package org.parpe.core.xml;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.parpe.core.diag.SourcePos;

/**
 * An element of the parse tree: name, attributes and text, each with its place in the file.
 * Built once by {@link XmlReader} and not changed afterwards.
 */
public final class XElement {
    private final String name;
    private final SourcePos pos;
    private final SourceText source;
    private final Map<String, XAttr> attributes = new LinkedHashMap<>();
    private final List<XElement> children = new ArrayList<>();
    private final List<XText> texts = new ArrayList<>();

    XElement(String name, SourcePos pos, SourceText source) {
        this.name = name;
        this.pos = pos;
        this.source = source;
    }

    /** An attribute with its name's place and its value's text. */
    public record XAttr(String name, SourcePos pos, XText value) {
    }

    /** The element name. */
    public String name() {
        return name;
    }

    /** The place of the element name in its start tag. */
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

    void addAttribute(XAttr a) {
        attributes.put(a.name(), a);
    }

    void addChild(XElement e) {
        children.add(e);
    }

    void addText(XText t) {
        texts.add(t);
    }
}
