package org.parpe.core.edit;

/**
 * The one replacement of PARPE: {@code length} characters of a text at {@code offset} become
 * {@code text}. Every view that changes a script or a robot file (diagrams, grid, Pose panel,
 * sweep, recorder) hands the editor these, so one edit is one Undo step and nothing outside the
 * replaced range changes.
 *
 * @param offset the first replaced character, in the original text
 * @param length how many characters are replaced (0 inserts)
 * @param text   the new characters
 */
public record Replacement(int offset, int length, String text) {

    /**
     * The smallest replacement that turns {@code before} (found at {@code offset}) into
     * {@code after}: their common head and tail are left alone, so the caret and the editor's
     * markers outside the changed characters stay where they are.
     */
    public static Replacement between(int offset, String before, String after) {
        int head = 0;
        int max = Math.min(before.length(), after.length());
        while (head < max && before.charAt(head) == after.charAt(head)) {
            head++;
        }
        int tail = 0;
        while (tail < max - head && before.charAt(before.length() - 1 - tail) == after.charAt(after.length() - 1 - tail)) {
            tail++;
        }
        return new Replacement(offset + head, before.length() - head - tail, after.substring(head, after.length() - tail));
    }

    /** Just after the replaced range. */
    public int end() {
        return offset + length;
    }

    /** Whether it changes nothing. */
    public boolean empty() {
        return length == 0 && text.isEmpty();
    }

    /** {@code doc} with this replacement made. */
    public String applyTo(String doc) {
        return doc.substring(0, offset) + text + doc.substring(end());
    }
}
