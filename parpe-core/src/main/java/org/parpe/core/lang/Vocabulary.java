package org.parpe.core.lang;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The vocabulary of PARSL (PARSL.md §1–§9): which elements stand where, which attributes each
 * takes, the functions with their arities, the reserved words and the logical variables. The
 * loader reads it for its checks, the expression compiler for its names, and the editor's
 * completion offers exactly these words, so that the three cannot drift apart.
 */
public final class Vocabulary {
    /** The root element of a program. */
    public static final String ROOT = "program";
    /** The element that pulls another file's sections in (PARSL.md §9). */
    public static final String INCLUDE = "include";
    /** The sections of a program, in the order the documentation lists them. */
    public static final List<String> SECTIONS = List.of("robot", "parameters", "controls", "main", "behaviors",
            "automata", "states");
    /** The parts of {@code <robot>}. */
    public static final List<String> ROBOT_PARTS = List.of("structure", "sensors", "actuators");
    /** The sensor types a {@code <sensors>} may declare (PARSL.md §2). */
    public static final List<String> SENSOR_TYPES = List.of("angle", "accel", "touch", "dock");
    /** The actuator types an {@code <actuators>} may declare (PARSL.md §2, §14). */
    public static final List<String> ACTUATOR_TYPES = List.of("latch");
    /** The connection plates of a module, as {@code latch}/{@code unlatch} and {@code dock} number them (PARSL.md §14). */
    public static final List<String> PLATES = List.of("0", "1");
    /** The element of a conditional block in a behavior (PARSL.md §7). */
    public static final String IF = "if";
    /** The words of {@code interp} (PARSL.md §5). */
    public static final List<String> INTERP_WORDS = List.of("linear", "step", "smooth");
    /** The words of a control's {@code type}. */
    public static final List<String> CONTROL_TYPES = List.of("slider", "text", "radio");
    /** The words of a parameter's {@code type}. */
    public static final List<String> PARAMETER_TYPES = List.of("text");
    /** The word of {@code <main cycles>} that repeats until stopped. */
    public static final String FOREVER = "forever";
    /** Written before a group's name, it mirrors the group: every target angle is negated (PARSL.md §7). */
    public static final String MIRROR = "!";
    /** The group every robot has: all its modules. */
    public static final String ALL = "all";
    /** The logical variables, written with {@code $} (PARSL.md §8); their order is their index. */
    public static final List<String> LOGICAL_VARIABLES = List.of("time", "btime", "index", "count", "id", "phase",
            "cycle");
    /** The named constants of expressions. */
    public static final List<String> CONSTANTS = List.of("pi", "e", "true", "false");
    /** The arity of {@code sum}: one argument or more. */
    public static final int ONE_OR_MORE = -2;
    /** The arity {@link #arity} gives an unknown name. */
    public static final int UNKNOWN = -1;
    /** The expression attributes: their values are compiled as expressions (macros of entries too). */
    public static final List<String> EXPRESSION_ATTRIBUTES = List.of("angles", "phase", "offset", "period", "start",
            "cycles", "times", "cond", "exit", "time");

    private static final Map<String, Integer> FUNCTIONS = functionTable();
    private static final Set<String> KEYS = keys();

    private Vocabulary() {
    }

    /** The kinds of element, each with the attributes the loader accepts on it. */
    public enum Element {
        /** {@code <program>}. */
        PROGRAM,
        /** A section without attributes ({@code <parameters>}, {@code <states>}, …), and a robot file's root. */
        SECTION,
        /** {@code <robot>} in a program. */
        ROBOT("file"),
        /** {@code <include>}. */
        INCLUDE("file"),
        /** {@code <main>}. */
        MAIN("cycles"),
        /** {@code <structure>}, {@code <sensors>}, {@code <actuators>}. */
        ROBOT_PART,
        /** A group of {@code <structure>}. */
        GROUP("elements"),
        /** A sensor of {@code <sensors>}. */
        SENSOR("elements"),
        /** An actuator of {@code <actuators>}. */
        ACTUATOR("elements"),
        /** A parameter. */
        PARAMETER("type", "value", "min", "max", "label"),
        /** A control of type {@code slider}. */
        SLIDER("type", "min", "max", "value", "step", "label", "keys"),
        /** A control of type {@code text} (the default). */
        TEXT_CONTROL("type", "value", "label"),
        /** A control of type {@code radio}. */
        RADIO("type", "values", "value", "label", "keys"),
        /** A state. */
        STATE("angles", "interp", "latch", "unlatch"),
        /** An automaton. */
        AUTOMATON("states", "times"),
        /** A behavior. */
        BEHAVIOR("macros"),
        /** An automaton instance in a behavior; {@code group} first, then the expressions. */
        INSTANCE("group", "phase", "offset", "period", "start", "cycles"),
        /** {@code <if>} in a behavior. */
        CONDITIONAL("cond"),
        /** An entry of {@code <main>}; it also takes the behavior's macros. */
        ENTRY("time", "exit");

        private final List<String> attributes;

        Element(String... attributes) {
            this.attributes = List.of(attributes);
        }

        /** The attributes this element takes, in the order the documentation lists them. */
        public List<String> attributes() {
            return attributes;
        }

