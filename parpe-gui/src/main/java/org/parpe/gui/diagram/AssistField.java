package org.parpe.gui.diagram;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.eclipse.jface.bindings.keys.KeyStroke;
import org.eclipse.jface.fieldassist.ContentProposal;
import org.eclipse.jface.fieldassist.ContentProposalAdapter;
import org.eclipse.jface.fieldassist.IContentProposal;
import org.eclipse.jface.fieldassist.TextContentAdapter;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Text;
import org.parpe.gui.editor.NameIndex;
import org.parpe.gui.editor.ParslAssistProcessor;

/**
 * Content assist in a field of the Diagram pane (Ctrl+Space, or typing {@code $}): the words
 * the editor's {@link ParslAssistProcessor} offers in the text for the attribute the field
 * stands for (a state's duration and exit are items of {@code times}, its angles the
 * {@code angles} of its definition, …), filtered by the word before the caret.
 */
final class AssistField {
    private AssistField() {
    }

    /** Which attribute, under which elements, field {@code name} stands for. */
    private static Map<String, String> words(String name, NameIndex names) {
        List<String> automata = List.of("program", "automata");
        return switch (name) {
            case "duration", "exit" -> ParslAssistProcessor.valueWords(automata, "times", names);
            case "add state" -> ParslAssistProcessor.valueWords(automata, "states", names);
            case "angles" -> ParslAssistProcessor.valueWords(List.of("program", "states"), "angles", names);
            case "phase", "offset" -> ParslAssistProcessor.valueWords(List.of("program", "behaviors", ""), name, names);
            case "group" -> ParslAssistProcessor.valueWords(List.of("program", "behaviors", ""), "group", names);
            case "time" -> ParslAssistProcessor.valueWords(List.of("program", "main"), "time", names);
            case "automaton" -> {
                Map<String, String> m = new LinkedHashMap<>();
                names.automata().forEach(a -> m.put(a, "automaton"));
                yield m;
            }
            default -> Map.of();
        };
    }

    /** The proposals for {@code contents} with the caret at {@code position}. */
    static List<IContentProposal> proposals(Map<String, String> words, String contents, int position) {
        int from = position;
        while (from > 0 && (Character.isLetterOrDigit(contents.charAt(from - 1)) || "_$.".indexOf(contents.charAt(from - 1)) >= 0)) {
            from--;
        }
        String prefix = contents.substring(from, position);
        List<IContentProposal> out = new ArrayList<>();
        words.forEach((word, what) -> {
            if (word.startsWith(prefix) && !word.equals(prefix)) {
                out.add(new ContentProposal(word.substring(prefix.length()), word + "  \u2014 " + what, what));
            }
        });
        return out;
    }

    /** Gives {@code field} (standing for {@code name}) content assist over {@code names}; nothing when no words fit. */
    static void attach(Text field, String name, NameIndex names) {
        Map<String, String> words = words(name, names);
        if (words.isEmpty()) {
            return;
        }
        ContentProposalAdapter adapter = new ContentProposalAdapter(field, new TextContentAdapter(),
                (contents, position) -> proposals(words, contents, position).toArray(IContentProposal[]::new),
                KeyStroke.getInstance(SWT.CTRL, ' '), new char[] {'$'});
        adapter.setProposalAcceptanceStyle(ContentProposalAdapter.PROPOSAL_INSERT);
        field.setData("assist", adapter);
    }
}
