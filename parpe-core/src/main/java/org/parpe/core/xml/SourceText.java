package org.parpe.core.xml;

import java.util.Arrays;
import org.parpe.core.diag.SourcePos;

/** A file's text with a line index, turning character offsets into line/column positions. */
public final class SourceText {
    private final String file;
    private final String text;
    private final int[] lineStarts;

    /** Indexes {@code text}, which was read from {@code file} (the name used in messages). */
    public SourceText(String file, String text) {
        this.file = file;
        this.text = text;
        int[] starts = new int[16];
        int n = 0;
        starts[n++] = 0;
        for (int i = 0; i < text.length(); i++) {
            if (text.charAt(i) == '\n') {
                if (n == starts.length) {
                    starts = Arrays.copyOf(starts, n * 2);
                }
                starts[n++] = i + 1;
            }
        }
        this.lineStarts = Arrays.copyOf(starts, n);
    }

    /** The file name used in messages. */
    public String file() {
        return file;
    }

    /** The whole text. */
    public String text() {
        return text;
    }

    /** The position of character offset {@code offset} (1-based line and column). */
    public SourcePos pos(int offset) {
        int o = Math.max(0, Math.min(offset, text.length()));
        int i = Arrays.binarySearch(lineStarts, o);
        int line = i >= 0 ? i : -i - 2;
        return new SourcePos(file, line + 1, o - lineStarts[line] + 1, null, o);
    }

    /**
     * The position of a 1-based line and column (as reported by the XML parser); its offset is
     * at most its line's end, and unknown for a line the text does not have.
     */
    public SourcePos pos(int line, int column) {
        int l = Math.max(1, line);
        int c = Math.max(1, column);
        int offset = -1;
        if (l <= lineStarts.length) {
            int end = l < lineStarts.length ? lineStarts[l] - 1 : text.length();
            offset = Math.min(lineStarts[l - 1] + c - 1, end);
        }
        return new SourcePos(file, l, c, null, offset);
    }
}
