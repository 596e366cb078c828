package org.parpe.core.expr;

import java.util.ArrayList;
import java.util.List;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;

/** Splits an expression into tokens with their character positions. */
final class Lexer {
    enum Type { NUMBER, NAME, DOLLAR, STRING, OP, LPAREN, RPAREN, COMMA }

    record Token(Type type, String text, int start, int end) {
    }

    /** Thrown for a character that starts no token. */
    static final class LexError extends Exception {
        final int index;
        final Message text;

        LexError(Message text, int index) {
            super(text.format(java.util.Locale.ENGLISH), null, false, false);
            this.index = index;
            this.text = text;
        }
    }

    private static final String[] OPS = {"||", "&&", "==", "!=", "<=", ">=", "<", ">", "+", "-", "*", "/", "%", "^", "!"};

    private Lexer() {
    }

    static List<Token> lex(String s) throws LexError {
        List<Token> out = new ArrayList<>();
        int i = 0;
        while (i < s.length()) {
            char c = s.charAt(i);
            if (Character.isWhitespace(c)) {
                i++;
            } else if (isDigit(c) || c == '.' && i + 1 < s.length() && isDigit(s.charAt(i + 1))) {
                int end = number(s, i);
                out.add(new Token(Type.NUMBER, s.substring(i, end), i, end));
                i = end;
            } else if (isNameStart(c)) {
                int end = nameEnd(s, i);
                out.add(new Token(Type.NAME, s.substring(i, end), i, end));
                i = end;
            } else if (c == '$') {
                int end = i + 1;
                while (end < s.length() && (Character.isLetterOrDigit(s.charAt(end)) && s.charAt(end) < 128 || s.charAt(end) == '_')) {
                    end++;
                }
                if (end == i + 1) {
                    throw new LexError(Message.of(Msg.DOLLAR_ALONE), i);
                }
                out.add(new Token(Type.DOLLAR, s.substring(i + 1, end), i, end));
                i = end;
            } else if (c == '"') {
                int close = s.indexOf('"', i + 1);
                if (close < 0) {
                    throw new LexError(Message.of(Msg.UNTERMINATED_STRING), i);
                }
                out.add(new Token(Type.STRING, s.substring(i + 1, close), i, close + 1));
                i = close + 1;
            } else if (c == '(' || c == ')' || c == ',') {
                Type t = c == '(' ? Type.LPAREN : c == ')' ? Type.RPAREN : Type.COMMA;
                out.add(new Token(t, String.valueOf(c), i, i + 1));
                i++;
            } else {
                String op = operator(s, i);
                if (op == null) {
                    throw new LexError(c == '=' ? Message.of(Msg.SINGLE_EQUALS)
                            : c == '&' ? Message.of(Msg.SINGLE_AMPERSAND)
                            : c == '|' ? Message.of(Msg.SINGLE_BAR)
                            : Character.isDigit(c) ? Message.of(Msg.NOT_ASCII_DIGIT, c,
                                    String.format(java.util.Locale.ROOT, "%04X", (int) c))
                            : Message.of(Msg.UNEXPECTED_CHARACTER, c), i);
                }
                out.add(new Token(Type.OP, op, i, i + op.length()));
                i += op.length();
            }
        }
        return out;
    }

    private static String operator(String s, int i) {
        for (String op : OPS) {
            if (s.startsWith(op, i)) {
                return op;
            }
        }
        return null;
    }

    /** Only ASCII digits: {@link Character#isDigit} accepts every script's digits, which Java cannot parse. */
    private static boolean isDigit(char c) {
        return c >= '0' && c <= '9';
    }

    static boolean isNameStart(char c) {
        return c < 128 && (Character.isLetter(c) || c == '_');
    }

    private static int nameEnd(String s, int i) {
        int end = i;
        while (end < s.length() && s.charAt(end) < 128 && (Character.isLetterOrDigit(s.charAt(end)) || s.charAt(end) == '_')) {
            end++;
        }
        return end;
    }

    private static int number(String s, int i) {
        int end = i;
        while (end < s.length() && isDigit(s.charAt(end))) {
            end++;
        }
        if (end < s.length() && s.charAt(end) == '.') {
            end++;
            while (end < s.length() && isDigit(s.charAt(end))) {
                end++;
            }
        }
        if (end < s.length() && (s.charAt(end) == 'e' || s.charAt(end) == 'E')) {
            int e = end + 1;
            if (e < s.length() && (s.charAt(e) == '+' || s.charAt(e) == '-')) {
                e++;
            }
            if (e < s.length() && isDigit(s.charAt(e))) {
                while (e < s.length() && isDigit(s.charAt(e))) {
                    e++;
                }
                end = e;
            }
        }
        return end;
    }
}
