package org.parpe.gui.editor;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.parpe.core.lang.Vocabulary;
import org.parpe.core.model.Program;

/**
 * The names a script defines (groups, parameters, controls, radio words, states, automata,
 * behaviors and their macros): taken from the loader's result ({@link #of(Program)}), which
 * also knows the names of included files, or read by a forgiving scan of the text
 * ({@link #of(String)}) so that completion keeps working while the script has errors.
 */
public final class NameIndex {
    private static final Pattern TAG = Pattern.compile("<(/?)([A-Za-z_][\\w.-]*)((?:[^>\"']|\"[^\"]*\"|'[^']*')*?)(/?)>|<!--.*?-->",
            Pattern.DOTALL);
    private static final Pattern ATTR = Pattern.compile("([A-Za-z_][\\w.-]*)\\s*=\\s*\"([^\"]*)\"");

    final Set<String> groups = new LinkedHashSet<>();
    final Set<String> parameters = new LinkedHashSet<>();
    final Set<String> controls = new LinkedHashSet<>();
    final Set<String> radioWords = new LinkedHashSet<>();
    final Set<String> states = new LinkedHashSet<>();
    final Set<String> automata = new LinkedHashSet<>();
    final Map<String, List<String>> behaviors = new LinkedHashMap<>();

    /** Scans {@code text}. */
    public static NameIndex of(String text) {
        NameIndex idx = new NameIndex();
        List<String> path = new ArrayList<>();
        Matcher m = TAG.matcher(text);
        while (m.find()) {
            if (m.group(2) == null) {
                continue;
            }
            String name = m.group(2);
            if (!m.group(1).isEmpty()) {
                int k = path.lastIndexOf(name);
                if (k >= 0) {
                    path.subList(k, path.size()).clear();
                }
                continue;
            }
            idx.define(path, name, attributes(m.group(3)));
            if (m.group(4).isEmpty()) {
                path.add(name);
            }
        }
        idx.groups.add(Vocabulary.ALL);
        return idx;
    }

    /** The names of a loaded program, its includes' names among them. */
    public static NameIndex of(Program p) {
        NameIndex idx = new NameIndex();
        p.robot().groups().forEach(g -> idx.groups.add(g.name()));
        p.parameters().forEach(x -> idx.parameters.add(x.name()));
        p.controls().forEach(c -> {
            idx.controls.add(c.name());
            idx.radioWords.addAll(c.words());
        });
        p.states().forEach(x -> idx.states.add(x.name()));
        p.automata().forEach(x -> idx.automata.add(x.name()));
        p.behaviors().forEach(b -> idx.behaviors.put(b.name(), b.macros()));
        return idx;
    }

    /**
     * The names of this index and of {@code other} (which may be {@code null}); for a behavior
     * both know, this index's macros.
     */
    public NameIndex with(NameIndex other) {
        if (other == null) {
            return this;
        }
        NameIndex idx = new NameIndex();
        for (NameIndex n : List.of(this, other)) {
            idx.groups.addAll(n.groups);
            idx.parameters.addAll(n.parameters);
            idx.controls.addAll(n.controls);
            idx.radioWords.addAll(n.radioWords);
            idx.states.addAll(n.states);
            idx.automata.addAll(n.automata);
            n.behaviors.forEach(idx.behaviors::putIfAbsent);
        }
        return idx;
    }

    private static Map<String, String> attributes(String text) {
        Map<String, String> out = new LinkedHashMap<>();
        Matcher m = ATTR.matcher(text);
        while (m.find()) {
            out.put(m.group(1), m.group(2));
        }
        return out;
    }

    private void define(List<String> path, String name, Map<String, String> attrs) {
        Vocabulary.Element kind = Vocabulary.elementAt(path, name);
        if (kind == null) {
            return;
        }
        switch (kind) {
            case GROUP -> groups.add(name);
            case PARAMETER -> parameters.add(name);
            case TEXT_CONTROL -> {
                controls.add(name);
                radioWords.addAll(list(attrs.getOrDefault("values", "")));
            }
            case STATE -> states.add(name);
            case AUTOMATON -> automata.add(name);
            case BEHAVIOR -> behaviors.put(name, list(attrs.getOrDefault("macros", "")));
            default -> {
            }
        }
    }

    private static List<String> list(String text) {
        List<String> out = new ArrayList<>();
        for (String s : text.split(",")) {
            if (!s.isBlank()) {
                out.add(s.trim());
            }
        }
        return out;
    }

    /** The macros of a behavior, empty if unknown. */
    public List<String> macros(String behavior) {
        return behaviors.getOrDefault(behavior, List.of());
    }

    public Set<String> groups() {
        return groups;
    }

    public Set<String> states() {
        return states;
    }

    public Set<String> automata() {
        return automata;
    }

    public Set<String> behaviorNames() {
        return behaviors.keySet();
    }

    public Set<String> parameters() {
        return parameters;
    }

    public Set<String> controls() {
        return controls;
    }

    public Set<String> radioWords() {
        return radioWords;
    }
}
