package org.parpe.core.export;

import java.util.List;
import org.parpe.core.expr.ExprTree;
import org.parpe.core.expr.Node;

/**
 * Translates one compiled expression tree into the body of a C function that evaluates it as
 * {@code org.parpe.core.expr.Nodes} does: operands left to right, one temporary per node (C
 * leaves the order of function arguments open), short-circuits as branches, and the same
 * finiteness checks, which raise the same run-time errors.
 */
final class CExpressions implements ExprTree.Visitor<String> {
    /** One-argument functions in the order of the runtime's names table ({@code parsl_io.c}). */
    static final List<String> FUNCTIONS = List.of("sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh",
            "asinh", "acosh", "atanh", "log", "ln", "exp", "sqrt", "abs", "round", "floor", "ceil", "rad", "deg");

    /**
     * Functions whose value can be finite where their argument is not (atan, tanh, exp of −inf, and,
     * by their formulas, asinh, acosh, atanh): the unchecked form checks their argument. The others
     * give NaN or an infinity for a non-finite argument (C99 Annex F), so their result shows it.
     */
    static final java.util.Set<String> HIDING = java.util.Set.of("atan", "tanh", "exp", "asinh", "acosh", "atanh");

    private final StringBuilder body = new StringBuilder();
    private final int[] sensorSlot;
    private final Kept kept;
    /** The unchecked form of the common case ({@link #fastFunction}), and the number of its next kept value. */
    private final boolean fast;
    private int keptNext;
    private int memos;
    private boolean keeping;
    private int temps;
    private int depth = 1;

    /** The values kept per module so far, numbered across the program's expressions ({@link ModuleConstants}). */
    static final class Kept {
        private int count;

        /** How many values are kept per module. */
        int count() {
            return count;
        }
    }

    /**
     * {@code sensorSlot} maps the interpreter's flat sensor slots to the compact C table (−1: none);
     * {@code kept} numbers the values kept per module, null where none are (not a state's angle).
     */
    private CExpressions(int[] sensorSlot, Kept kept, boolean fast, int keptFirst) {
        this.sensorSlot = sensorSlot;
        this.kept = kept;
        this.fast = fast;
        this.keptNext = keptFirst;
    }

    /** The C function {@code static double NAME(parsl_rt *r)} evaluating {@code root}. */
    static String function(String name, Node root, int[] sensorSlot) {
        return function(name, root, sensorSlot, null);
    }

    /**
     * As {@link #function(String, Node, int[])} for a state's angle, which is evaluated for one
     * module at a time: sub-expressions that are the same for a module at every tick are kept in
     * {@code parsl_kept}, numbered by {@code kept}, where {@code PARSL_KEEP} is defined.
     */
    static String function(String name, Node root, int[] sensorSlot, Kept kept) {
        CExpressions c = new CExpressions(sensorSlot, kept, false, 0);
        return c.text("static double " + name + "(parsl_rt *r)", c.emit(root));
    }

    /**
     * The unchecked form of a state's angle for the common case of a tick ({@code PARSL_FAST},
     * {@link CFastForm}): the same operations on the same values as {@link #function}, without
     * its checks, reading the module's phase and cycle from {@code m} and its position from
     * {@code k}; NaN (so that the caller runs the checked form, which raises what the interpreter
     * raises) where an operand an operation could hide is not finite, and where a kept value is
     * not there yet. {@code keptFirst}: the number of the first value {@link #function} kept for
     * this tree, or −1 where it keeps none. Only for trees without {@code rand()} and local sensors
     * ({@link #fastForm}).
     */
    static Fast fastFunction(String name, Node root, int[] sensorSlot, int keptFirst) {
        CExpressions c = new CExpressions(sensorSlot, keptFirst < 0 ? null : new Kept(), true, keptFirst);
        String result = c.emit(root);
        return new Fast(c.text("static inline double " + name
                + "(parsl_rt *r, const inst_view *v, int16_t k, const parsl_fast_mod *m, parsl_memo *memo)", result),
                c.memos);
    }

