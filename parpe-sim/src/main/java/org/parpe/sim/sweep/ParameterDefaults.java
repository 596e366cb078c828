package org.parpe.sim.sweep;

import org.parpe.sim.text.SimMsg;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.parpe.core.edit.Replacement;
import org.parpe.core.edit.ScriptEdits;
import org.parpe.core.edit.TextEdit;
import org.parpe.core.lang.Numbers;
import org.parpe.core.model.Parameter;

/**
 * Writes new default values into a script's text: each parameter's {@code value="..."}
 * attribute is replaced in place through the edit layer, so comments, layout and everything
 * else stay as the author wrote them.
 */
public final class ParameterDefaults {
    private ParameterDefaults() {
    }

    /**
     * {@code text} (the content of {@code file}, as the parameters were loaded from it) with the
     * defaults of {@code parameters} named in {@code values} replaced, each found by its
     * element's source span; throws when a parameter is defined in another file (an include).
     */
    public static String rewrite(Path file, String text, List<Parameter> parameters, Map<String, Double> values)
            throws SweepException {
        List<Replacement> edits = new ArrayList<>();
        // From the end of the text backwards, so that the last parameter's problem is the one reported, as before.
        List<Parameter> byPlace = parameters.stream().filter(p -> values.containsKey(p.name()))
                .sorted((a, b) -> a.pos().line() != b.pos().line() ? b.pos().line() - a.pos().line()
                        : b.pos().column() - a.pos().column())
                .toList();
        for (Parameter p : byPlace) {
            if (!Path.of(p.pos().file()).normalize().equals(file.normalize())) {
                throw new SweepException(SimMsg.DEFINED_ELSEWHERE, p.name(), p.pos().file(), file);
            }
            if (p.pos().span() == null) {
                throw new SweepException(SimMsg.NO_ELEMENT, p.pos(), p.name());
            }
            if (p.pos().span().value("value") == null) {
                throw new SweepException(SimMsg.NO_VALUE_ATTRIBUTE, p.pos(), p.name());
            }
            edits.addAll(ScriptEdits.setAttribute(text, p.pos(), "value", Numbers.format(values.get(p.name())))
                    .replacements());
        }
        return new TextEdit(edits).apply(text);
    }
}
