package org.parpe.core.text;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * The translators' check of code: the string literals of a Java source that read as prose, that
 * is, texts for a user that bypass the bundles. Comments, annotations' arguments, PARSL snippets
 * and the arguments of exceptions that report a fault of PARPE's own are left out. Each module's
 * text test runs it over its main code with an allow-list by reason (file formats, crash reports).
 */
public final class ProseLiterals {
    /** Two letters, a space and a letter: words; or a capitalised word; or a letter outside ASCII. */
    private static final Pattern PROSE = Pattern.compile("\\p{L}{2,}[,;:!?.]*\\s+\\p{L}|^[\\p{Lu}][\\p{Ll}]+|[\\p{L}&&[^\\x00-\\x7f]]");

    /** A PARSL snippet (an element with attributes, or an element's name in brackets): the file format, English on purpose. */
    private static final Pattern PARSL = Pattern.compile("<[a-z][\\w-]*(\\s+[\\w-]+=\"|\\s*/?>)|^<[a-z][\\w-]*>$|^<\\?xml |<!-- ");

    /** Arguments of these are a fault of PARPE's own, shown as an internal error with its crash file. */
    private static final Pattern INTERNAL = Pattern.compile(
            "new (IllegalStateException|AssertionError|UnsupportedOperationException|BadLocationException)\\(");

    private ProseLiterals() {
    }

    /**
     * {@link #in} over every {@code .java} file under {@code main}'s {@code org/parpe} that
     * {@code skipped} does not take (it sees the path from {@code main}, with {@code /}).
     */
    public static List<String> inTree(Path main, Predicate<String> skipped, Predicate<String> allowed) throws IOException {
        List<String> out = new ArrayList<>();
        try (Stream<Path> s = Files.walk(main.resolve("org/parpe"))) {
            for (Path p : (Iterable<Path>) s.filter(p -> p.toString().endsWith(".java")).sorted()::iterator) {
                String file = main.relativize(p).toString().replace('\\', '/');
                if (!skipped.test(file)) {
                    out.addAll(in(file, Files.readString(p), allowed));
                }
            }
        }
        return out;
    }

    /**
     * The literals of {@code java} (comments and annotations left out) that read as prose and
     * that {@code allowed} does not take (it sees the literal's text, escapes resolved), one per
     * line: {@code FILE:LINE: "text"} with the text as the source writes it.
     */
    public static List<String> in(String file, String java, Predicate<String> allowed) {
        List<String> out = new ArrayList<>();
        int line = 1;
        int annotationDepth = -1;
        int depth = 0;
        for (int i = 0; i < java.length(); i++) {
            char c = java.charAt(i);
            if (c == '\n') {
                line++;
            } else if (java.startsWith("//", i)) {
                i = java.indexOf('\n', i) - 1;
                if (i < 0) {
                    break;
                }
            } else if (java.startsWith("/*", i)) {
                int end = java.indexOf("*/", i + 2);
                line += count(java.substring(i, end), '\n');
                i = end + 1;
            } else if (c == '\'') {
                i = java.indexOf('\'', i + (java.charAt(i + 1) == '\\' ? 3 : 2));
            } else if (c == '@' && Character.isUpperCase(java.charAt(i + 1)) && annotationDepth < 0) {
                int open = i + 1;
                while (open < java.length() && Character.isJavaIdentifierPart(java.charAt(open))) {
                    open++;
                }
                if (open < java.length() && java.charAt(open) == '(') {
                    annotationDepth = depth;
                }
            } else if (c == '(') {
                depth++;
            } else if (c == ')') {
                depth--;
                if (depth == annotationDepth) {
                    annotationDepth = -1;
                }
            } else if (c == '"') {
                boolean block = java.startsWith("\"\"\"", i);
                int end = literalEnd(java, i);
                String literal = java.substring(i + (block ? 3 : 1), end);
                // the statement up to the literal: its start is after the last ';', '{' or '}'
                int start = Math.max(java.lastIndexOf(';', i), Math.max(java.lastIndexOf('{', i), java.lastIndexOf('}', i)));
                String before = java.substring(start + 1, i);
                String text = unescape(literal);
                if (annotationDepth < 0 && !allowed.test(text) && !PARSL.matcher(text).find() && PROSE.matcher(text).find()
                        && !INTERNAL.matcher(before).find()) {
                    out.add(file + ":" + line + ": \"" + literal + "\"");
                }
                line += count(literal, '\n');
                i = end + (block ? 2 : 0);
            }
        }
        return out;
    }

    /** Where the literal opening at {@code i} ends: its closing quote (of a text block, the first of three). */
    private static int literalEnd(String java, int i) {
        if (java.startsWith("\"\"\"", i)) {
            return java.indexOf("\"\"\"", i + 3);
        }
        int end = i + 1;
        while (java.charAt(end) != '"') {
            end += java.charAt(end) == '\\' ? 2 : 1;
        }
        return end;
    }

    private static String unescape(String literal) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < literal.length(); i++) {
            char c = literal.charAt(i);
            if (c == '\\' && literal.charAt(i + 1) == 'u') {
                b.append((char) Integer.parseInt(literal.substring(i + 2, i + 6), 16));
                i += 5;
            } else if (c == '\\') {
                char n = literal.charAt(++i);
                b.append(n == 't' ? '\t' : n == 'n' ? '\n' : n);
            } else {
                b.append(c);
            }
        }
        return b.toString();
    }

    private static int count(String s, char c) {
        return (int) s.chars().filter(x -> x == c).count();
    }
}
