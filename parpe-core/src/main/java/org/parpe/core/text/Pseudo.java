package org.parpe.core.text;

import java.util.Collections;
import java.util.Enumeration;
import java.util.ResourceBundle;

/**
 * The pseudo-language {@code qps} ({@link Lang#PSEUDO}), a tester's language: every text of every
 * bundle is the English text with its letters accented, made about 40 % longer and put in
 * brackets ({@code Open file…} → {@code [Öþéñ fîłé… ~~~]}). A label that clips it, a layout
 * that cannot grow or a text glued together from pieces ({@code [Śåvé ~~] [fîłé ~~]}) shows at a
 * glance, in any window, before a translator writes a word. Placeholders ({@code {0}},
 * {@code {1,choice,…}}), {@link java.text.MessageFormat}'s quotes, mnemonics ({@code &F}) and a
 * menu item's accelerator after a tab stay as they are, so the text still formats and the keys
 * still work (docs/decisions.md, "The pseudo-language").
 */
public final class Pseudo {
    private static final String PLAIN = "aAbcCdeEgGhiIjklLnNoOpsSuUwyYzZ";
    private static final String ACCENTED = "åÅƀçÇđéÉĝĜĥîÎĵķłŁñÑöÖþšŠüÜŵýÝžŽ";

    private Pseudo() {
    }

    /**
     * The pseudo text of the {@link java.text.MessageFormat} pattern {@code english}: the same
     * placeholders, quotes, mnemonics and accelerator, every other letter accented, in brackets,
     * with {@code ~} added to make it about 40 % longer. Empty stays empty.
     */
    public static String text(String english) {
        if (english.isEmpty()) {
            return english;
        }
        int tab = english.indexOf('\t');
        String body = tab < 0 ? english : english.substring(0, tab);
        String accelerator = tab < 0 ? "" : english.substring(tab);
        return "[" + accented(body) + padding(body.length()) + "]" + accelerator;
    }

    /** {@code ~} for 40 % of {@code length} characters (at least one), after a space where there are several. */
    private static String padding(int length) {
        int n = Math.max(1, (length * 2 + 4) / 5);
        return n == 1 ? "~" : " " + "~".repeat(n - 1);
    }

    private static String accented(String pattern) {
        StringBuilder out = new StringBuilder(pattern.length());
        boolean quoted = false;
        for (int i = 0; i < pattern.length(); i++) {
            char c = pattern.charAt(i);
            if (c == '\'') {
                if (i + 1 < pattern.length() && pattern.charAt(i + 1) == '\'') {
                    out.append("''"); // an apostrophe, in quotes or not
                    i++;
                } else {
                    out.append(c);
                    quoted = !quoted;
                }
            } else if (c == '{' && !quoted) {
                int end = placeholderEnd(pattern, i);
                out.append(pattern, i, end);
                i = end - 1;
            } else if (c == '&' && i + 1 < pattern.length()) {
                out.append(c).append(pattern.charAt(i + 1)); // a mnemonic keeps its key; "&&" stays an ampersand
                i++;
            } else {
                int k = PLAIN.indexOf(c);
                out.append(k < 0 ? c : ACCENTED.charAt(k));
            }
        }
        return out.toString();
    }

    /** The index after the {@code }} that closes the placeholder opened at {@code start} (nested ones in it). */
    private static int placeholderEnd(String pattern, int start) {
        int depth = 0;
        for (int i = start; i < pattern.length(); i++) {
            char c = pattern.charAt(i);
            if (c == '{') {
                depth++;
            } else if (c == '}' && --depth == 0) {
                return i + 1;
            }
        }
        return pattern.length(); // unbalanced: MessageFormat rejects it in English too
    }

    /** {@code english} seen through {@link #text}: the same keys, every string value pseudo. */
    static ResourceBundle bundle(ResourceBundle english) {
        return new ResourceBundle() {
            @Override
            protected Object handleGetObject(String key) {
                Object v = english.getObject(key);
                return v instanceof String s ? text(s) : v;
            }

            @Override
            public Enumeration<String> getKeys() {
                return english.getKeys();
            }

            @Override
            protected java.util.Set<String> handleKeySet() {
                return Collections.unmodifiableSet(english.keySet());
            }
        };
    }
}
