package org.parpe.core.text;

import java.text.MessageFormat;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.ResourceBundle;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The translators' check of one bundle: for each language of {@link Lang#SUPPORTED}, the keys
 * its file lacks, the keys it has that no constant names, and the texts whose placeholders
 * ({@code {0}}, {@code {1}}, ...) differ from the English text's or that are not valid
 * {@link MessageFormat} patterns. {@code parpe i18n-check} prints it; tests require it empty.
 */
public final class BundleCheck {
    private static final Pattern PLACEHOLDER = Pattern.compile("\\{(\\d+)[^}]*}");

    private BundleCheck() {
    }

    /**
     * The keys of {@code keys} that {@code code} never names: a key counts as used where
     * {@code prefix} followed by its name stands as a word ({@code "SimMsg."} for code that always
     * writes the enum's name; {@code ""} for any mention). The translators' "unused keys" list.
     */
    public static List<String> unusedIn(CharSequence code, List<? extends Key> keys, String prefix) {
        List<String> unused = new ArrayList<>();
        for (Key k : keys) {
            if (!Pattern.compile((prefix.isEmpty() ? "\\b" : "") + Pattern.quote(prefix + k.name()) + "\\b").matcher(code).find()) {
                unused.add(k.name());
            }
        }
        return unused;
    }

    /**
     * The problems of bundle {@code base} against {@code keys} (the constants of its key enum),
     * one line each: {@code de: missing KEY}, {@code ja: unused KEY},
     * {@code es: KEY has placeholders [0, 2], English [0, 1]}; empty when all is well.
     */
    public static List<String> problems(String base, List<? extends Key> keys) {
        List<String> out = new ArrayList<>();
        Set<String> names = new TreeSet<>();
        keys.forEach(k -> names.add(k.name()));
        ResourceBundle english = own(base, Locale.ROOT);
        for (Locale l : Lang.SUPPORTED) {
            String code = l.getLanguage();
            ResourceBundle b = l.equals(Locale.ENGLISH) ? english : own(base, l);
            if (b == null) {
                out.add(code + ": no bundle " + base);
                continue;
            }
            Set<String> have = new TreeSet<>(Collections.list(b.getKeys()));
            for (String k : names) {
                if (!have.contains(k)) {
                    out.add(code + ": missing " + k);
                }
            }
            for (String k : have) {
                if (!names.contains(k)) {
                    out.add(code + ": unused " + k);
                } else {
                    pattern(code, k, b.getString(k), english != null && english.containsKey(k) ? english.getString(k) : null, out);
                }
            }
        }
        return out;
    }

    private static void pattern(String code, String key, String text, String englishText, List<String> out) {
        try {
            new MessageFormat(text, Locale.ROOT);
        } catch (IllegalArgumentException e) {
            out.add(code + ": " + key + " is not a valid pattern: " + e.getMessage());
            return;
        }
        if (englishText != null && !placeholders(text).equals(placeholders(englishText))) {
            out.add(code + ": " + key + " has placeholders " + placeholders(text) + ", English " + placeholders(englishText));
        }
    }

    /** The argument numbers a pattern uses, e.g. {@code [0, 1]}. */
    static Set<Integer> placeholders(String pattern) {
        Set<Integer> out = new TreeSet<>();
        Matcher m = PLACEHOLDER.matcher(pattern);
        while (m.find()) {
            out.add(Integer.parseInt(m.group(1)));
        }
        return out;
    }

    /**
     * The file of {@code locale} alone, without the English file behind it; null if there is none
     * (the translators' checks, and the tests of bundles this class does not check, read it).
     */
    public static ResourceBundle own(String base, Locale locale) {
        // newBundle loads the one file, past the cache of getBundle, which would chain the English parent
        try {
            return ResourceBundle.Control.getControl(ResourceBundle.Control.FORMAT_PROPERTIES)
                    .newBundle(base, locale, "java.properties", BundleCheck.class.getClassLoader(), true);
        } catch (ReflectiveOperationException | java.io.IOException e) {
            return null;
        }
    }
}
