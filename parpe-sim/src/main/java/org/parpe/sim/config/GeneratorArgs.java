package org.parpe.sim.config;

import org.parpe.core.text.Msg;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.Names;

/**
 * The {@code key=value} arguments of a generator spec such as {@code snake:n=12,axes=alternate},
 * with their columns for located messages. Every key a generator reads is marked used; keys
 * left over are reported as unknown.
 */
final class GeneratorArgs {
    private final String origin;
    private final Map<String, String> values = new LinkedHashMap<>();
    private final Map<String, Integer> columns = new LinkedHashMap<>();
    private final List<String> known = new ArrayList<>();
    private final DiagnosticSink diags;
    private boolean ok = true;

    private GeneratorArgs(String origin, DiagnosticSink diags) {
        this.origin = origin;
        this.diags = diags;
    }

    /** Parses the part after the colon, which starts at 1-based column {@code column} of the spec. */
    static GeneratorArgs parse(String origin, String text, int column, DiagnosticSink diags) {
        GeneratorArgs a = new GeneratorArgs(origin, diags);
        int at = 0;
        for (String item : text.split(",", -1)) {
            int col = column + at;
            at += item.length() + 1;
            String t = item.trim();
            int eq = t.indexOf('=');
            if (eq <= 0) {
                a.error(col, Msg.EXPECTED_KEY_VALUE, t);
            } else if (a.values.put(t.substring(0, eq).trim(), t.substring(eq + 1).trim()) != null) {
                a.error(col, Msg.GIVEN_TWICE, t.substring(0, eq).trim());
            } else {
                a.columns.put(t.substring(0, eq).trim(), col);
            }
        }
        return a;
    }

    /** No arguments. */
    static GeneratorArgs empty(String origin, DiagnosticSink diags) {
        return new GeneratorArgs(origin, diags);
    }

    /** A whole-number argument in {@code [min, max]}. */
    int integer(String key, int fallback, int min, int max) {
        known.add(key);
        String v = values.get(key);
        if (v == null) {
            return fallback;
        }
        try {
            if (!v.matches("[+-]?[0-9]+")) {
                // Integer.parseInt would read other scripts' digits ("٣" as 3)
                throw new NumberFormatException(v);
            }
            int n = Integer.parseInt(v);
            if (n < min || n > max) {
                error(columns.get(key), Msg.MUST_BE_IN_RANGE, key, min, max, n);
                return fallback;
            }
            return n;
        } catch (NumberFormatException e) {
            error(columns.get(key), Msg.MUST_BE_WHOLE, key, v);
            return fallback;
        }
    }

    /** A word argument out of {@code choices} (the first is the default). */
    String word(String key, String... choices) {
        known.add(key);
        String v = values.get(key);
        if (v == null) {
            return choices[0];
        }
        for (String c : choices) {
            if (c.equals(v)) {
                return c;
            }
        }
        error(columns.get(key), Msg.MUST_BE_ONE_OF, key, String.join(", ", choices), v);
        return choices[0];
    }

    /** Reports keys no generator asked for; returns whether every argument was fine. */
    boolean finish(String generator) {
        for (Map.Entry<String, Integer> e : columns.entrySet()) {
            if (!known.contains(e.getKey())) {
                error(e.getValue(), Msg.GENERATOR_NO_PARAMETER, generator, e.getKey(), String.join(", ", known),
                        Names.suggest(e.getKey(), known));
            }
        }
        return ok;
    }

    void error(int column, Msg key, Object... args) {
        diags.error(new SourcePos(origin, 1, column), key, args);
        ok = false;
    }
}
