package org.parpe.gui.text;

import java.util.List;
import java.util.Locale;
import java.util.function.UnaryOperator;
import org.eclipse.jface.dialogs.IDialogConstants;
import org.eclipse.jface.resource.JFaceResources;
import org.parpe.core.text.Lang;

/**
 * Which language the IDE speaks, chosen once when it starts (docs/decisions.md, "Language of the
 * IDE"): {@code parpe gui --lang CODE}, else the Language preference, else the environment
 * ({@code LC_ALL}, {@code LC_MESSAGES}, {@code LANG}), else English. A change of the preference
 * applies at the next start: the widgets took their texts when they were made, and JFace reads
 * its button labels once per process.
 */
public final class IdeLanguage {
    /** The preference key (in {@code ide.properties}): a language code, or absent for "as the system". */
    public static final String PREFERENCE = "language";

    /**
     * The JFace keys PARPE's dialogs show (JFace's {@code org/eclipse/jface/messages.properties},
     * read by {@link JFaceResources#getString}); PARPE gives them in German, Spanish and Japanese.
     */
    public static final List<String> JFACE_KEYS = List.of("ok", "cancel", "yes", "no", "yestoall", "notoall",
            "close", "help", "helpToolTip", "apply", "abort", "retry", "ignore", "proceed", "open", "skip", "stop",
            "showDetails", "hideDetails", "backButton", "nextButton", "finish", "openBrowse", "openChange");

    private IdeLanguage() {
    }

    /**
     * The language to speak: {@code option} ({@code --lang}) if given, else {@code preference}
     * if it names a language PARPE speaks, else the environment's.
     *
     * @throws IllegalArgumentException when {@code option} names no language PARPE speaks
     */
    public static Locale choose(String option, String preference, UnaryOperator<String> env) {
        if (option != null) {
            Locale l = Lang.parse(option);
            if (l == null) {
                throw new IllegalArgumentException(UiMsg.UNKNOWN_LANGUAGE.text(option, Lang.codes()));
            }
            return l;
        }
        Locale chosen = preference == null || preference.isBlank() ? null : Lang.parse(preference);
        return chosen != null ? chosen : Lang.fromEnvironment(env);
    }

    /**
     * Makes {@code language} the IDE's: PARPE's texts ({@link Lang#use}) and JFace's button labels,
     * which JFace reads once, from the JVM's default locale, the first time it is asked. The
     * default locale is the chosen language only for that moment: numbers are formatted as before.
     */
    public static void use(Locale language) {
        Lang.use(language);
        Locale before = Locale.getDefault();
        Locale display = Locale.getDefault(Locale.Category.DISPLAY);
        Locale format = Locale.getDefault(Locale.Category.FORMAT);
        try {
            Locale.setDefault(Lang.current());
            JFaceResources.getBundle();
            // IDialogConstants' labels are constants made from the bundle when the interface is first used
            java.util.Objects.requireNonNull(IDialogConstants.OK_LABEL);
        } finally {
            Locale.setDefault(before);
            Locale.setDefault(Locale.Category.DISPLAY, display);
            Locale.setDefault(Locale.Category.FORMAT, format);
        }
    }
}
