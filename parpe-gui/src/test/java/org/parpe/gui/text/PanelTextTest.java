package org.parpe.gui.text;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.parpe.core.text.BundleCheck;
import org.parpe.core.text.Lang;

/**
 * The translators' check of the IDE's panels (issue 38: "every bundle has every key; no unused
 * keys"): the bundles {@code Panels} of {@link PanelMsg} and {@code Tools} of {@link ToolMsg} in
 * every language, every key used, and no English prose left in the code of the panels' packages. Run it with
 * {@code mvn -B -o -pl parpe-gui -am test -Dtest=PanelTextTest -Dsurefire.failIfNoSpecifiedTests=false}.
 */
class PanelTextTest {
    private static final Path MAIN = Path.of("src/main/java/org/parpe/gui");

    /** The packages whose texts are {@link PanelMsg}'s and {@link ToolMsg}'s. */
    private static final List<String> PACKAGES = List.of("pose", "diagram", "robot", "sweep", "panels", "grid", "view3d");

    /**
     * Literals of those packages that read as prose but are no text of the IDE: what the Pose panel
     * writes into a PARSL file (comments and the recording's origin, part of the file), the edit
     * row's name of its state list (an input name like the attributes beside it), what a crash file
     * (English, for the bug report) says PARPE was doing, and a fault of PARPE's own.
     */
    private static final Set<String> ALLOWED = Set.of("playback in the Pose panel", "recorded in the PARPE IDE's Pose panel from ",
            " poses of group ", ", recorded in the Pose panel -->\\n", "add state", "running a sweep", "the span ",
            " lies outside a document of ", "a file dialog needs a title");

    @Test
    void everyBundleHasEveryKeyNoOtherAndTheEnglishPlaceholders() {
        List<String> problems = new ArrayList<>(BundleCheck.problems(PanelMsg.BUNDLE, List.of(PanelMsg.values())));
        problems.addAll(BundleCheck.problems(ToolMsg.BUNDLE, List.of(ToolMsg.values())));
        assertEquals(List.of(), problems, String.join("\n", problems));
    }

    @Test
    void everyKeyIsUsedByTheCode() {
        // the key classes' own code after their constants counts (PanelMsg's ORDINAL is used there)
        String code = UiTextTest.sources().map(p -> {
            String text = UiTextTest.read(p);
            boolean keys = p.endsWith("text/PanelMsg.java") || p.endsWith("text/ToolMsg.java");
            return keys ? text.substring(text.indexOf("String BUNDLE")) : text;
        }).reduce("", String::concat);
        List<String> unused = new ArrayList<>(BundleCheck.unusedIn(code, List.of(PanelMsg.values()), ""));
        unused.addAll(BundleCheck.unusedIn(code, List.of(ToolMsg.values()), ""));
        assertEquals(List.of(), unused, "keys no code uses");
    }

    /** A literal of two words in the panels' code is a text that bypasses the bundle. */
    @Test
    void panelsCodeHasNoProseLiterals() {
        List<String> found = new ArrayList<>();
        UiTextTest.sources().filter(p -> PACKAGES.contains(MAIN.relativize(p).getName(0).toString())).forEach(p -> {
            String text = UiTextTest.read(p).replaceAll("(?s)/\\*.*?\\*/", "").replaceAll("(?m)//.*$", "");
            Matcher m = Pattern.compile("\"((?:[^\"\\\\\\n]|\\\\.)*)\"").matcher(text);
            while (m.find()) {
                if (!ALLOWED.contains(m.group(1)) && Pattern.compile("[A-Za-z]{2,}[ ,;:]+[A-Za-z]{2,}").matcher(m.group(1)).find()) {
                    found.add(MAIN.relativize(p) + ": \"" + m.group(1) + "\"");
                }
            }
        });
        assertEquals(List.of(), found, "user-visible text outside the bundles (add a key to PanelMsg or ToolMsg)");
    }

    /** English counts in words as the loader's messages do; the other languages put the number in their pattern. */
    @Test
    void ordinalsReadAsEachLanguageCounts() {
        try {
            assertEquals(List.of("first", "second", "11th"), List.of(PanelMsg.ordinal(0), PanelMsg.ordinal(1), PanelMsg.ordinal(10)));
            Lang.use(Locale.GERMAN);
            assertEquals(List.of("1.", "11."), List.of(PanelMsg.ordinal(0), PanelMsg.ordinal(10)));
            assertEquals("die 2. Zeile von wave", PanelMsg.DIAGRAM_ROW_TITLE.text(PanelMsg.ordinal(1), "wave"));
            Lang.use(Locale.JAPANESE);
            assertEquals("wave の 2 番目の行", PanelMsg.DIAGRAM_ROW_TITLE.text(PanelMsg.ordinal(1), "wave"));
        } finally {
            Lang.use(Locale.ENGLISH);
        }
    }

}
