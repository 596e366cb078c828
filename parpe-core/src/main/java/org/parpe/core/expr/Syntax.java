package org.parpe.core.expr;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import org.parpe.core.expr.Lexer.Token;
import org.parpe.core.expr.Lexer.Type;
import org.parpe.core.lang.Vocabulary;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;

/**
 * Checks the token sequence of an expression (operand/operator alternation, parentheses,
 * function arity) so that syntax errors get a precise column and a plain message before the
 * expression reaches exp4j. Records the argument count of every call.
 */
final class Syntax {
    /** A syntax error at a character index. */
    record Problem(Message message, int index) {
        Problem(Msg key, int index, Object... args) {
            this(Message.of(key, args), index);
        }
    }

    private record Frame(boolean call, Token open, String function, int[] args) {
    }

    private Syntax() {
    }

    /** Returns the first problem, or {@code null}; fills {@code argCounts[i]} for call tokens. */
    static Problem check(List<Token> tokens, int[] argCounts) {
        if (tokens.isEmpty()) {
            return new Problem(Msg.EMPTY_EXPRESSION, 0);
        }
        Deque<Frame> frames = new ArrayDeque<>();
        boolean expectOperand = true;
        for (int i = 0; i < tokens.size(); i++) {
            Token t = tokens.get(i);
            Token next = i + 1 < tokens.size() ? tokens.get(i + 1) : null;
            if (expectOperand) {
                if (t.type() == Type.NAME && next != null && next.type() == Type.LPAREN) {
                    frames.push(new Frame(true, next, t.text(), new int[] {i, 0}));
                    i++;
                    if (i + 1 < tokens.size() && tokens.get(i + 1).type() == Type.RPAREN) {
                        Problem p = close(frames.pop(), argCounts, tokens.get(i + 1), true);
                        if (p != null) {
                            return p;
                        }
                        i++;
                        expectOperand = false;
                    }
                } else if (t.type() == Type.NUMBER || t.type() == Type.NAME || t.type() == Type.DOLLAR
                        || t.type() == Type.STRING) {
                    expectOperand = false;
                } else if (t.type() == Type.LPAREN) {
                    frames.push(new Frame(false, t, null, null));
                } else if (t.type() == Type.OP && (t.text().equals("-") || t.text().equals("+") || t.text().equals("!"))) {
                    continue;
                } else {
                    return new Problem(Msg.VALUE_EXPECTED_BEFORE, t.start(), t.text());
                }
            } else {
                Problem p = afterOperand(tokens, i, frames, argCounts);
                if (p != null) {
                    return p;
                }
                expectOperand = t.type() == Type.OP || t.type() == Type.COMMA;
            }
        }
        Token last = tokens.get(tokens.size() - 1);
        if (expectOperand) {
            return new Problem(Msg.VALUE_EXPECTED_AFTER, last.start(), last.text());
        }
        if (!frames.isEmpty()) {
            return new Problem(Msg.UNCLOSED_OPEN, frames.peek().open().start());
        }
        return null;
    }

    /**
     * Checks token {@code i}, which follows an operand: an operator, a parenthesis closing a
     * group or call, or a comma between a call's arguments; returns the problem, or null.
     */
    private static Problem afterOperand(List<Token> tokens, int i, Deque<Frame> frames, int[] argCounts) {
        Token t = tokens.get(i);
        if (t.type() == Type.OP && !t.text().equals("!")) {
            return null;
        }
        if (t.type() == Type.RPAREN) {
            if (frames.isEmpty()) {
                return new Problem(Msg.UNMATCHED_CLOSE, t.start());
            }
            Frame f = frames.pop();
            return f.call() ? close(f, argCounts, t, false) : null;
        }
        if (t.type() == Type.COMMA) {
            if (frames.isEmpty() || !frames.peek().call()) {
                Token next = i + 1 < tokens.size() ? tokens.get(i + 1) : null;
                return new Problem(Msg.COMMA_OUTSIDE_CALL, t.start(), decimalComma(tokens.get(i - 1), t, next));
            }
            frames.peek().args()[1]++;
            return null;
        }
        return new Problem(Msg.OPERATOR_MISSING, t.start(), t.text(), letterO(tokens.get(i - 1), t));
    }

    /**
     * What to type instead when {@code comma} is a decimal comma, {@code 0,25} (half of Europe
     * writes decimals so): a number, the comma and a number, with nothing between them.
     */
    private static Message decimalComma(Token before, Token comma, Token after) {
        if (before.type() == Type.NUMBER && after != null && after.type() == Type.NUMBER && before.end() == comma.start()
                && after.start() == comma.end() && !before.text().contains(".")) {
            return Message.of(Msg.DECIMAL_COMMA, before.text(), after.text());
        }
        return Message.EMPTY;
    }

    /**
     * What to type instead when {@code name} right after a number is made of the letter O where
     * the digit 0 (zero) was meant, as in {@code 3O}.
     */
    private static Message letterO(Token before, Token name) {
        if (before.type() == Type.NUMBER && name.type() == Type.NAME && before.end() == name.start()
                && name.text().matches("[oO][0-9oO]*")) {
            return Message.of(Msg.LETTER_O, before.text() + name.text().replace('o', '0').replace('O', '0'));
        }
        return Message.EMPTY;
    }

    private static Problem close(Frame f, int[] argCounts, Token at, boolean empty) {
        int n = empty ? 0 : f.args()[1] + 1;
        argCounts[f.args()[0]] = n;
        int arity = Vocabulary.arity(f.function());
        if (arity == -1) {
            return null; // an unknown function is reported by name resolution
        }
        if (arity == -2) {
            return n >= 1 ? null : new Problem(Msg.SUM_NEEDS_ARGUMENT, at.start());
        }
        if (n != arity) {
            return new Problem(arity == 1 ? Msg.ONE_ARGUMENT : Msg.N_ARGUMENTS, f.open().start(), f.function(), arity, n);
        }
        return null;
    }
}