    /** An unchecked form's C, and how many values it shares between modules ({@code memo[]}, {@link ModuleConstants#worthSharing}). */
    record Fast(String text, int memos) {
    }

    /** Whether {@code root} has an unchecked form: no {@code rand()} (a second run would draw again), no local sensor. */
    static boolean fastForm(Node root) {
        return !ExprTree.visit(root, new ExprTree.Question(false) {
            @Override
            public Boolean variable(String name) {
                return false;
            }

            @Override
            public Boolean localSensor(int position, int channel) {
                return true;
            }

            @Override
            public Boolean random() {
                return true;
            }
        });
    }

    private String text(String signature, String result) {
        CExpressions c = this;
        StringBuilder out = new StringBuilder(signature).append("\n{\n");
        if (c.temps > 0) {
            out.append("    double ");
            for (int i = 0; i < c.temps; i++) {
                out.append(i == 0 ? "" : ", ").append('t').append(i);
            }
            out.append(";\n");
        }
        out.append(c.body);
        if (c.body.indexOf("r->") < 0 && c.body.indexOf("(r,") < 0 && c.body.indexOf("(r)") < 0) {
            out.append("    (void) r;\n");
        }
        out.append("    return ").append(result).append(";\n}\n");
        return out.toString();
    }

    /** A C literal with exactly the value of {@code v}. */
    static String literal(double v) {
        if (v == 0) {
            return (1 / v < 0) ? "(-0.0)" : "0.0";
        }
        return "(" + Double.toHexString(v) + ")";
    }

    /**
     * The C of node {@code n}; a value worth keeping per module is computed as before where no
     * kept value is there yet (the first tick, or a board without {@code PARSL_KEEP}) and read
     * afterwards. An error raised computing it keeps nothing, so it is raised again next time, as
     * the interpreter does.
     */
    private String emit(Node n) {
        if (fast && !keeping && (kept == null || !ModuleConstants.worthKeeping(n)) && ModuleConstants.worthSharing(n)) {
            return shared(n);
        }
        if (kept == null || keeping || !ModuleConstants.worthKeeping(n)) {
            return ExprTree.visit(n, this);
        }
        if (fast) {
            String slot = "[" + keptNext++ + "][v->mod + k]";
            line("if (!parsl_kept_ok" + slot + ") return NAN;");
            return set("parsl_kept" + slot);
        }
        int at = body.length();
        String pad = "    ".repeat(depth);
        keeping = true;
        String v = ExprTree.visit(n, this); // a temporary: every costly node's value is one
        keeping = false;
        String slot = "[" + kept.count++ + "][r->group_off + r->index]";
        body.insert(at, "#ifdef PARSL_KEEP\n" + pad + "if (parsl_kept_ok" + slot + ") {\n" + pad + "    " + v
                + " = parsl_kept" + slot + ";\n" + pad + "} else {\n#endif\n");
        body.append("#ifdef PARSL_KEEP\n").append(pad).append("    parsl_kept").append(slot).append(" = ").append(v)
                .append(";\n").append(pad).append("    parsl_kept_ok").append(slot).append(" = 1;\n").append(pad)
                .append("}\n#endif\n");
        return v;
    }

    /**
     * In the unchecked form, a value the same for every module in the tick (with the same {@code
     * $cycle} where it reads it): computed for the first and reused, the same operations on the
     * same values. A guard that fails on the way stores nothing.
     */
    private String shared(Node n) {
        String memo = "memo[" + memos++ + "]";
        String t = temp();
        line("if (" + memo + ".ok" + (ModuleConstants.readsCycle(n) ? " && parsl_same(" + memo + ".cycle, m->cycle)" : "")
                + ") {");
        line("    " + t + " = " + memo + ".value;");
        line("} else {");
        depth++;
        keeping = true;
        String v = ExprTree.visit(n, this);
        keeping = false;
        line(t + " = " + v + ";");
        line(memo + ".value = " + t + ";");
        line(memo + ".cycle = m->cycle;");
        line(memo + ".ok = 1;");
        depth--;
        line("}");
        return t;
    }

