package org.parpe.core.export;

import java.util.List;
import java.util.function.IntUnaryOperator;
import java.util.function.ToIntFunction;
import org.parpe.core.expr.Expression;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.StateDef;

/**
 * The common case of a tick, generated per automaton into {@code parsl_program.c} (issue 36 item
 * 3; {@code PARSL_FAST} in {@code parsl_inst.h} says what it is): a loop over the instance's
 * modules that steps each by its state's whole-tick step, worked out once per tick, and computes
 * its angle inline in the unchecked form ({@link CExpressions#fastFunction}); a module outside the
 * common case, or whose angle is not finite, runs the runtime's {@code parsl_advance}. Automata
 * whose durations depend on the module have none, nor states with an exit condition, with one
 * angle per module, or whose angle draws a random number or reads a local sensor.
 */
final class CFastForm {
    /** The line that opens the common case in {@code parsl_program.c} (its {@code #endif} closes it). */
    static final String GUARD = "#ifdef PARSL_FAST";

    private CFastForm() {
    }

    /**
     * The C of the common case for {@code automata}: {@code id} numbers an expression as the
     * checked functions {@code x<id>} do, {@code keptFirst} gives the number of the first value
     * that function keeps per module (−1: none).
     */
    static String source(List<Automaton> automata, ToIntFunction<Expression> id, IntUnaryOperator keptFirst,
            int[] sensorSlot) {
        StringBuilder c = new StringBuilder(GUARD + "\n#include \"parsl_inst.h\"\n\n");
        StringBuilder dispatch = new StringBuilder();
        java.util.Map<Integer, Integer> written = new java.util.HashMap<>(); // expression: its shared values
        for (int a = 0; a < automata.size(); a++) {
            Automaton aut = automata.get(a);
            if (aut.times().stream().anyMatch(tm -> tm.duration().perModule())) {
                continue;
            }
            StringBuilder cases = new StringBuilder();
            StringBuilder memos = new StringBuilder();
            for (int s = 0; s < aut.states().size(); s++) {
                StateDef st = aut.states().get(s);
                if (aut.times().get(s).exit() != null || st.angles().size() != 1
                        || !CExpressions.fastForm(st.angles().get(0).root())) {
                    continue;
                }
                Expression e = st.angles().get(0);
                int x = id.applyAsInt(e);
                if (!written.containsKey(x)) {
                    CExpressions.Fast f = CExpressions.fastFunction("f" + x, e.root(), sensorSlot, keptFirst.applyAsInt(x));
                    c.append("/* ").append(CText.comment(e.text())).append(", unchecked */\n").append(f.text()).append('\n');
                    written.put(x, f.memos());
                }
                String memo = "0";
                if (written.get(x) > 0) {
                    memo = "memo" + s;
                    memos.append("    parsl_memo ").append(memo).append('[').append(written.get(x)).append("] = {{0, 0, 0}};\n");
                }
                cases.append("        case ").append(s).append(": a = f").append(x).append("(r, v, k, &m, ").append(memo)
                        .append("); break;\n");
            }
            if (cases.isEmpty()) {
                continue;
            }
            c.append("/* automaton ").append(CText.comment(aut.name())).append(" */\n");
            c.append(String.format(java.util.Locale.ROOT, LOOP, a, aut.states().size(), memos, cases));
            dispatch.append("    case ").append(a).append(": fast").append(a).append("(r, v); return 1;\n");
        }
        c.append("int parsl_fast(parsl_rt *r, inst_view *v)\n{\n");
        if (dispatch.isEmpty()) {
            c.append("    (void) r;\n    (void) v;\n    return 0;\n}\n");
        } else {
            c.append("    switch (v->aut) {\n").append(dispatch).append("    default: return 0;\n    }\n}\n");
        }
        return c.append("#endif\n\n").toString();
    }

    /**
     * An automaton's loop (its number, its count of states, the values its states' angles share
     * between modules in a tick, the cases of its states): as the
     * runtime's loop over an instance's modules ({@code run_instances}), each module that is not
     * finished advanced and driven in turn; the expression context is left as the last module's,
     * as {@code parsl_advance} leaves it.
     */
    private static final String LOOP = """
            static void fast%1$d(parsl_rt *r, inst_view *view)
            {
                const inst_view copy = *view; /* a copy no store to r can change: its fields stay in registers */
                const inst_view *v = &copy;
                parsl_fast_step f[%2$d];
            %3$s    parsl_fast_mod m;
                int16_t k;
                int16_t last = -1;
                int some_finished = v->is->finished != 0; /* else no module's fin is set */
                parsl_fast_begin(r, v, f);
                for (k = 0; k < v->n; k++) {
                    double a;
                    if (some_finished && r->fin[v->pool + k]) {
                        continue;
                    }
                    switch (parsl_fast_enter(r, v, f, k, &m)) {
            %4$s        default: a = NAN; break;
                    }
                    if (isfinite(a)) {
                        parsl_fast_store(r, v, &f[r->st[v->pool + k]], k, &m, a);
                        last = k;
                    } else {
                        parsl_advance(r, view, k, PARSL_DT);
                        last = -1;
                    }
                    parsl_drive(r, v, k);
                }
                if (last >= 0) {
                    parsl_enter(r, v, last);
                }
            }

            """;
}
