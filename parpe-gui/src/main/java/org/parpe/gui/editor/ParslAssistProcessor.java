package org.parpe.gui.editor;

import org.parpe.core.text.Msg;
import org.parpe.gui.text.UiMsg;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.ITextViewer;
import org.eclipse.jface.text.contentassist.CompletionProposal;
import org.eclipse.jface.text.contentassist.ICompletionProposal;
import org.eclipse.jface.text.contentassist.IContentAssistProcessor;
import org.eclipse.jface.text.contentassist.IContextInformation;
import org.eclipse.jface.text.contentassist.IContextInformationValidator;
import org.parpe.core.lang.Vocabulary;
import org.parpe.core.lang.Vocabulary.Element;

/**
 * Content assist for PARSL: section and element names where an element may start, attribute
 * names for the element being typed, and names defined by the script (groups, states,
 * automata, behaviors, macros, parameters, {@code $controls}, radio words) inside attribute
 * values, depending on the attribute. The language's own words come from the core's
 * {@link Vocabulary}, the one the loader checks against.
 */
public final class ParslAssistProcessor implements IContentAssistProcessor {
    private final Function<String, NameIndex> index;

    /** {@code index} gives the names defined by a text (scanned now, or kept from a background scan). */
    public ParslAssistProcessor(Function<String, NameIndex> index) {
        this.index = index;
    }

    @Override
    public ICompletionProposal[] computeCompletionProposals(ITextViewer viewer, int offset) {
        IDocument doc = viewer.getDocument();
        String text = doc.get();
        XmlContext ctx = XmlContext.at(text, offset);
        Map<String, String> candidates = candidates(ctx, index.apply(text));
        String prefix = ctx.prefix();
        List<ICompletionProposal> out = new ArrayList<>();
        for (Map.Entry<String, String> e : candidates.entrySet()) {
            String word = e.getKey();
            if (!word.startsWith(prefix) || word.equals(prefix) && ctx.kind() != XmlContext.Kind.ATTRIBUTE_NAME) {
                continue;
            }
            String insert = ctx.kind() == XmlContext.Kind.ATTRIBUTE_NAME ? word + "=\"\"" : word;
            int caret = ctx.kind() == XmlContext.Kind.ATTRIBUTE_NAME ? insert.length() - 1 : insert.length();
            out.add(new CompletionProposal(insert, offset - prefix.length(), prefix.length(), caret, null,
                    word + "  \u2014 " + e.getValue(), null, null));
        }
        return out.toArray(new ICompletionProposal[0]);
    }

    /**
     * Every word that may stand at {@code ctx}, before filtering by the prefix typed, with what
     * it is: the words of {@link Vocabulary} that fit there and the script's names.
     */
    static Map<String, String> candidates(XmlContext ctx, NameIndex names) {
        return switch (ctx.kind()) {
            case ELEMENT_NAME -> elementNames(ctx, names);
            case ATTRIBUTE_NAME -> attributeNames(ctx, names);
            case ATTRIBUTE_VALUE -> attributeValues(ctx, names);
            case TEXT -> Map.of();
        };
    }

    /**
     * The words offered in a form field that stands for attribute {@code attribute} of an
     * element under {@code path} (outermost first, e.g. {@code program, automata}): the same
     * words as typing that attribute's value in the text, so the Diagram pane's fields and the
     * editor agree.
     */
    public static Map<String, String> valueWords(List<String> path, String attribute, NameIndex names) {
        return candidates(new XmlContext(path, XmlContext.Kind.ATTRIBUTE_VALUE, "", attribute, ""), names);
    }

    private static Map<String, String> elementNames(XmlContext ctx, NameIndex names) {
        Map<String, String> m = new LinkedHashMap<>();
        List<String> path = ctx.path();
        if (path.size() == 2 && path.get(1).equals("main")) {
            names.behaviorNames().forEach(s -> m.put(s, Msg.KIND_BEHAVIOR.text()));
        } else if (path.size() >= 3 && path.get(1).equals("behaviors")) {
            names.automata().forEach(s -> m.put(s, Msg.KIND_AUTOMATON.text()));
        }
        for (String word : Vocabulary.fixedChildren(path)) {
            // a section is explained as the quick reference explains it, in the IDE's language
            String holds = path.size() == 1 ? org.parpe.gui.help.HelpText.sectionHolds(word) : null;
            m.put(word, holds != null ? holds : describe(Vocabulary.elementAt(path, word)));
        }
        return m;
    }

