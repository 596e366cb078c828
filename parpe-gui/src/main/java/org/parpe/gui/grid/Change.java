package org.parpe.gui.grid;

/**
 * A replacement in the document: {@code length} characters at {@code offset} become {@code text}.
 *
 * @param offset where the replaced range starts
 * @param length how many characters it has
 * @param text   what replaces them
 */
public record Change(int offset, int length, String text) {

    /** The smallest change that turns {@code before} (found at {@code offset}) into {@code after}. */
    static Change between(int offset, String before, String after) {
        int head = 0;
        int max = Math.min(before.length(), after.length());
        while (head < max && before.charAt(head) == after.charAt(head)) {
            head++;
        }
        int tail = 0;
        while (tail < max - head && before.charAt(before.length() - 1 - tail) == after.charAt(after.length() - 1 - tail)) {
            tail++;
        }
        return new Change(offset + head, before.length() - head - tail, after.substring(head, after.length() - tail));
    }

    /** Whether it changes nothing. */
    public boolean empty() {
        return length == 0 && text.isEmpty();
    }

    /** {@code doc} with this change made. */
    public String applyTo(String doc) {
        return doc.substring(0, offset) + text + doc.substring(offset + length);
    }
}
