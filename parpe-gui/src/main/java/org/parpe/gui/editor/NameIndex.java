package org.parpe.gui.editor;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The names a script defines (groups, parameters, controls, radio words, states, automata,
 * behaviors and their macros), read by a forgiving scan of the text so that completion keeps
 * working while the script has errors.
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
        idx.groups.add("all");
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
        if (path.size() != 2 && !(path.size() == 3 && path.get(1).equals("robot"))) {
            return;
        }
        String section = path.get(path.size() - 1);
        switch (section) {
            case "structure" -> groups.add(name);
            case "parameters" -> parameters.add(name);
            case "controls" -> {
                controls.add(name);
                for (String w : attrs.getOrDefault("values", "").split(",")) {
                    if (!w.isBlank()) {
                        radioWords.add(w.trim());
                    }
                }
            }
            case "states" -> states.add(name);
            case "automata" -> automata.add(name);
            case "behaviors" -> behaviors.put(name, list(attrs.getOrDefault("macros", "")));
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