    private String temp() {
        return "t" + temps++;
    }

    private void line(String s) {
        body.append("    ".repeat(depth)).append(s).append('\n');
    }

    /** In the unchecked form: NaN, so that the checked form runs, where {@code x} is not finite. */
    private void guard(String x) {
        if (fast && x.startsWith("t")) { // a temporary, not a literal
            line("if (!isfinite(" + x + ")) return NAN;");
        }
    }

    private String set(String expression) {
        String t = temp();
        line(t + " = " + expression + ";");
        return t;
    }

    @Override
    public String constant(double value) {
        return literal(value);
    }

    @Override
    public String variable(String name) {
        if (fast) {
            switch (name) {
                case "phase": case "cycle": return set("m->" + name);
                case "index": return set("(double) k");
                case "count": return set("(double) v->n");
                case "id": return set("(double) PARSL_U16(parsl_ids, parsl_module_of(v, k))");
                default: break;
            }
        }
        switch (name) {
            case "index": case "count": case "id":
                return set("(double) r->" + name);
            default:
                return set("r->" + name);
        }
    }

    @Override
    public String control(int index) {
        return set("r->controls[" + index + "]");
    }

    @Override
    public String macro(int index) {
        return set("r->macros[" + index + "]");
    }

    @Override
    public String globalSensor(int slot) {
        int s = sensorSlot[slot];
        return s < 0 ? "0.0" : set("r->sens[" + s + "]");
    }

    @Override
    public String localSensor(int position, int channel) {
        if (fast) {
            throw new IllegalStateException("no unchecked form reads a local sensor (fastForm)");
        }
        return set("parsl_local(r, " + position + ", " + channel + ")");
    }

    @Override
    public String unary(boolean not, Node arg) {
        String a = emit(arg);
        if (not) {
            guard(a);
        }
        return set(not ? "(" + a + " == 0 ? 1.0 : 0.0)" : "-" + a);
    }

    @Override
    public String binary(String op, Node left, Node right) {
        String a = emit(left);
        String b = emit(right);
        switch (op) {
            case "+": return checked(a + " + " + b, "PARSL_E_SUM");
            case "-": return checked(a + " - " + b, "PARSL_E_DIFF");
            case "*": return checked(a + " * " + b, "PARSL_E_PROD");
            case "/":
                // x / inf is 0; x / 0 is not finite and stays so
                divisor(b, "PARSL_E_DIV");
                return checked(a + " / " + b, "PARSL_E_QUOT");
            case "%":
                divisor(b, "PARSL_E_REM");
                return set("fmod(" + a + ", " + b + ")");
            case "^": {
                guard(a); // pow(NaN, 0) and pow(1, NaN) are 1
                guard(b);
                String t = set("pow(" + a + ", " + b + ")");
                if (!fast) {
                    line("if (!isfinite(" + t + ")) parsl_raise(r, PARSL_E_POW, " + a + ", " + b + ", 0);");
                }
                return t;
            }
            default:
                guard(a); // a comparison is 0 or 1 whatever its operands
                guard(b);
                return set("(" + a + " " + op + " " + b + " ? 1.0 : 0.0)");
        }
    }

    /** The check of a divisor: raises at 0; in the unchecked form NaN where it is not finite (x / inf is 0). */
    private void divisor(String b, String error) {
        if (fast) {
            guard(b);
        } else {
            line("if (" + b + " == 0) parsl_raise(r, " + error + ", 0, 0, 0);");
        }
    }

