package org.parpe.gui.editor;

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

/**
 * Content assist for PARSL: section and element names where an element may start, attribute
 * names for the element being typed, and names defined by the script (groups, states,
 * automata, behaviors, macros, parameters, {@code $controls}, radio words) inside attribute
 * values, depending on the attribute.
 */
public final class ParslAssistProcessor implements IContentAssistProcessor {
    private static final List<String> SECTIONS = List.of("robot", "parameters", "controls", "main", "behaviors",
            "automata", "states", "include");
    private static final List<String> VARIABLES = List.of("$time", "$btime", "$index", "$count", "$id", "$phase", "$cycle");
    private static final List<String> FUNCTIONS = List.of("sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh",
            "cosh", "tanh", "log", "ln", "exp", "sqrt", "abs", "mod", "rand", "sum", "if", "round", "floor", "ceil", "min",
            "max", "rad", "deg");
    private static final List<String> EXPRESSION_ATTRS = List.of("angles", "phase", "offset", "period", "start",
            "cycles", "times", "cond", "exit", "time");

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
        NameIndex names = index.apply(text);
        Map<String, String> candidates = switch (ctx.kind()) {
            case ELEMENT_NAME -> elementNames(ctx, names);
            case ATTRIBUTE_NAME -> attributeNames(ctx, names);
            case ATTRIBUTE_VALUE -> attributeValues(ctx, names);
            case TEXT -> Map.of();
        };
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

    private static Map<String, String> elementNames(XmlContext ctx, NameIndex names) {
        Map<String, String> m = new LinkedHashMap<>();
        int depth = ctx.path().size();
        if (depth == 0) {
            m.put("program", "root element");
        } else if (depth == 1) {
            SECTIONS.forEach(s -> m.put(s, "section"));
        } else if (ctx.parent().equals("robot")) {
            List.of("structure", "sensors", "actuators").forEach(s -> m.put(s, "robot part"));
        } else if (ctx.parent().equals("sensors")) {
            List.of("angle", "accel", "touch").forEach(s -> m.put(s, "sensor"));
        } else if (ctx.parent().equals("main")) {
            names.behaviorNames().forEach(s -> m.put(s, "behavior"));
        } else if (depth >= 3 && ctx.path().get(1).equals("behaviors")) {
            names.automata().forEach(s -> m.put(s, "automaton"));
            m.put("if", "conditional block");
        }
        return m;
    }

    private static Map<String, String> attributeNames(XmlContext ctx, NameIndex names) {
        Map<String, String> m = new LinkedHashMap<>();
        List<String> path = ctx.path();
        String parent = ctx.parent();
        String el = ctx.element();
        List<String> attrs;
        if (path.size() == 1 && (el.equals("robot") || el.equals("include"))) {
            attrs = List.of("file");
        } else if (path.size() == 1 && el.equals("main")) {
            attrs = List.of("cycles");
        } else if (parent.equals("structure") || parent.equals("sensors") || parent.equals("actuators")) {
            attrs = List.of("elements");
        } else if (parent.equals("parameters")) {
            attrs = List.of("type", "value", "min", "max", "label");
        } else if (parent.equals("controls")) {
            attrs = List.of("type", "value", "min", "max", "step", "label", "values", "keys");
        } else if (parent.equals("states")) {
            attrs = List.of("angles", "interp");
        } else if (parent.equals("automata")) {
            attrs = List.of("states", "times");
        } else if (parent.equals("behaviors")) {
            attrs = List.of("macros");
        } else if (path.size() >= 3 && path.get(1).equals("behaviors")) {
            attrs = el.equals("if") ? List.of("cond") : List.of("group", "phase", "offset", "period", "start", "cycles");
        } else if (parent.equals("main")) {
            List<String> a = new ArrayList<>(List.of("time", "exit"));
            a.addAll(names.macros(el));
            attrs = a;
        } else {
            attrs = List.of();
        }
        attrs.forEach(a -> m.put(a, "attribute of <" + el + ">"));
        return m;
    }

    private static Map<String, String> attributeValues(XmlContext ctx, NameIndex names) {
        Map<String, String> m = new LinkedHashMap<>();
        String attr = ctx.attribute();
        String parent = ctx.parent();
        switch (attr) {
            case "group" -> {
                names.groups().forEach(g -> m.put(g, "group"));
                if (ctx.path().size() >= 3 && ctx.path().get(1).equals("behaviors")) {
                    names.macros(ctx.path().get(2)).forEach(g -> m.put(g, "macro"));
                }
            }
            case "states" -> names.states().forEach(s -> m.put(s, "state"));
            case "elements" -> names.groups().forEach(g -> m.put(g, "group"));
            case "interp" -> List.of("linear", "step", "smooth").forEach(s -> m.put(s, "motion profile"));
            case "type" -> (parent.equals("controls") ? List.of("slider", "radio", "text") : List.of("text"))
                    .forEach(s -> m.put(s, "type"));
            default -> {
                if (EXPRESSION_ATTRS.contains(attr) || parent.equals("main")) {
                    expressionNames(names, m);
                    if (attr.equals("cycles") && ctx.path().size() == 1) {
                        m.put("forever", "repeat until stopped");
                    }
                }
            }
        }
        return m;
    }

    private static void expressionNames(NameIndex names, Map<String, String> m) {
        names.controls().forEach(c -> m.put("$" + c, "control"));
        names.parameters().forEach(p -> m.put(p, "parameter"));
        names.radioWords().forEach(w -> m.put(w, "radio word"));
        VARIABLES.forEach(v -> m.put(v, "logical variable"));
        FUNCTIONS.forEach(f -> m.put(f, "function"));
        m.put("pi", "constant");
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
