package org.parpe.core.expr;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import net.objecthunter.exp4j.function.Function;
import net.objecthunter.exp4j.operator.Operator;
import net.objecthunter.exp4j.shuntingyard.ShuntingYard;
import net.objecthunter.exp4j.tokenizer.FunctionToken;
import net.objecthunter.exp4j.tokenizer.NumberToken;
import net.objecthunter.exp4j.tokenizer.OperatorToken;
import net.objecthunter.exp4j.tokenizer.Token;
import net.objecthunter.exp4j.tokenizer.VariableToken;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.expr.Lexer.Type;
import org.parpe.core.run.Channel;
import org.parpe.core.xml.XText;

/**
 * Compiles PARSL expressions (JEP syntax, PARSL.md §8) once at load. Our lexer places every
 * token so errors point at their column; names are resolved against a {@link Scope}; exp4j's
 * shunting-yard parser (implicit multiplication off) orders the operators; and the resulting
 * RPN becomes a tree of {@link Node}s that evaluates without allocating, short-circuits
 * {@code &&}, {@code ||} and {@code if}, and folds constant parts.
 */
public final class ExprCompiler {
    /** A local sensor reference, checked where the automaton meets a group (PARSL.md §13 rule 13). */
    public record LocalUse(int position, Channel channel, org.parpe.core.diag.SourcePos pos, String text) {
        /** The position code of {@code $_self_…}. */
        public static final int SELF = Nodes.LocalSensor.SELF;
    }

    /** A compiled expression with what the loader needs to check it further. */
    public record Result(Expression expression, boolean perModule, List<LocalUse> locals) {
    }

    private static final Pattern GLOBAL = Pattern.compile("(\\d+)_([A-Za-z]+)(?:_([A-Za-z0-9]+))?");
    private static final Pattern LOCAL = Pattern.compile("_(\\d+|self|prev|next)_([A-Za-z]+)(?:_([A-Za-z0-9]+))?");
    private static final Map<String, Operator> OPERATORS = operators();
    private static final Set<String> CONSTANTS = Set.of("pi", "e", "true", "false");
    private static final EvalContext FOLD = new EvalContext();

    private ExprCompiler() {
    }

    /** Names that no script may define: functions and constants of §8 and the keywords. */
    public static boolean isReserved(String name) {
        return CONSTANTS.contains(name) || name.equals("forever") || name.equals("all")
                || Functions.arity(name) != -1 && name.equals(name.toLowerCase(Locale.ROOT));
    }

    /** Compiles {@code src} in {@code scope}; returns {@code null} after reporting errors. */
    public static Result compile(XText src, Scope scope, DiagnosticSink diags) {
        String text = src.value();
        List<Lexer.Token> tokens;
        try {
            tokens = Lexer.lex(text);
        } catch (Lexer.LexError e) {
            diags.error(src.posAt(e.index), e.getMessage() + " in '" + text.trim() + "'");
            return null;
        }
        int[] argCounts = new int[tokens.size()];
        Syntax.Problem p = Syntax.check(tokens, argCounts, text.length());
        if (p != null) {
            diags.error(src.posAt(p.index()), p.message() + " in '" + text.trim() + "'");
            return null;
        }
        Resolver r = new Resolver(src, scope, diags);
        StringBuilder rewritten = new StringBuilder();
        Map<String, Function> functions = new HashMap<>();
        for (int i = 0; i < tokens.size(); i++) {
            Lexer.Token t = tokens.get(i);
            boolean call = t.type() == Type.NAME && i + 1 < tokens.size() && tokens.get(i + 1).type() == Type.LPAREN;
            if (call) {
                rewritten.append(r.function(t, argCounts[i], functions));
            } else if (t.type() == Type.NUMBER || t.type() == Type.NAME || t.type() == Type.DOLLAR
                    || t.type() == Type.STRING) {
                rewritten.append(r.operand(t));
            } else {
                rewritten.append(t.text());
            }
            rewritten.append(' ');
        }
        if (r.failed) {
            return null;
        }
        Node root;
        try {
            Token[] rpn = ShuntingYard.convertToRPN(rewritten.toString(), functions, OPERATORS,
                    r.variableNames(), false);
            root = build(rpn, r.nodes);
        } catch (RuntimeException e) {
            diags.error(src.pos(), "cannot parse expression '" + text.trim() + "': " + e.getMessage());
            return null;
        }
        return new Result(new Expression(text.trim(), src.pos(), root, r.perModule), r.perModule, List.copyOf(r.locals));
    }

