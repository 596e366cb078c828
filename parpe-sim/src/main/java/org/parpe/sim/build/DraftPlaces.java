package org.parpe.sim.build;

import java.util.ArrayList;
import java.util.List;
import org.parpe.core.diag.SourceSpan;
import org.parpe.core.edit.ElementWriter;
import org.parpe.core.edit.Replacement;
import org.parpe.core.edit.ScriptEdits;
import org.parpe.core.edit.TextEdit;
import org.parpe.core.xml.FlatXmlFile;

/**
 * Where a builder edit writes in a draft's text, by the spans the reader gave its elements:
 * a new {@code <part>} after the last {@code <part>}, a new {@code <connect>} after the last
 * {@code <connect>} (after the new part when there is none), a new {@code <root>} last, each
 * with that element's indentation; an attribute set or, at its default, left out; an element
 * removed with its line.
 */
final class DraftPlaces {
    private static final String ROOT = "robot-config";

    private final RobotDraft draft;
    private final String text;

    DraftPlaces(RobotDraft draft) {
        this.draft = draft;
        this.text = draft.text();
    }

    /** A new part (or none) after the last {@code <part>} and a new connection after the last {@code <connect>}. */
    TextEdit insert(String part, String connect) {
        SourceSpan lastPart = last("part");
        SourceSpan lastConnect = last("connect");
        List<Replacement> out = new ArrayList<>();
        if (lastConnect == null) {
            String both = (part == null ? "" : part + "\n" + ElementWriter.indent(text, lastPart.start())) + connect;
            return ScriptEdits.appendChild(text, draft.read().root().span(), ROOT, lastPart, both);
        }
        if (part != null) {
            out.addAll(ScriptEdits.appendChild(text, draft.read().root().span(), ROOT, lastPart, part).replacements());
        }
        out.addAll(ScriptEdits.appendChild(text, draft.read().root().span(), ROOT, lastConnect, connect).replacements());
        return new TextEdit(out);
    }

    /** {@code element} after the root's last child. */
    TextEdit appendLast(String element) {
        List<FlatXmlFile.Element> all = draft.read().elements();
        return ScriptEdits.appendChild(text, draft.read().root().span(), ROOT, all.get(all.size() - 1).at().span(), element);
    }

    SourceSpan last(String element) {
        SourceSpan s = null;
        for (FlatXmlFile.Element e : draft.read().elements()) {
            if (e.name().equals(element)) {
                s = e.at().span();
            }
        }
        return s;
    }

    TextEdit setOrDrop(org.parpe.core.diag.SourcePos node, String attribute, String value, boolean drop) {
        return drop ? ScriptEdits.removeAttribute(text, node, attribute) : ScriptEdits.setAttribute(text, node, attribute, value);
    }

    List<Replacement> removed(SourceSpan s) {
        return ScriptEdits.removeElement(text, s).replacements();
    }
}
