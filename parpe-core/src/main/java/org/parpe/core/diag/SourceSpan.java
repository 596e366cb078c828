package org.parpe.core.diag;

import java.util.Map;

/**
 * Where an element is in the text of its file, as character offsets: the whole element
 * ({@code <} of the start tag to just after its end tag), the end of the start tag, and the
 * value of each attribute (between the quotes, as written, entities not decoded). A view that
 * changes one attribute replaces exactly {@link #value(String)}'s range and nothing else.
 *
 * @param start    offset of the {@code <} of the start tag
 * @param end      offset just after the element ({@code />} or the end tag)
 * @param tagEnd   offset of the {@code >} or {@code />} that closes the start tag
 * @param values   the range of each attribute's value, in document order
 */
public record SourceSpan(int start, int end, int tagEnd, Map<String, Range> values) {

    public SourceSpan {
        values = java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(values));
    }

    /**
     * A range of characters {@code [offset, offset + length)}.
     *
     * @param offset the first character
     * @param length the number of characters
     */
    public record Range(int offset, int length) {
        /** Just after the last character. */
        public int end() {
            return offset + length;
        }

        /** The characters of {@code text} in this range. */
        public String of(String text) {
            return text.substring(offset, end());
        }
    }

    /** The range of attribute {@code name}'s value, or {@code null} when it is not written. */
    public Range value(String name) {
        return values.get(name);
    }

    /** Whether the element is written as an empty-element tag ({@code <x/>}). */
    public boolean empty() {
        return tagEnd + 2 == end;
    }
}
