package org.parpe.core.load;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.Severity;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.Names;
import org.parpe.core.lang.Vocabulary;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;
import org.parpe.core.lang.Vocabulary.Element;
import org.parpe.core.model.Control;
import org.parpe.core.model.Control.ControlType;
import org.parpe.core.lang.Numbers;
import org.parpe.core.model.Parameter;
import org.parpe.core.xml.XElement;
import org.parpe.core.xml.XText;

/** Resolves {@code <parameters>} (PARSL.md §3) and {@code <controls>} (§4). */
final class Declarations {
    /**
     * The parameters of a program.
     *
     * @param list   the parameters in document order
     * @param values the value of each parameter by name: its default, or the value given from outside
     * @param errors problems with the values given from outside (see {@link LoadResult#parameterErrors})
     */
    record Parameters(List<Parameter> list, Map<String, Double> values, List<Diagnostic> errors) {
        Parameters {
            list = List.copyOf(list);
            values = Collections.unmodifiableMap(new LinkedHashMap<>(values));
            errors = List.copyOf(errors);
        }
    }

    /**
     * The controls of a program.
     *
     * @param list       the controls in document order
     * @param index      each control's index in {@code list} by name
     * @param radioWords the symbol code of every radio word
     */
    record Controls(List<Control> list, Map<String, Integer> index, Map<String, Integer> radioWords) {
        Controls {
            list = List.copyOf(list);
            index = Collections.unmodifiableMap(new LinkedHashMap<>(index));
            radioWords = Collections.unmodifiableMap(new LinkedHashMap<>(radioWords));
        }
    }

    private final List<Parameter> parameters = new ArrayList<>();
    private final Map<String, Double> values = new LinkedHashMap<>();
    private final List<Diagnostic> parameterErrors = new ArrayList<>();
    private final List<Control> controls = new ArrayList<>();
    private final Map<String, Integer> controlIndex = new LinkedHashMap<>();
    private final Map<String, Integer> radioWords = new LinkedHashMap<>();
    private final DiagnosticSink d;
    private final NameRegistry names;

    private Declarations(DiagnosticSink d, NameRegistry names) {
        this.d = d;
        this.names = names;
    }

    /** Resolves the {@code <parameters>} sections, with the values given from outside ({@code overrides}). */
    static Parameters parameters(List<Includes.Section> sections, Map<String, Double> overrides, DiagnosticSink d,
                                 NameRegistry names) {
        Declarations decl = new Declarations(d, names);
        decl.readParameters(sections, overrides);
        return new Parameters(decl.parameters, decl.values, decl.parameterErrors);
    }

    /** Resolves the {@code <controls>} sections. */
    static Controls controls(List<Includes.Section> sections, DiagnosticSink d, NameRegistry names) {
        Declarations decl = new Declarations(d, names);
        decl.readControls(sections);
        return new Controls(decl.controls, decl.controlIndex, decl.radioWords);
    }

    private void readParameters(List<Includes.Section> sections, Map<String, Double> overrides) {
        for (Includes.Section s : sections) {
            Attrs.allow(s.element(), d, Element.SECTION.attributes());
            Attrs.noText(s.element(), d);
            int i = 0;
            for (XElement e : s.element().children()) {
                parameter(e, s, i++);
            }
        }
        for (Map.Entry<String, Double> o : overrides.entrySet()) {
            Parameter p = parameters.stream().filter(q -> q.name().equals(o.getKey())).findFirst().orElse(null);
            if (p == null) {
                parameterErrors.add(new Diagnostic(Severity.ERROR, SourcePos.origin("--param " + o.getKey()),
                        Msg.UNKNOWN_PARAMETER, o.getKey(), Names.suggest(o.getKey(), values.keySet()),
                        values.isEmpty() ? Message.of(Msg.NO_PARAMETERS) : Message.EMPTY));
                continue;
            }
            Message problem = p.problem(o.getValue());
            if (problem != null) {
                // Located at the definition, whose min and max the value breaks.
                parameterErrors.add(new Diagnostic(Severity.ERROR, p.pos(), problem));
            } else {
                values.put(p.name(), o.getValue());
            }
        }
    }

