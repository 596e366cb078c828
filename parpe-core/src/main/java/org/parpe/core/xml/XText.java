package org.parpe.core.xml;

import java.util.Arrays;
import org.parpe.core.diag.SourcePos;

/**
 * A decoded piece of source text (an attribute value or element text) that remembers, for
 * every character, where it came from in the file, so an error inside an expression can point
 * at its exact column even after entity decoding ({@code &lt;} is one character).
 */
public final class XText {
    private final String value;
    /** The offset of the first character when characters map one to one onto the file. */
    private final int start;
    /** The offset of each character, only where decoding made them differ (entities, CR LF). */
    private final int[] offsets;
    private final int endOffset;
    private final SourceText source;
    private final SourcePos fixed;

    /**
     * A text whose character {@code i} is at {@code offsets[i]}, or, with {@code offsets}
     * {@code null}, at {@code start + i}: most text has no entity, and an offset per character
     * made a large gait table take four times its size again.
     */
    XText(String value, int start, int[] offsets, int endOffset, SourceText source) {
        this(value, start, offsets, endOffset, source, null);
    }

    private XText(String value, int start, int[] offsets, int endOffset, SourceText source, SourcePos fixed) {
        this.value = value;
        this.start = start;
        this.offsets = offsets;
        this.endOffset = endOffset;
        this.source = source;
        this.fixed = fixed;
    }

    /** A text whose every character is placed at {@code pos} (e.g. a command-line value). */
    public static XText detached(String value, SourcePos pos) {
        return new XText(value, 0, null, 0, null, pos);
    }

    /** The decoded value. */
    public String value() {
        return value;
    }

    /** The position of character {@code index} of the value (the end if past it). */
    public SourcePos posAt(int index) {
        if (fixed != null) {
            return fixed;
        }
        return source.pos(offset(Math.max(index, 0)));
    }

    private int offset(int index) {
        if (index >= value.length()) {
            return endOffset;
        }
        return offsets == null ? start + index : offsets[index];
    }

    /** The position where the value starts. */
    public SourcePos pos() {
        return posAt(0);
    }

    /** The part {@code [from, to)} of this text, keeping positions. */
    public XText sub(int from, int to) {
        if (fixed != null) {
            return new XText(value.substring(from, to), 0, null, 0, null, fixed);
        }
        int[] part = offsets == null ? null : Arrays.copyOfRange(offsets, from, to);
        return new XText(value.substring(from, to), offset(from), part, offset(to), source, null);
    }

    @Override
    public String toString() {
        return value;
    }
}