    private static Node build(Token[] rpn, List<Node> vars) {
        List<Node> stack = new ArrayList<>();
        for (Token t : rpn) {
            switch (t.getType()) {
                case Token.TOKEN_NUMBER:
                    stack.add(new Nodes.Const(((NumberToken) t).getValue()));
                    break;
                case Token.TOKEN_VARIABLE:
                    stack.add(vars.get(Integer.parseInt(((VariableToken) t).getName().substring(1))));
                    break;
                case Token.TOKEN_OPERATOR:
                    stack.add(fold(operator(((OperatorToken) t).getOperator(), stack)));
                    break;
                case Token.TOKEN_FUNCTION:
                    stack.add(fold(function(((FunctionToken) t).getFunction(), stack)));
                    break;
                default:
                    throw new IllegalStateException("unexpected token in RPN");
            }
        }
        if (stack.size() != 1) {
            throw new IllegalStateException("malformed expression");
        }
        return stack.get(0);
    }

    private static Node pop(List<Node> stack) {
        return stack.remove(stack.size() - 1);
    }

    private static Node operator(Operator op, List<Node> stack) {
        if (op.getNumOperands() == 1) {
            Node a = pop(stack);
            switch (op.getSymbol()) {
                case "-": return new Nodes.Unary(false, a);
                case "!": return new Nodes.Unary(true, a);
                default: return a;
            }
        }
        Node b = pop(stack);
        Node a = pop(stack);
        switch (op.getSymbol()) {
            case "&&": return new Nodes.Logic(true, a, b);
            case "||": return new Nodes.Logic(false, a, b);
            default:
                int code = List.of(Nodes.Binary.SYMBOLS).indexOf(op.getSymbol());
                return new Nodes.Binary(code, a, b);
        }
    }

    private static Node function(Function f, List<Node> stack) {
        String name = f.getName();
        int n = f.getNumArguments();
        Node[] args = new Node[n];
        for (int i = n - 1; i >= 0; i--) {
            args[i] = pop(stack);
        }
        if (name.startsWith("sum")) {
            return new Nodes.Sum(args);
        }
        switch (name) {
            case "if": return new Nodes.If(args[0], args[1], args[2]);
            case "rand": return new Nodes.Rand();
            case "atan2": case "mod": case "min": case "max":
                return new Nodes.Func2(Functions.F2.valueOf(name.toUpperCase(Locale.ROOT)), args[0], args[1]);
            default:
                return new Nodes.Func1(Functions.F1.valueOf(name.toUpperCase(Locale.ROOT)), args[0]);
        }
    }

    /** Replaces a node whose inputs are all constant by its value, unless evaluating fails. */
    private static Node fold(Node n) {
        if (n instanceof Nodes.Rand || !Fold.childrenConstant(n)) {
            return n;
        }
        try {
            return new Nodes.Const(n.eval(FOLD));
        } catch (EvalException e) {
            return n; // fails at run time, where the error names the tick
        }
    }

    private static Map<String, Operator> operators() {
        Map<String, Operator> ops = new HashMap<>();
        addOp(ops, "!", 1, false, Operator.PRECEDENCE_UNARY_MINUS);
        addOp(ops, "||", 2, true, 100);
        addOp(ops, "&&", 2, true, 200);
        for (String s : List.of("==", "!=")) {
            addOp(ops, s, 2, true, 300);
        }
        for (String s : List.of("<", ">", "<=", ">=")) {
            addOp(ops, s, 2, true, 400);
        }
        return Map.copyOf(ops);
    }

