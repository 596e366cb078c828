package org.parpe.gui.help;

import java.util.regex.Pattern;

/**
 * The tutorial and the documentation write commands as a source checkout runs them,
 * {@code ./parpe run …}; the installed PARPE has {@code parpe} on the PATH, so the IDE shows
 * them as {@code parpe run …} there. Applied to a page's Markdown text before it is rendered.
 */
public final class CommandNames {
    /** {@code ./parpe} as a command: not part of a longer path or name. */
    private static final Pattern LAUNCHER = Pattern.compile("(?<![\\w./-])\\./parpe(?![\\w.-])");

    private CommandNames() {
    }

    /** {@code markdown} with {@code ./parpe} written as {@code parpe} when {@code installed}. */
    public static String forInstall(String markdown, boolean installed) {
        return installed ? LAUNCHER.matcher(markdown).replaceAll("parpe") : markdown;
    }
}