    private static String describe(Element kind) {
        return switch (kind) {
            case PROGRAM -> UiMsg.ASSIST_ROOT.text();
            case ROBOT_PART -> UiMsg.ASSIST_ROBOT_PART.text();
            case SENSOR -> Msg.KIND_SENSOR.text();
            case ACTUATOR -> Msg.KIND_ACTUATOR.text();
            case CONDITIONAL -> UiMsg.ASSIST_CONDITIONAL.text();
            default -> UiMsg.ASSIST_SECTION.text();
        };
    }

    private static Map<String, String> attributeNames(XmlContext ctx, NameIndex names) {
        Map<String, String> m = new LinkedHashMap<>();
        String el = ctx.element();
        Element kind = Vocabulary.elementAt(ctx.path(), el);
        List<String> attrs = new ArrayList<>();
        if (kind == Element.TEXT_CONTROL) {
            // The attributes a control takes depend on its type, which may not be written yet.
            Vocabulary.CONTROL_TYPES.forEach(t -> attrs.addAll(Element.control(t).attributes()));
        } else if (kind != null) {
            attrs.addAll(kind.attributes());
        }
        if (kind == Element.ENTRY) {
            attrs.addAll(names.macros(el));
        }
        String of = UiMsg.ASSIST_ATTRIBUTE_OF.text(el);
        attrs.forEach(a -> m.put(a, of));
        return m;
    }

    private static Map<String, String> attributeValues(XmlContext ctx, NameIndex names) {
        Map<String, String> m = new LinkedHashMap<>();
        String attr = ctx.attribute();
        String parent = ctx.parent();
        switch (attr) {
            case "group" -> {
                names.groups().forEach(g -> m.put(g, Msg.KIND_GROUP.text()));
                if (ctx.path().size() >= 3 && ctx.path().get(1).equals("behaviors")) {
                    names.macros(ctx.path().get(2)).forEach(g -> m.put(g, Msg.KIND_MACRO.text()));
                }
            }
            case "states" -> names.states().forEach(s -> m.put(s, Msg.KIND_STATE.text()));
            case "elements" -> names.groups().forEach(g -> m.put(g, Msg.KIND_GROUP.text()));
            case "interp" -> Vocabulary.INTERP_WORDS.forEach(s -> m.put(s, UiMsg.ASSIST_MOTION_PROFILE.text()));
            case "latch", "unlatch" -> Vocabulary.PLATES.forEach(p -> m.put(p, UiMsg.ASSIST_PLATE.text()));
            case "keys" -> Vocabulary.keyNames().forEach(k -> m.put(k, UiMsg.ASSIST_KEY.text()));
            case "type" -> (parent.equals("controls") ? Vocabulary.CONTROL_TYPES : Vocabulary.PARAMETER_TYPES)
                    .forEach(s -> m.put(s, UiMsg.ASSIST_TYPE.text()));
            default -> {
                if (Vocabulary.EXPRESSION_ATTRIBUTES.contains(attr) || parent.equals("main")) {
                    expressionNames(names, m);
                    if (attr.equals("cycles") && ctx.path().size() == 1) {
                        m.put(Vocabulary.FOREVER, UiMsg.ASSIST_FOREVER.text());
                    }
                }
            }
        }
        return m;
    }

    private static void expressionNames(NameIndex names, Map<String, String> m) {
        names.controls().forEach(c -> m.put("$" + c, Msg.KIND_CONTROL.text()));
        names.parameters().forEach(p -> m.put(p, Msg.KIND_PARAMETER.text()));
        names.radioWords().forEach(w -> m.put(w, Msg.KIND_RADIO_WORD.text()));
        Vocabulary.LOGICAL_VARIABLES.forEach(v -> m.put("$" + v, UiMsg.ASSIST_LOGICAL_VARIABLE.text()));
        Vocabulary.functions().forEach(f -> m.put(f, UiMsg.ASSIST_FUNCTION.text()));
        Vocabulary.CONSTANTS.forEach(c -> m.put(c, UiMsg.ASSIST_CONSTANT.text()));
    }

    @Override
    public IContextInformation[] computeContextInformation(ITextViewer viewer, int offset) {
        return new IContextInformation[0];
    }
    @Override
    public char[] getCompletionProposalAutoActivationCharacters() {
        return new char[] {'<', '$', '"'};
    }

    @Override
    public char[] getContextInformationAutoActivationCharacters() {
        return new char[0];
    }

    @Override
    public String getErrorMessage() {
        return null;
    }

    @Override
    public IContextInformationValidator getContextInformationValidator() {
        return null;
    }
}
