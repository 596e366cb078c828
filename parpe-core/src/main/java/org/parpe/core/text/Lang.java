package org.parpe.core.text;

import java.util.List;
import java.util.Locale;
import java.util.function.UnaryOperator;

/**
 * The language PARPE speaks, chosen once per process. Until a program's entry point calls
 * {@link #use}, it is English, whatever the machine's locale: tests, golden traces and
 * conformance outputs are English unless a command asks otherwise (docs/decisions.md,
 * "Language of messages").
 */
public final class Lang {
    /** The languages PARPE has bundles for, English first. */
    public static final List<Locale> SUPPORTED = List.of(Locale.ENGLISH, Locale.GERMAN,
            Locale.forLanguageTag("es"), Locale.JAPANESE);

    /**
     * The pseudo-language {@code qps} ({@link Pseudo}): English made longer and accented, to test
     * layouts. Chosen only by {@code --lang qps}, never by the environment, and not one of
     * {@link #SUPPORTED} (a student's language list does not offer it).
     */
    public static final Locale PSEUDO = Locale.forLanguageTag("qps");

    /** The environment variables that name a language, strongest first (POSIX). */
    public static final List<String> VARIABLES = List.of("LC_ALL", "LC_MESSAGES", "LANG");

    private static volatile Locale current = Locale.ENGLISH;

    private Lang() {
    }

    /** The chosen language. */
    public static Locale current() {
        return current;
    }

    /** Makes {@code locale} (one of {@link #SUPPORTED}, or {@link #PSEUDO}) the language of every later text. */
    public static void use(Locale locale) {
        Locale l = isPseudo(locale) ? PSEUDO : supported(locale.getLanguage());
        current = l == null ? Locale.ENGLISH : l;
    }

    /** Whether {@code locale} is the pseudo-language {@link #PSEUDO}. */
    public static boolean isPseudo(Locale locale) {
        return PSEUDO.getLanguage().equals(locale.getLanguage());
    }

    /**
     * The language of a code given by the user ({@code de}, {@code de_DE}, {@code ja-JP}), or
     * {@code null} when PARPE does not speak it. {@code qps} (also {@code qps-ploc}) is
     * {@link #PSEUDO}.
     */
    public static Locale parse(String code) {
        String language = language(code);
        return language.equals(PSEUDO.getLanguage()) ? PSEUDO : supported(language);
    }

    /**
     * The language the environment asks for: the first of {@code LC_ALL}, {@code LC_MESSAGES},
     * {@code LANG} that is set and not empty decides (as POSIX has it); its language if PARPE
     * speaks it, else English ({@code C}, {@code POSIX}, {@code fr_FR.UTF-8}, nothing set).
     */
    public static Locale fromEnvironment(UnaryOperator<String> env) {
        for (String v : VARIABLES) {
            String value = env.apply(v);
            if (value != null && !value.isEmpty()) {
                Locale l = supported(language(value));
                return l == null ? Locale.ENGLISH : l;
            }
        }
        return Locale.ENGLISH;
    }

    /** The codes of {@link #SUPPORTED}, e.g. {@code en, de, es, ja}. */
    public static String codes() {
        return String.join(", ", SUPPORTED.stream().map(Locale::getLanguage).toList());
    }

    /** {@code de_DE.UTF-8@euro} → {@code de}. */
    private static String language(String code) {
        String s = code.trim();
        int cut = s.length();
        for (char c : new char[] {'_', '-', '.', '@'}) {
            int i = s.indexOf(c);
            if (i >= 0) {
                cut = Math.min(cut, i);
            }
        }
        return s.substring(0, cut).toLowerCase(Locale.ROOT);
    }

    private static Locale supported(String language) {
        for (Locale l : SUPPORTED) {
            if (l.getLanguage().equals(language)) {
                return l;
            }
        }
        return null;
    }
}
