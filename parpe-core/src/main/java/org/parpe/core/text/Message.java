package org.parpe.core.text;

import java.text.MessageFormat;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.MissingResourceException;
import java.util.ResourceBundle;

/**
 * A text to show to the user: a bundle key and its arguments, formatted in a language only
 * when it is shown ({@link #toString()} in {@link Lang#current()}). Arguments are kept as
 * strings, so numbers appear as the caller wrote them ({@code 0.5}, never {@code 0,5} or
 * {@code 1,000}: they are values of the script), or as messages, formatted in the same
 * language. Equal messages have equal keys and arguments.
 *
 * @param key  the key, or {@code null} for a text from outside PARPE (an operating system's or
 *             library's message), shown as it is: its one argument
 * @param args the arguments: strings and messages
 */
public record Message(Key key, List<Object> args) {

    /** No text at all (an absent hint). */
    public static final Message EMPTY = new Message(null, List.of(""));

    public Message {
        args = Collections.unmodifiableList(new ArrayList<>(args));
    }

    /** The text of {@code key} with {@code args}; numbers and other values become strings. */
    public static Message of(Key key, Object... args) {
        List<Object> kept = new ArrayList<>(args.length);
        for (Object a : args) {
            kept.add(a instanceof Message m ? m : String.valueOf(a));
        }
        return new Message(key, kept);
    }

    /**
     * A text PARPE does not translate, shown as it is: an operating system's or a library's
     * message, or a text of a part of PARPE not yet in the bundles.
     */
    public static Message verbatim(String text) {
        return new Message(null, List.of(text));
    }

    /** This text in {@code locale} (English where the bundle lacks the language). */
    public String format(Locale locale) {
        if (key == null) {
            return String.valueOf(args.get(0));
        }
        Object[] shown = new Object[args.size()];
        for (int i = 0; i < shown.length; i++) {
            shown[i] = args.get(i) instanceof Message m ? m.format(locale) : args.get(i);
        }
        return new MessageFormat(pattern(key, locale), locale).format(shown);
    }

    /**
     * The pattern of {@code key} in {@code locale}: the language's bundle, else the English
     * one. Never the bundle of the machine's default locale (English stays English on a German
     * machine).
     */
    public static String pattern(Key key, Locale locale) {
        return bundle(key.bundle(), locale).getString(key.name());
    }

    /**
     * The bundle {@code base} in {@code locale}, falling back to English, not to the default
     * locale; in the pseudo-language ({@link Lang#PSEUDO}) the English bundle seen through
     * {@link Pseudo}.
     */
    public static ResourceBundle bundle(String base, Locale locale) {
        if (Lang.isPseudo(locale)) {
            return Pseudo.bundle(bundle(base, Locale.ROOT));
        }
        try {
            return ResourceBundle.getBundle(base, locale,
                    ResourceBundle.Control.getNoFallbackControl(ResourceBundle.Control.FORMAT_PROPERTIES));
        } catch (MissingResourceException e) {
            return ResourceBundle.getBundle(base, Locale.ROOT,
                    ResourceBundle.Control.getNoFallbackControl(ResourceBundle.Control.FORMAT_PROPERTIES));
        }
    }

    /** The text in the chosen language ({@link Lang#current()}). */
    @Override
    public String toString() {
        return format(Lang.current());
    }
}
