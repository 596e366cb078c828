package org.parpe.core.text;

import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.PrintStream;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.function.UnaryOperator;

/** The encoding of standard output and error: what the user's terminal reads. */
public final class Terminal {
    private Terminal() {
    }

    /**
     * Writes UTF-8 to standard output and error when the locale variables name a UTF-8 locale
     * ({@code LC_ALL}, else {@code LC_CTYPE}, else {@code LANG}) but Java chose another encoding:
     * the JVM falls back to ASCII where the named locale is not installed (a fresh container with
     * {@code LANG=de_DE.UTF-8}), and would print umlauts and Japanese as {@code ?}. Returns the
     * encoding the streams write now.
     */
    public static Charset utf8WhereNamed(UnaryOperator<String> env) {
        String chosen = null;
        for (String v : new String[] {"LC_ALL", "LC_CTYPE", "LANG"}) {
            String value = env.apply(v);
            if (value != null && !value.isEmpty()) {
                chosen = value.toLowerCase(Locale.ROOT);
                break;
            }
        }
        if (chosen != null && (chosen.contains("utf-8") || chosen.contains("utf8"))
                && !Charset.defaultCharset().equals(StandardCharsets.UTF_8)) {
            System.setOut(new PrintStream(new FileOutputStream(FileDescriptor.out), true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(new FileOutputStream(FileDescriptor.err), true, StandardCharsets.UTF_8));
            return StandardCharsets.UTF_8;
        }
        return Charset.defaultCharset();
    }
}
