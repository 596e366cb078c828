package org.parpe.core.export;

/** Pieces of C text shared by the generators. */
final class CText {
    private CText() {
    }

    /** Names compared in flash on AVR. */
    static final String PRELUDE = """
            #if defined(__AVR__)
            #define PARSL_IS(s, word) (strcmp_P((s), PSTR(word)) == 0)
            #else
            #define PARSL_IS(s, word) (strcmp((s), (word)) == 0)
            #endif

            """;

    /** {@code s} as the inside of a C string literal. */
    static String escape(String s) {
        StringBuilder b = new StringBuilder();
        for (char c : s.toCharArray()) {
            if (c == '"' || c == '\\') {
                b.append('\\').append(c);
            } else if (c < 32 || c > 126) {
                b.append(String.format("\\%03o", (int) c & 0xff));
            } else if (c == '?') {
                b.append("\\?"); // no trigraphs
            } else {
                b.append(c);
            }
        }
        return b.toString();
    }
}