    private void parameter(XElement e, Includes.Section s, int index) {
        Attrs.allow(e, d, Element.PARAMETER.attributes());
        Attrs.noText(e, d);
        Attrs.noChildren(e, d);
        String name = e.name();
        boolean okName = Attrs.validName(name, "parameter", e.pos(), d);
        XText type = Attrs.optional(e, "type");
        if (type != null && !type.value().trim().equals("text")) {
            d.error(type.pos(), Msg.PARAMETER_TYPE, type.value());
        }
        Message what = Msg.named("parameter", name);
        Double value = number(e, "value", true, what);
        Double min = number(e, "min", false, what);
        Double max = number(e, "max", false, what);
        if (value == null || !okName) {
            return;
        }
        // A value outside its bounds is reported here; the parameter is still defined so that its
        // uses are not reported again as unknown names (one mistake, one message).
        bounds(e, value, min, max, what);
        XText label = Attrs.optional(e, "label");
        Parameter p = new Parameter(name, value, min, max, label == null ? "" : label.value(), e.pos());
        if (values.containsKey(name)) {
            names.define(name, "parameter", order(s, index), s.reportAt(e.pos()), e.pos(), "");
            return;
        }
        parameters.add(p);
        values.put(name, value);
        names.define(name, "parameter", order(s, index), s.reportAt(e.pos()), e.pos(), "");
    }

    static long order(Includes.Section s, int index) {
        return order(s.order(), index, 0);
    }

    /** The document order of item {@code sub} of entry {@code index} of the section at {@code section}. */
    static long order(int section, int index, int sub) {
        return section * 1_000_000_000L + index * 1000L + sub;
    }

    /** Reads a plain-number attribute; reports a malformed or missing one. */
    private Double number(XElement e, String attr, boolean required, Message what) {
        XText t = required ? Attrs.require(e, attr, d) : Attrs.optional(e, attr);
        if (t == null) {
            return null;
        }
        Double v = Numbers.parsePlain(t.value());
        if (v == null) {
            d.error(t.pos(), Msg.NOT_A_PLAIN_NUMBER, attr, what, t.value());
        }
        return v;
    }

    private boolean bounds(XElement e, Double value, Double min, Double max, Message what) {
        if (min != null && max != null && min > max) {
            d.error(e.attr("min").pos(), Msg.MIN_ABOVE_MAX, what, Numbers.format(min), Numbers.format(max));
            return false;
        }
        if (value != null && (min != null && value < min || max != null && value > max)) {
            d.error(e.attr("value").pos(), Msg.VALUE_OUT_OF_BOUNDS, what, min == null ? "-inf" : Numbers.format(min),
                    max == null ? "inf" : Numbers.format(max), Numbers.format(value));
            return false;
        }
        return true;
    }

    private void readControls(List<Includes.Section> sections) {
        for (Includes.Section s : sections) {
            Attrs.allow(s.element(), d, Element.SECTION.attributes());
            Attrs.noText(s.element(), d);
            int i = 0;
            for (XElement e : s.element().children()) {
                control(e, s, i++);
            }
        }
    }

    private void control(XElement e, Includes.Section s, int index) {
        Attrs.noText(e, d);
        Attrs.noChildren(e, d);
        String name = e.name();
        boolean ok = Attrs.validName(name, "control", e.pos(), d);
        if (Vocabulary.LOGICAL_VARIABLES.contains(name)) {
            d.error(e.pos(), Msg.CONTROL_NAME_TAKEN, name);
            ok = false;
        }
        XText typeText = Attrs.optional(e, "type");
        String type = typeText == null ? "text" : typeText.value().trim();
        Control c;
        switch (type) {
            case "slider": c = slider(e, name); break;
            case "text": c = text(e, name); break;
            case "radio": c = radio(e, name, s, index); break;
            default:
                d.error(typeText.pos(), Msg.BAD_CONTROL_TYPE, type);
                return;
        }
        names.define(name, "control", order(s, index), s.reportAt(e.pos()), e.pos(), "");
        if (c != null && ok && !controlIndex.containsKey(name)) {
            controlIndex.put(name, controls.size());
            controls.add(c);
        }
    }

