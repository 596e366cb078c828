package org.parpe.gui.grid;

/**
 * One entry of a gait table as written: its decoded text and where it sits in the document.
 *
 * @param text      the entry's text, trimmed and with XML entities decoded
 * @param start     document offset of the entry's first character (of the slot, when empty)
 * @param end       document offset after its last character
 * @param slotStart document offset where the space before the entry starts (after the separator)
 * @param slotEnd   document offset where the space after it ends (at the next separator)
 */
public record Cell(String text, int start, int end, int slotStart, int slotEnd) {

    /** Whether {@code offset} falls on this entry (its text, or its slot when it has none). */
    public boolean covers(int offset) {
        return start == end ? offset >= slotStart && offset <= slotEnd : offset >= start && offset <= end;
    }
}