    /** {@code expression}'s value, checked to be finite; unchecked in the fast form, where + - * and / keep a non-finite operand's. */
    private String checked(String expression, String error) {
        String t = set(expression);
        if (fast) {
            return t;
        }
        line("if (!isfinite(" + t + ")) parsl_raise(r, " + error + ", 0, 0, 0);");
        return t;
    }

    @Override
    public String logic(boolean and, Node left, Node right) {
        String a = emit(left);
        String t = temp();
        guard(a);
        line("if (" + a + (and ? " != 0" : " == 0") + ") {");
        depth++;
        String b = emit(right);
        guard(b);
        line(t + " = " + b + " != 0 ? 1.0 : 0.0;");
        depth--;
        line("} else {");
        line("    " + t + " = " + (and ? "0.0" : "1.0") + ";");
        line("}");
        return t;
    }

    @Override
    public String conditional(Node cond, Node then, Node otherwise) {
        String c = emit(cond);
        String t = temp();
        guard(c);
        line("if (" + c + " != 0) {");
        depth++;
        line(t + " = " + emit(then) + ";");
        depth--;
        line("} else {");
        depth++;
        line(t + " = " + emit(otherwise) + ";");
        depth--;
        line("}");
        return t;
    }

    @Override
    public String function1(String name, Node arg) {
        String x = emit(arg);
        if (HIDING.contains(name)) {
            guard(x);
        }
        String t = set(c1(name, x));
        if (fast) {
            return t;
        }
        line("if (!isfinite(" + t + ")) parsl_raise(r, PARSL_E_FUNC, " + x + ", 0, " + FUNCTIONS.indexOf(name) + ");");
        return t;
    }

    /** The C of {@code org.parpe.core.expr.Functions.F1}, formula for formula. */
    private static String c1(String name, String x) {
        switch (name) {
            case "asinh": return "log(" + x + " + sqrt(" + x + " * " + x + " + 1))";
            case "acosh": return "log(" + x + " + sqrt(" + x + " * " + x + " - 1))";
            case "atanh": return "0.5 * log((1 + " + x + ") / (1 - " + x + "))";
            case "log": return "log10(" + x + ")";
            case "ln": return "log(" + x + ")";
            // the runtime's own, inline (parsl_maths.h): a C library call was 40 % of a tick
            case "sin": return "parsl_sin(" + x + ")";
            case "cos": return "parsl_cos(" + x + ")";
            case "abs": return "fabs(" + x + ")";
            case "round": return "floor(" + x + " + 0.5)";
            // java.lang.Math.toRadians and toDegrees multiply by these constants (JDK 9 and later)
            case "rad": return x + " * 0.017453292519943295";
            case "deg": return x + " * 57.29577951308232";
            default: return name + "(" + x + ")";
        }
    }

    @Override
    public String function2(String name, Node a, Node b) {
        String x = emit(a);
        String y = emit(b);
        if (!name.equals("mod")) { // mod's divisor is checked below
            guard(x); // atan2(inf, 1) is finite, min(inf, 1) 1
            guard(y);
        }
        switch (name) {
            case "atan2": return set("atan2(" + x + ", " + y + ")");
            case "mod":
                divisor(y, "PARSL_E_MODF");
                return set("fmod(" + x + ", " + y + ")");
            // java.lang.Math.min/max: NaN wins, and -0.0 is below 0.0
            case "min": return set("parsl_min(" + x + ", " + y + ")");
            default: return set("parsl_max(" + x + ", " + y + ")");
        }
    }

    @Override
    public String sum(List<Node> args) {
        String s = set("0.0");
        for (Node n : args) {
            String v = emit(n);
            line(s + " += " + v + ";");
        }
        if (fast) {
            return s;
        }
        line("if (!isfinite(" + s + ")) parsl_raise(r, PARSL_E_SUMF, 0, 0, 0);");
        return s;
    }

    @Override
    public String random() {
        if (fast) {
            throw new IllegalStateException("no unchecked form draws a random number (fastForm)");
        }
        return set("parsl_rand(r)");
    }
}