    private static void addOp(Map<String, Operator> ops, String symbol, int n, boolean left, int precedence) {
        ops.put(symbol, new Operator(symbol, n, left, precedence) {
            @Override
            public double apply(double... args) {
                throw new UnsupportedOperationException("PARSL evaluates its own node tree");
            }
        });
    }

    /** Resolves names to nodes and emits exp4j variable names for them. */
    private static final class Resolver {
        final XText src;
        final Scope scope;
        final DiagnosticSink diags;
        final List<Node> nodes = new ArrayList<>();
        final List<LocalUse> locals = new ArrayList<>();
        boolean failed;
        boolean perModule;

        Resolver(XText src, Scope scope, DiagnosticSink diags) {
            this.src = src;
            this.scope = scope;
            this.diags = diags;
        }

        Set<String> variableNames() {
            Set<String> names = new HashSet<>();
            for (int i = 0; i < nodes.size(); i++) {
                names.add("v" + i);
            }
            return names;
        }

        String function(Lexer.Token t, int args, Map<String, Function> functions) {
            String name = t.text();
            int arity = Functions.arity(name);
            if (arity == -1 || !name.equals(name.toLowerCase(Locale.ROOT))) {
                error(t, "unknown function '" + name + "()'" + Names.suggest(name, Names.FUNCTIONS));
                return "rand";
            }
            String key = arity == -2 ? "sum" + args : name;
            functions.computeIfAbsent(key, k -> new Function(k, arity == -2 ? args : arity) {
                @Override
                public double apply(double... a) {
                    throw new UnsupportedOperationException("PARSL evaluates its own node tree");
                }
            });
            return key;
        }

        String operand(Lexer.Token t) {
            Node n;
            switch (t.type()) {
                case NUMBER: n = number(t); break;
                case STRING: n = word(t); break;
                case DOLLAR: n = dollar(t); break;
                default: n = bare(t); break;
            }
            nodes.add(n == null ? new Nodes.Const(0) : n);
            return "v" + (nodes.size() - 1);
        }

        private Node number(Lexer.Token t) {
            double v = Double.parseDouble(t.text());
            if (!Double.isFinite(v)) {
                error(t, "the number " + t.text() + " is too large");
                return null;
            }
            return new Nodes.Const(v);
        }

        private Node word(Lexer.Token t) {
            Integer code = scope.kind() == Scope.Kind.PARAMETERS_ONLY ? null : scope.radioWords().get(t.text());
            if (code == null) {
                error(t, "\"" + t.text() + "\" is not a radio word; string literals are only for radio words"
                        + Names.suggest(t.text(), scope.radioWords().keySet()));
                return null;
            }
            return new Nodes.Const(code);
        }

        private Node bare(Lexer.Token t) {
            String name = t.text();
            switch (name) {
                case "pi": return new Nodes.Const(Math.PI);
                case "e": return new Nodes.Const(Math.E);
                case "true": return new Nodes.Const(1);
                case "false": return new Nodes.Const(0);
                default: break;
            }
            if (scope.parameters().containsKey(name)) {
                return new Nodes.Const(scope.parameters().get(name));
            }
            if (scope.macros().containsKey(name)) {
                return new Nodes.MacroRef(scope.macros().get(name));
            }
            if (scope.kind() != Scope.Kind.PARAMETERS_ONLY && scope.radioWords().containsKey(name)) {
                return new Nodes.Const(scope.radioWords().get(name));
            }
            if (scope.groupMacros().contains(name)) {
                error(t, "macro '" + name + "' names a group; it cannot be used in an arithmetic expression");
            } else if (scope.groups().contains(name)) {
                error(t, "'" + name + "' is a group; groups cannot be used in expressions");
            } else if (scope.controls().containsKey(name)) {
                error(t, "control '" + name + "' is written '$" + name + "' in expressions");
            } else if (Functions.arity(name) != -1) {
                error(t, "'" + name + "' is a function; call it as " + name + "(...)");
            } else {
                List<String> known = new ArrayList<>(scope.parameters().keySet());
                known.addAll(scope.macros().keySet());
                known.addAll(scope.radioWords().keySet());
                known.addAll(CONSTANTS);
                String where = scope.kind() == Scope.Kind.PARAMETERS_ONLY ? " (only parameters are allowed here)" : "";
                error(t, "unknown name '" + name + "'" + where + Names.suggest(name, known));
            }
            return null;
        }