    private String label(XElement e) {
        XText l = Attrs.optional(e, "label");
        return l == null ? "" : l.value();
    }

    private Control slider(XElement e, String name) {
        Attrs.allow(e, d, Element.SLIDER.attributes());
        Message what = Msg.named("slider", name);
        Double min = number(e, "min", true, what);
        Double max = number(e, "max", true, what);
        Double value = number(e, "value", true, what);
        Double step = number(e, "step", false, what);
        if (step != null && step <= 0) {
            d.error(e.attr("step").pos(), Msg.STEP_NOT_POSITIVE, what, Numbers.format(step));
            return null;
        }
        List<String> keys = keys(e, 2, Message.of(Msg.SLIDER_KEYS));
        if (!bounds(e, value, min, max, what) || min == null || max == null || value == null || keys == null) {
            return null;
        }
        return new Control(name, ControlType.SLIDER, value, min, max, step, label(e), List.of(), keys, e.pos());
    }

    private Control text(XElement e, String name) {
        Attrs.allow(e, d, Element.TEXT_CONTROL.attributes());
        Double value = number(e, "value", true, Msg.named("control", name));
        return value == null ? null
                : new Control(name, ControlType.TEXT, value, null, null, null, label(e), List.of(), List.of(), e.pos());
    }

    private Control radio(XElement e, String name, Includes.Section s, int index) {
        Attrs.allow(e, d, Element.RADIO.attributes());
        XText values = Attrs.require(e, "values", d);
        if (values == null) {
            return null;
        }
        List<String> words = new ArrayList<>();
        int k = 0;
        for (XText w : ListItem.split(values, ',')) {
            String word = w.value();
            if (word.isEmpty()) {
                d.error(w.pos(), Msg.EMPTY_RADIO_ITEM, name);
                return null;
            }
            if (!Attrs.validName(word, "radio word", w.pos(), d)) {
                return null;
            }
            if (words.contains(word)) {
                d.error(w.pos(), Msg.RADIO_WORD_TWICE, name, word);
                return null;
            }
            words.add(word);
            names.define(word, "radio word", order(s.order(), index, ++k), s.reportAt(w.pos()), w.pos(), name);
        }
        XText initial = Attrs.optional(e, "value");
        String first = words.get(0);
        if (initial != null && !words.contains(initial.value().trim())) {
            d.error(initial.pos(), Msg.RADIO_VALUE, name, String.join(", ", words), initial.value());
            return null;
        }
        List<String> keys = keys(e, words.size(), Message.of(Msg.RADIO_KEYS, words.size()));
        if (keys == null) {
            return null;
        }
        for (String w : words) {
            radioWords.putIfAbsent(w, radioWords.size() + 1);
        }
        String start = initial == null ? first : initial.value().trim();
        return new Control(name, ControlType.RADIO, radioWords.get(start), null, null, null, label(e), words, keys, e.pos());
    }

    private List<String> keys(XElement e, int count, Message rule) {
        XText t = Attrs.optional(e, "keys");
        if (t == null) {
            return List.of();
        }
        List<String> keys = new ArrayList<>();
        for (XText k : ListItem.split(t, ',')) {
            if (!Vocabulary.keyNames().contains(k.value())) {
                d.error(k.pos(), Msg.UNKNOWN_KEY, k.value());
                return null;
            }
            keys.add(k.value());
        }
        if (keys.size() != count) {
            d.error(t.pos(), Msg.KEY_COUNT, rule, keys.size());
            return null;
        }
        return keys;
    }

}
