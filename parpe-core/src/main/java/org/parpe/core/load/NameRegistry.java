package org.parpe.core.load;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.text.Msg;

/**
 * The shared expression namespace of groups, parameters, controls, radio words and macros
 * (PARSL.md §1, §13 rule 10). Clashes are reported at the later definition in document order,
 * naming the earlier one.
 */
final class NameRegistry {
    private record Def(String name, String kind, long order, SourcePos reportAt, SourcePos own, String owner) {
    }

    private final List<Def> defs = new ArrayList<>();

    /**
     * Records a definition.
     *
     * @param owner for radio words the control, for macros the behavior; definitions with the
     *              same kind and owner scope rules (same radio word in two controls, macros of
     *              different behaviors) do not clash
     */
    void define(String name, String kind, long order, SourcePos reportAt, SourcePos own, String owner) {
        defs.add(new Def(name, kind, order, reportAt, own, owner));
    }

    /** Reports every clash. */
    void check(DiagnosticSink d) {
        List<Def> sorted = new ArrayList<>(defs);
        sorted.sort(Comparator.comparingLong(Def::order));
        Map<String, List<Def>> seen = new HashMap<>();
        for (Def def : sorted) {
            List<Def> earlier = seen.computeIfAbsent(def.name(), k -> new ArrayList<>());
            for (Def e : earlier) {
                if (clash(e, def)) {
                    d.error(def.reportAt(), Msg.NAME_CLASH, Msg.named(def.kind(), def.name()),
                            Msg.definedAt(def.reportAt().equals(def.own()) ? null : def.own(), def.own()),
                            Msg.named(e.kind(), e.name()), e.own());
                    break;
                }
            }
            earlier.add(def);
        }
    }

    private static boolean clash(Def a, Def b) {
        if (a.kind().equals("radio word") && b.kind().equals("radio word")) {
            return a.owner().equals(b.owner());
        }
        if (a.kind().equals("macro") && b.kind().equals("macro")) {
            return a.owner().equals(b.owner());
        }
        if (a.kind().equals("macro") || b.kind().equals("macro")) {
            // a macro clashes with global names, not with macros of other behaviors
            return !(a.kind().equals("macro") && b.kind().equals("macro"));
        }
        return true;
    }
}
