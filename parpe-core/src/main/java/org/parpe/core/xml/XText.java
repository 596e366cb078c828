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
    private final int[] offsets;
    private final int endOffset;
    private final SourceText source;
    private final SourcePos fixed;

    XText(String value, int[] offsets, int endOffset, SourceText source) {
        this(value, offsets, endOffset, source, null);
    }

    private XText(String value, int[] offsets, int endOffset, SourceText source, SourcePos fixed) {
        this.value = value;
        this.offsets = offsets;
        this.endOffset = endOffset;
        this.source = source;
        this.fixed = fixed;
    }

    /** A text whose every character is placed at {@code pos} (e.g. a command-line value). */
    public static XText detached(String value, SourcePos pos) {
        return new XText(value, new int[0], 0, null, pos);
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
        if (offsets.length == 0) {
            return source.pos(endOffset);
        }
        if (index < 0) {
            return source.pos(offsets[0]);
        }
        return source.pos(index < offsets.length ? offsets[index] : endOffset);
    }

    /** The position where the value starts. */
    public SourcePos pos() {
        return posAt(0);
    }

    /** The part {@code [from, to)} of this text, keeping positions. */
    public XText sub(int from, int to) {
        if (fixed != null) {
            return new XText(value.substring(from, to), offsets, 0, null, fixed);
        }
        int end = to < offsets.length ? offsets[to] : endOffset;
        return new XText(value.substring(from, to), Arrays.copyOfRange(offsets, from, to), end, source, null);
    }

    @Override
    public String toString() {
        return value;
    }
}