        /** The control element of a {@code type} word, or {@code null} for an unknown word. */
        public static Element control(String type) {
            switch (type) {
                case "slider": return SLIDER;
                case "text": return TEXT_CONTROL;
                case "radio": return RADIO;
                default: return null;
            }
        }
    }

    /**
     * The kind of an element named {@code name} inside the open elements {@code path}
     * (outermost first), or {@code null} where PARSL has no element of that name. A control is
     * {@link Element#TEXT_CONTROL}: its kind depends on its {@code type} (see {@link Element#control}).
     */
    public static Element elementAt(List<String> path, String name) {
        if (path.isEmpty()) {
            return name.equals(ROOT) ? Element.PROGRAM : null;
        }
        if (path.size() == 1) {
            return name.equals(INCLUDE) ? Element.INCLUDE : section(name);
        }
        String section = path.get(1);
        String parent = path.get(path.size() - 1);
        if (section.equals("robot")) {
            if (path.size() == 2) {
                return ROBOT_PARTS.contains(name) ? Element.ROBOT_PART : null;
            }
            if (path.size() == 3 && parent.equals("structure")) {
                return Element.GROUP;
            }
            if (path.size() == 3 && parent.equals("actuators")) {
                return ACTUATOR_TYPES.contains(name) ? Element.ACTUATOR : null;
            }
            return path.size() == 3 && parent.equals("sensors") && SENSOR_TYPES.contains(name) ? Element.SENSOR : null;
        }
        if (path.size() > 2) {
            return section.equals("behaviors") ? (name.equals(IF) ? Element.CONDITIONAL : Element.INSTANCE) : null;
        }
        switch (section) {
            case "parameters": return Element.PARAMETER;
            case "controls": return Element.TEXT_CONTROL;
            case "states": return Element.STATE;
            case "automata": return Element.AUTOMATON;
            case "behaviors": return Element.BEHAVIOR;
            case "main": return Element.ENTRY;
            default: return null;
        }
    }

    private static Element section(String name) {
        switch (name) {
            case "robot": return Element.ROBOT;
            case "main": return Element.MAIN;
            default: return SECTIONS.contains(name) ? Element.SECTION : null;
        }
    }

    /**
     * The element names fixed by the language that may stand inside {@code path} (names the
     * script defines, such as groups, automata and behaviors, are not listed).
     */
    public static List<String> fixedChildren(List<String> path) {
        if (path.isEmpty()) {
            return List.of(ROOT);
        }
        if (path.size() == 1) {
            List<String> out = new java.util.ArrayList<>(SECTIONS);
            out.add(INCLUDE);
            return List.copyOf(out);
        }
        String parent = path.get(path.size() - 1);
        if (path.get(1).equals("robot")) {
            if (path.size() == 2) {
                return ROBOT_PARTS;
            }
            return path.size() != 3 ? List.of() : parent.equals("sensors") ? SENSOR_TYPES
                    : parent.equals("actuators") ? ACTUATOR_TYPES : List.of();
        }
        return path.size() >= 3 && path.get(1).equals("behaviors") ? List.of(IF) : List.of();
    }

    /** The function names of PARSL.md §8, in the order the documentation lists them. */
    public static Set<String> functions() {
        return FUNCTIONS.keySet();
    }

    /** The arity of function {@code name}: a count, {@link #ONE_OR_MORE}, or {@link #UNKNOWN}. */
    public static int arity(String name) {
        return FUNCTIONS.getOrDefault(name, UNKNOWN);
    }

    /** Names no script may define: functions, constants, {@code forever} and {@code all}. */
    public static boolean isReserved(String name) {
        return CONSTANTS.contains(name) || name.equals(FOREVER) || name.equals(ALL) || FUNCTIONS.containsKey(name);
    }

    /** The key names a control's {@code keys} may use: arrows, {@code space}, a–z and 0–9. */
    public static Set<String> keyNames() {
        return KEYS;
    }

    private static Map<String, Integer> functionTable() {
        Map<String, Integer> f = new LinkedHashMap<>();
        for (String one : List.of("sin", "cos", "tan", "asin", "acos", "atan")) {
            f.put(one, 1);
        }
        f.put("atan2", 2);
        for (String one : List.of("sinh", "cosh", "tanh", "asinh", "acosh", "atanh", "log", "ln", "exp", "sqrt", "abs")) {
            f.put(one, 1);
        }
        f.put("mod", 2);
        f.put("rand", 0);
        f.put("sum", ONE_OR_MORE);
        f.put("if", 3);
        for (String one : List.of("round", "floor", "ceil")) {
            f.put(one, 1);
        }
        f.put("min", 2);
        f.put("max", 2);
        f.put("rad", 1);
        f.put("deg", 1);
        return Collections.unmodifiableMap(f);
    }

    private static Set<String> keys() {
        Set<String> k = new LinkedHashSet<>(List.of("Up", "Down", "Left", "Right", "space"));
        for (char c = 'a'; c <= 'z'; c++) {
            k.add(String.valueOf(c));
        }
        for (char c = '0'; c <= '9'; c++) {
            k.add(String.valueOf(c));
        }
        return Collections.unmodifiableSet(k);
    }
}
