package org.parpe.core.expr;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
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
import org.parpe.core.sensor.Channel;
import org.parpe.core.xml.XText;
import org.parpe.core.text.Msg;

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
    }

    /** A compiled expression with what the loader needs to check it further. */
    public record Result(Expression expression, boolean perModule, List<LocalUse> locals) {
    }

    private static final Map<String, Operator> OPERATORS = operators();
    private static final EvalContext FOLD = new EvalContext();

    private ExprCompiler() {
    }

    /** Compiles {@code src} in {@code scope}; returns {@code null} after reporting errors. */
    public static Result compile(XText src, Scope scope, DiagnosticSink diags) {
        String text = src.value();
        List<Lexer.Token> tokens;
        try {
            tokens = Lexer.lex(text);
        } catch (Lexer.LexError e) {
            diags.error(src.posAt(e.index), Msg.IN_EXPRESSION, e.text, text.trim());
            return null;
        }
        int[] argCounts = new int[tokens.size()];
        Syntax.Problem p = Syntax.check(tokens, argCounts);
        if (p != null) {
            diags.error(src.posAt(p.index()), Msg.IN_EXPRESSION, p.message(), text.trim());
            return null;
        }
        NameResolver r = new NameResolver(src, scope, diags);
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
            diags.error(src.pos(), Msg.CANNOT_PARSE_EXPRESSION, text.trim(), e.getMessage());
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
                    throw new IllegalStateException(Msg.UNEXPECTED_TOKEN.text());
            }
        }
        if (stack.size() != 1) {
            throw new IllegalStateException(Msg.MALFORMED_EXPRESSION.text());
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
            case "&&": return new Nodes.And(a, b);
            case "||": return new Nodes.Or(a, b);
            default:
                int code = List.of(Nodes.Binary.SYMBOLS).indexOf(op.getSymbol());
                return Nodes.Binary.of(code, a, b);
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
                return Nodes.Func1.of(Functions.F1.valueOf(name.toUpperCase(Locale.ROOT)), args[0]);
        }
    }

    /** Replaces a node whose inputs are all constant by its value, unless evaluating fails. */
    static Node fold(Node n) {
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
}
