package org.parpe.cli.text;

import java.util.Locale;
import org.parpe.core.text.Lang;
import org.parpe.core.text.Message;
import picocli.CommandLine;

/**
 * The language of a picocli command line of PARPE ({@code parpe} and the IDE's own, {@code parpe
 * gui}): {@code --lang} read before picocli parses, so that picocli's errors are in that language
 * too ({@link ParseErrors}), and picocli's help from a bundle of translations of its annotations.
 */
public final class CommandLanguage {
    private CommandLanguage() {
    }

    /** The value of {@code --lang CODE} or {@code --lang=CODE} before any {@code --}; null without one. */
    public static String langOption(String[] args) {
        for (int i = 0; i < args.length && !args[i].equals("--"); i++) {
            if (args[i].equals("--lang")) {
                return i + 1 < args.length ? args[i + 1] : "";
            }
            if (args[i].startsWith("--lang=")) {
                return args[i].substring("--lang=".length());
            }
        }
        return null;
    }

    /**
     * Has {@code cl} show its help in the chosen language ({@link Lang#current()}) from the help
     * bundle {@code base} ({@code base_de.properties}, keyed as picocli looks texts up). English is
     * in the annotations; the pseudo-language has no file of its own there, so its help is the
     * English one.
     */
    public static void helpIn(CommandLine cl, String base) {
        if (!Lang.current().equals(Locale.ENGLISH) && !Lang.isPseudo(Lang.current())) {
            cl.setResourceBundle(Message.bundle(base, Lang.current()));
        }
    }
}