        private Node dollar(Lexer.Token t) {
            String name = t.text();
            if (Scope.LOGICAL.contains(name)) {
                if (!scope.sees(name)) {
                    error(t, "'$" + name + "' is not available here" + logicalWhere(name));
                    return null;
                }
                int which = Scope.LOGICAL.indexOf(name);
                perModule |= which == Nodes.Var.INDEX || which == Nodes.Var.ID || which == Nodes.Var.PHASE
                        || which == Nodes.Var.CYCLE;
                return new Nodes.Var(which);
            }
            if (scope.controls().containsKey(name)) {
                return new Nodes.ControlRef(scope.controls().get(name));
            }
            Matcher g = GLOBAL.matcher(name);
            if (g.matches()) {
                return globalSensor(t, g);
            }
            Matcher l = LOCAL.matcher(name);
            if (l.matches()) {
                return localSensor(t, l);
            }
            List<String> known = new ArrayList<>();
            scope.controls().keySet().forEach(c -> known.add(c));
            known.addAll(Scope.LOGICAL);
            error(t, "unknown control or variable '$" + name + "'" + Names.suggest(name, known, "$"));
            return null;
        }

        private Channel channel(Lexer.Token t, String sensor, String arg) {
            if (!List.of("angle", "accel", "touch").contains(sensor)) {
                error(t, "sensor '" + sensor + "' is not implemented; available: angle, accel, touch");
                return null;
            }
            Channel c = Channel.of(sensor, arg == null ? "" : arg);
            if (c == null) {
                error(t, sensor.equals("angle") ? "the angle sensor takes no argument"
                        : sensor.equals("accel") ? "accel needs an axis: _x, _y or _z"
                        : "touch needs a side: _left or _right");
            }
            return c;
        }

        private Node globalSensor(Lexer.Token t, Matcher m) {
            if (scope.sensors() == null) {
                error(t, "sensor references are not allowed here");
                return null;
            }
            Channel c = channel(t, m.group(2), m.group(3));
            if (c == null) {
                return null;
            }
            int id = m.group(1).length() > 7 ? -1 : Integer.parseInt(m.group(1));
            int index = id < 0 ? -1 : scope.sensors().moduleIndex(id);
            if (index < 0) {
                error(t, "module " + m.group(1) + " is not part of the robot");
                return null;
            }
            if (!scope.sensors().carries(id, c)) {
                error(t, "module " + id + " has no " + c.sensor() + " sensor (declare it in <sensors>)");
                return null;
            }
            return new Nodes.GlobalSensor(Nodes.slot(index, c.ordinal()));
        }

        private Node localSensor(Lexer.Token t, Matcher m) {
            if (scope.kind() != Scope.Kind.MODULE) {
                error(t, "local sensor references ($_" + m.group(1) + "_...) are only allowed in states, times and exit conditions");
                return null;
            }
            Channel c = channel(t, m.group(2), m.group(3));
            if (c == null) {
                return null;
            }
            String which = m.group(1);
            int position = which.equals("self") ? Nodes.LocalSensor.SELF : which.equals("prev") ? Nodes.LocalSensor.PREV
                    : which.equals("next") ? Nodes.LocalSensor.NEXT : which.length() > 7 ? Integer.MAX_VALUE : Integer.parseInt(which);
            perModule = true;
            locals.add(new LocalUse(position, c, src.posAt(t.start()), "$" + t.text()));
            return new Nodes.LocalSensor(position, c.ordinal());
        }

        private static String logicalWhere(String name) {
            switch (name) {
                case "count": return " ($count is defined in states, times and instance attributes)";
                case "time": case "btime": return " (only parameters are allowed here)";
                default: return " ($" + name + " is defined in states and automaton times)";
            }
        }

        private void error(Lexer.Token t, String message) {
            diags.error(src.posAt(t.start()), message);
            failed = true;
        }
    }
}
