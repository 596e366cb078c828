package org.parpe.core.export;

import java.util.List;
import java.util.Map;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.Control;
import org.parpe.core.model.Program;
import org.parpe.core.model.StateDef;

/** Writes the constant tables of a {@link CProgram} as C definitions ({@code PARSL_ROM}: flash on AVR). */
final class CTables {
    private final Program program;
    private final int[] ids;
    private final int[] sensorSlot;
    private final CProgram.Tables t;
    private final List<SourcePos> places;
    private final Map<String, Integer> files;
    private final List<String> exprTexts;
    private final List<String> instGroups;

    CTables(Program program, int[] ids, int[] sensorSlot, CProgram.Tables t, List<SourcePos> places,
            Map<String, Integer> files, List<String> exprTexts, List<String> instGroups) {
        this.exprTexts = exprTexts;
        this.instGroups = instGroups;
        this.program = program;
        this.ids = ids;
        this.sensorSlot = sensorSlot;
        this.t = t;
        this.places = places;
        this.files = files;
    }

    void append(StringBuilder c) {
        c.append("/* module IDs, ascending: the order of r->commanded and of the trace columns */\n");
        list(c, "const uint16_t parsl_ids[]", java.util.Arrays.stream(ids).boxed().toList());
        c.append("/* sensor reading of (module index, channel) in r->sens, -1: not carried */\n");
        list(c, "const int16_t parsl_slot[]", java.util.Arrays.stream(sensorSlot).boxed().toList());
        controls(c);
        c.append("\n/* <main> entries: first instance, instances, time, exit, first macro value, macro values */\n");
        rows(c, "const int16_t parsl_entry[][PARSL_ENTRY_COLS]", t.entry, CLayout.EntryCol.class);
        c.append("/* expression-valued macros: slot, expression */\n");
        rows(c, "const int16_t parsl_varg[][PARSL_VARG_COLS]", t.varg, CLayout.VargCol.class);
        c.append("/* instances: automaton, mirror, modules, first module, first condition, conditions, phase, offset,\n"
                + "   period, start, cycles (expressions, -1: none), state pool, duration pool, place */\n");
        rows(c, "const int16_t parsl_inst[][PARSL_INST_COLS]", t.inst, CLayout.InstCol.class);
        c.append("/* module indices of each instance's group, in group order */\n");
        list(c, "const int16_t parsl_inst_mod[]", t.mod);
        c.append("/* <if> conditions of each instance, outermost first */\n");
        list(c, "const int16_t parsl_cond[]", t.cond);
        c.append("/* automata: states, first state, whether durations depend on the module */\n");
        rows(c, "const int16_t parsl_aut[][PARSL_AUT_COLS]", t.aut, CLayout.AutCol.class);
        c.append("/* states: profile (0 linear, 1 step, 2 smooth), angles, first angle, duration, exit (-1: none) */\n");
        rows(c, "const int16_t parsl_state[][PARSL_STATE_COLS]", t.state, CLayout.StateCol.class);
        c.append("/* target angle expressions: one for the group, or one per position */\n");
        list(c, "const int16_t parsl_angle[]", t.angle);
        positions(c);
        names(c);
    }

    private void controls(StringBuilder c) {
        List<Control> cs = program.controls();
        StringBuilder init = new StringBuilder("PARSL_ROM const double parsl_control_init[] = {");
        StringBuilder range = new StringBuilder("PARSL_ROM const double parsl_control_range[][2] = {");
        StringBuilder rows = new StringBuilder("PARSL_ROM const int16_t parsl_control[][PARSL_CONTROL_COLS] = {");
        StringBuilder words = new StringBuilder("PARSL_ROM const int16_t parsl_words[] = {");
        StringBuilder index = new StringBuilder("int16_t parsl_control_index(const char *name)\n{\n");
        int nwords = 0;
        for (int i = 0; i < cs.size(); i++) {
            Control k = cs.get(i);
            init.append(i == 0 ? "" : ", ").append(CExpressions.literal(k.value()));
            range.append(i == 0 ? "" : ", ").append('{').append(CExpressions.literal(k.min() == null ? 0 : k.min()))
                    .append(", ").append(CExpressions.literal(k.max() == null ? 0 : k.max())).append('}');
            int[] row = new CLayout.Row<>(CLayout.ControlCol.class).set(CLayout.ControlCol.TYPE, k.type().ordinal())
                    .set(CLayout.ControlCol.WORDS, nwords).set(CLayout.ControlCol.NWORDS, k.words().size()).done();
            rows.append(i == 0 ? "{" : ", {").append(java.util.Arrays.stream(row).mapToObj(String::valueOf)
                    .collect(java.util.stream.Collectors.joining(", "))).append('}');
            for (String w : k.words()) {
                words.append(nwords++ == 0 ? "" : ", ").append(program.radioWords().get(w));
            }
            index.append("    if (PARSL_IS(name, \"").append(k.name()).append("\")) {\n        return ").append(i)
                    .append(";\n    }\n");
        }
        if (cs.isEmpty()) {
            init.append("0.0");
            range.append("{0.0, 0.0}");
            rows.append("{0}");
        }
        if (nwords == 0) {
            words.append('0');
        }
        index.append("    (void) name;\n    return -1;\n}\n\n");
        c.append(init).append("};\n").append(range).append("};\n").append(rows).append("};\n").append(words)
                .append("};\n\n").append(index);
        c.append("int16_t parsl_word_code(const char *name)\n{\n");
        program.radioWords().entrySet().stream().sorted(Map.Entry.comparingByValue()).forEach(e ->
                c.append("    if (PARSL_IS(name, \"").append(e.getKey()).append("\")) {\n        return ")
                        .append(e.getValue()).append(";\n    }\n"));
        c.append("    (void) name;\n    return -1;\n}\n\n");
    }

