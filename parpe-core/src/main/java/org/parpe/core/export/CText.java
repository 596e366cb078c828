package org.parpe.core.export;

import java.nio.charset.StandardCharsets;

/** Pieces of C text shared by the generators (and by parpe-serial's sketch writer). */
public final class CText {
    /** The longest string literal a C99 compiler must accept (C99 5.2.4.1; gcc -pedantic warns above it). */
    static final int MAX_LITERAL = 4095;

    private CText() {
    }

    /** Names compared in flash on AVR. */
    static final String PRELUDE = """
            #if defined(__AVR__)
            #define PARSL_IS(s, word) (strcmp_P((s), PSTR(word)) == 0)
            #else
            #define PARSL_IS(s, word) (strcmp((s), (word)) == 0)
            #endif
            #if defined(__AVR__) && defined(__GNUC__)
            /* avr-gcc would turn the switch of parsl_expr into a lookup table in RAM (.data). */
            #define PARSL_NO_TABLE __attribute__((optimize("no-tree-switch-conversion")))
            #else
            #define PARSL_NO_TABLE
            #endif

            """;

    /**
     * The values of sub-expressions kept per module ({@link ModuleConstants}): a format of the
     * count of values and of positions (the instances' groups), twice. Not on AVR boards, whose
     * RAM (2 KB) they would take, and where the code is then what it was without them.
     */
    static final String KEEP = """
            #if !defined(__AVR__)
            /* Sub-expressions of angles that are the same for a module at every tick: computed at its
               first tick, then read, by instance and position (r->group_off + r->index). */
            #define PARSL_KEEP 1
            static double parsl_kept[%d][%d];
            static uint8_t parsl_kept_ok[%d][%d];
            #endif

            """;

    /**
     * {@code s} made safe for a C comment or a {@code //} line: only printable ASCII, without
     * {@code \\} (a line splice), {@code ?} (trigraphs such as {@code ??/}), and no {@code *} next
     * to a {@code /} (which would end the comment or open one inside it);
     * everything else, line breaks included, becomes {@code _}. File and folder names go into
     * comments through this only, so no name can end a comment or splice the next line into it.
     */
    public static String comment(String s) {
        StringBuilder b = new StringBuilder();
        for (char c : s.toCharArray()) {
            char prev = b.length() == 0 ? ' ' : b.charAt(b.length() - 1);
            boolean ok = c >= 32 && c <= 126 && c != '\\' && c != '?' && !(c == '/' && prev == '*')
                    && !(c == '*' && prev == '/');
            b.append(ok ? c : '_');
        }
        return b.toString();
    }

    /**
     * {@code s} as a C string expression: a literal whose bytes are {@code s} in UTF-8 (anything
     * outside printable ASCII as octal escapes), or, when it would be longer than C99's
     * {@value #MAX_LITERAL} characters, a compound literal array of the same bytes.
     */
    static String literal(String s) {
        byte[] bytes = s.getBytes(StandardCharsets.UTF_8);
        if (bytes.length <= MAX_LITERAL) {
            return "\"" + escape(s) + "\"";
        }
        StringBuilder b = new StringBuilder("(const char[]){");
        for (byte x : bytes) {
            b.append(String.format("'\\%03o', ", x & 0xff));
        }
        return b.append("0}").toString();
    }

    /** {@code s} in UTF-8 as the inside of a C string literal. */
    static String escape(String s) {
        StringBuilder b = new StringBuilder();
        for (byte x : s.getBytes(StandardCharsets.UTF_8)) {
            int c = x & 0xff;
            if (c == '"' || c == '\\') {
                b.append('\\').append((char) c);
            } else if (c < 32 || c > 126) {
                b.append(String.format("\\%03o", c));
            } else if (c == '?') {
                b.append("\\?"); // no trigraphs
            } else {
                b.append((char) c);
            }
        }
        return b.toString();
    }
}
