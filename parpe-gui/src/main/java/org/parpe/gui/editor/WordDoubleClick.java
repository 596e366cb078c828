package org.parpe.gui.editor;

import java.text.BreakIterator;
import org.eclipse.jface.text.BadLocationException;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.IRegion;
import org.eclipse.jface.text.ITextDoubleClickStrategy;
import org.eclipse.jface.text.ITextViewer;

/**
 * A double-click selects the word under the pointer, as the JDK's word {@link BreakIterator}
 * finds it on the line ({@code 30.5}, {@code simpleWave}, {@code speed_x}; not the quotes or the
 * {@code =} around them). jface.text's default strategy does the same with ICU's BreakIterator,
 * which the IDE does not ship: it linked ICU on the first double-click and ended the IDE with a
 * {@code NoClassDefFoundError} (issue 31).
 */
final class WordDoubleClick implements ITextDoubleClickStrategy {
    private final BreakIterator words = BreakIterator.getWordInstance(java.util.Locale.ROOT);

    @Override
    public void doubleClicked(ITextViewer viewer) {
        int offset = viewer.getSelectedRange().x;
        int[] word = word(viewer.getDocument(), offset);
        if (word != null) {
            viewer.setSelectedRange(word[0], word[1] - word[0]);
        }
    }

    /** The word around {@code offset} as [start, end), or null (an empty line, the end of a line). */
    int[] word(IDocument document, int offset) {
        try {
            IRegion line = document.getLineInformationOfOffset(offset);
            int at = offset - line.getOffset();
            if (at >= line.getLength()) {
                return null;
            }
            words.setText(document.get(line.getOffset(), line.getLength()));
            int start = at == 0 ? 0 : words.preceding(at);
            int end = words.following(at);
            if (at > 0 && words.isBoundary(at)) {
                // Between two words (a click on the right half of a character): the longer one, as jface.text does.
                if (end - at > at - start) {
                    start = at;
                } else {
                    end = at;
                }
            }
            return new int[] {line.getOffset() + start, line.getOffset() + end};
        } catch (BadLocationException e) {
            return null;
        }
    }
}