    private void positions(StringBuilder c) {
        c.append("PARSL_ROM const uint16_t parsl_pos[][3] = {\n");
        for (int i = 0; i < places.size(); i++) {
            SourcePos p = places.get(i);
            int f = files.computeIfAbsent(p.file(), k -> files.size());
            c.append(i == 0 ? "    " : ",\n    ").append('{').append(f).append(", ").append(Math.min(65535, p.line()))
                    .append(", ").append(Math.min(65535, p.column())).append('}');
        }
        if (places.isEmpty()) {
            c.append("    {0, 0, 0}");
        }
        c.append("\n};\n\n");
    }

    private void names(StringBuilder c) {
        c.append("#ifndef PARSL_NO_NAMES\nconst char *const parsl_files[] = {");
        if (files.isEmpty()) {
            c.append("\"\"");
        }
        int i = 0;
        for (String f : files.keySet()) {
            c.append(i++ == 0 ? "" : ", ").append(CText.literal(f));
        }
        c.append("};\nconst char *const parsl_expr_text[] = {");
        for (int e = 0; e < exprTexts.size(); e++) {
            c.append(e == 0 ? "\n    " : ",\n    ").append(CText.literal(exprTexts.get(e)));
        }
        if (exprTexts.isEmpty()) {
            c.append("\"\"");
        }
        c.append("\n};\nconst char *const parsl_inst_groups[] = {");
        for (int g = 0; g < instGroups.size(); g++) {
            c.append(g == 0 ? "" : ", ").append(CText.literal(instGroups.get(g)));
        }
        if (instGroups.isEmpty()) {
            c.append("\"\"");
        }
        c.append("};\nconst char *const parsl_aut_names[] = {");
        StringBuilder states = new StringBuilder("const char *const parsl_state_names[] = {");
        int s = 0;
        for (int a = 0; a < program.automata().size(); a++) {
            Automaton au = program.automata().get(a);
            c.append(a == 0 ? "" : ", ").append(CText.literal(au.name()));
            for (StateDef st : au.states()) {
                states.append(s++ == 0 ? "" : ", ").append(CText.literal(st.name()));
            }
        }
        if (program.automata().isEmpty()) {
            c.append("\"\"");
            states.append("\"\"");
        }
        c.append("};\n").append(states).append("};\n#endif\n");
    }

    private static void list(StringBuilder c, String decl, List<Integer> values) {
        c.append("PARSL_ROM ").append(decl).append(" = {");
        for (int i = 0; i < values.size(); i++) {
            c.append(i == 0 ? "" : ",").append(i % 16 == 0 ? "\n    " : " ").append(values.get(i));
        }
        if (values.isEmpty()) {
            c.append('0');
        }
        c.append("\n};\n");
    }

    private static <E extends Enum<E>> void rows(StringBuilder c, String decl, List<int[]> rows, Class<E> cols) {
        int width = CLayout.width(cols);
        c.append("PARSL_ROM ").append(decl).append(" = {\n");
        for (int i = 0; i < rows.size(); i++) {
            c.append(i == 0 ? "    {" : ",\n    {");
            for (int j = 0; j < width; j++) {
                c.append(j == 0 ? "" : ", ").append(rows.get(i)[j]);
            }
            c.append('}');
        }
        if (rows.isEmpty()) {
            c.append("    {0}");
        }
        c.append("\n};\n");
    }
}
