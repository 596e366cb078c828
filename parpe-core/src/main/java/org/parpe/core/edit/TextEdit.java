package org.parpe.core.edit;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * An edit of a script's (or any XML file's) text: {@link Replacement}s of ranges of the original
 * text that do not overlap. A diagram edit becomes one of these, so the editor applies it as one
 * Undo step and everything outside the replaced ranges (comments, order, layout) stays byte for
 * byte.
 *
 * @param replacements the replacements, in text order
 */
public record TextEdit(List<Replacement> replacements) {

    public TextEdit {
        List<Replacement> sorted = new ArrayList<>(replacements);
        sorted.sort(Comparator.comparingInt(Replacement::offset));
        for (int i = 1; i < sorted.size(); i++) {
            if (sorted.get(i).offset() < sorted.get(i - 1).end()) {
                throw new IllegalArgumentException("replacements overlap: " + sorted.get(i - 1) + " and " + sorted.get(i));
            }
        }
        replacements = List.copyOf(sorted);
    }

    /** An edit of one range. */
    public static TextEdit of(int offset, int length, String text) {
        return new TextEdit(List.of(new Replacement(offset, length, text)));
    }

    /** {@code text} with every replacement made. */
    public String apply(String text) {
        StringBuilder out = new StringBuilder(text.length() + 64);
        int at = 0;
        for (Replacement r : replacements) {
            out.append(text, at, r.offset()).append(r.text());
            at = r.end();
        }
        return out.append(text, at, text.length()).toString();
    }
}
