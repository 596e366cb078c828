package org.parpe.sim.sweep;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.parpe.core.lang.Numbers;
import org.parpe.core.model.Parameter;

/**
 * Writes new default values into a script's text: each parameter's {@code value="..."}
 * attribute is replaced in place, so comments, layout and everything else stay as the author
 * wrote them.
 */
public final class ParameterDefaults {
    private static final Pattern VALUE = Pattern.compile("(\\svalue\\s*=\\s*)([\"'])([^\"']*)\\2");

    private ParameterDefaults() {
    }

    /**
     * {@code text} (the content of {@code file}) with the defaults of {@code parameters} named in
     * {@code values} replaced; throws when a parameter is defined in another file (an include).
     */
    public static String rewrite(Path file, String text, List<Parameter> parameters, Map<String, Double> values)
            throws SweepException {
        StringBuilder out = new StringBuilder(text);
        // From the end of the text backwards, so that earlier offsets stay valid.
        List<Parameter> byPlace = parameters.stream().filter(p -> values.containsKey(p.name()))
                .sorted((a, b) -> a.pos().line() != b.pos().line() ? b.pos().line() - a.pos().line()
                        : b.pos().column() - a.pos().column())
                .toList();
        for (Parameter p : byPlace) {
            if (!Path.of(p.pos().file()).normalize().equals(file.normalize())) {
                throw new SweepException("parameter '" + p.name() + "' is defined in " + p.pos().file()
                        + ", not in " + file + "; set its value there by hand");
            }
            int at = offset(out, p.pos().line(), p.pos().column());
            int open = out.lastIndexOf("<", at);
            int close = tagEnd(out, open);
            if (open < 0 || close < 0) {
                throw new SweepException(p.pos().file() + ":" + p.pos().line() + ":" + p.pos().column()
                        + ": cannot find the element of parameter '" + p.name() + "'");
            }
            Matcher m = VALUE.matcher(out).region(open, close);
            if (!m.find()) {
                throw new SweepException(p.pos().file() + ":" + p.pos().line() + ":" + p.pos().column()
                        + ": parameter '" + p.name() + "' has no value attribute to replace");
            }
            out.replace(m.start(3), m.end(3), Numbers.format(values.get(p.name())));
        }
        return out.toString();
    }

    private static int offset(CharSequence text, int line, int column) {
        int l = 1;
        int i = 0;
        while (l < line && i < text.length()) {
            if (text.charAt(i++) == '\n') {
                l++;
            }
        }
        return Math.min(text.length() - 1, i + Math.max(0, column - 1));
    }

    /** The index of the {@code >} closing the tag opened at {@code open}, skipping quoted values. */
    private static int tagEnd(CharSequence text, int open) {
        if (open < 0) {
            return -1;
        }
        char quote = 0;
        for (int i = open; i < text.length(); i++) {
            char c = text.charAt(i);
            if (quote != 0) {
                quote = c == quote ? 0 : quote;
            } else if (c == '"' || c == '\'') {
                quote = c;
            } else if (c == '>') {
                return i;
            }
        }
        return -1;
    }
}
