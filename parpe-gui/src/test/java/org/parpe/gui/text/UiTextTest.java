package org.parpe.gui.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.ResourceBundle;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.parpe.core.text.BundleCheck;
import org.parpe.core.text.Lang;
import org.parpe.core.text.ProseLiterals;

/**
 * The translators' check of the IDE (issue 38: "a test fails on any user-visible string literal in
 * widget code"; "every bundle has every key; no unused keys"). Run it with
 * {@code mvn -B -o -pl parpe-gui -am test -Dtest=UiTextTest -Dsurefire.failIfNoSpecifiedTests=false}.
 */
class UiTextTest {
    private static final Path MAIN = Path.of("src/main/java/org/parpe/gui");

    /**
     * Whole literals that are not prose though they look like it: the command's name before the
     * error and warning prefixes tools parse (English, as the command line's), the comments of the settings and autosave files, what a crash file
     * (English, for the bug report) says PARPE was doing.
     */
    private static final Set<String> ALLOWED = Set.of("parpe gui: error: ", "parpe gui: warning: ", "parpe gui: ",
            "PARPE IDE settings", "PARPE autosave", "handling a UI event",
            // what a crash file says PARPE was doing (English, for the bug report)
            "running a sweep", "playback in the Pose panel",
            // the edit row's input key for the list of states (its label is EditRow.label), the keys' names as GTK shows them, the user's folder
            "add state", "Up", "Down", "Left", "Right", "Documents", "a file dialog needs a title",
            // comments the Pose panel writes into the student's PARSL file (the file's language is English)
            "recorded in the PARPE IDE's Pose panel from ", " poses of group ", ", recorded in the Pose panel -->\n");

    /** A menu accelerator's text after the tab: key names as GTK shows them. */
    private static final Pattern KEYS = Pattern.compile("\t(Ctrl\\+|Shift\\+|Alt\\+)*[^\\s]+");

    @Test
    void everyBundleHasEveryKeyNoOtherAndTheEnglishPlaceholders() {
        List<String> problems = BundleCheck.problems(UiMsg.BUNDLE, List.of(UiMsg.values()));
        assertEquals(List.of(), problems, String.join("\n", problems));
    }

    @Test
    void everyKeyIsUsedByTheCode() {
        String code = sources().filter(p -> !p.endsWith("text/UiMsg.java")).map(UiTextTest::read).reduce("", String::concat);
        List<String> unused = BundleCheck.unusedIn(code, List.of(UiMsg.values()), "");
        assertEquals(List.of(), unused, "keys no code uses");
    }

    /** JFace's OK, Cancel, Yes, No, ... in every language PARPE speaks (org/eclipse/jface/messages.properties is English). */
    @Test
    void jfaceButtonsInEveryLanguage() {
        List<String> problems = new ArrayList<>();
        for (Locale l : Lang.SUPPORTED.subList(1, Lang.SUPPORTED.size())) {
            ResourceBundle b = BundleCheck.own("org.eclipse.jface.messages", l);
            assertNotNull(b, "no org/eclipse/jface/messages_" + l + ".properties");
            Set<String> have = new TreeSet<>(Collections.list(b.getKeys()));
            IdeLanguage.JFACE_KEYS.stream().filter(k -> !have.contains(k)).forEach(k -> problems.add(l + ": missing " + k));
            have.stream().filter(k -> !IdeLanguage.JFACE_KEYS.contains(k)).forEach(k -> problems.add(l + ": unused " + k));
        }
        assertEquals(List.of(), problems, String.join("\n", problems));
    }

    /** Every string literal of the IDE's code that reads as prose is a text outside the bundles. */
    @Test
    void noUserVisibleLiteralOutsideTheBundles() {
        List<String> found = new ArrayList<>();
        sources().forEach(p -> found.addAll(proseLiterals(MAIN.relativize(p).toString(), read(p))));
        assertEquals(List.of(), found, "user-visible text outside the bundles: give it a key in UiMsg\n" + String.join("\n", found));
    }

    /** The scan itself: it finds prose and passes code, PARSL and key names (else the test above proves nothing). */
    @Test
    void theScanTellsProseFromCode() {
        String java = String.join("\n",
                "class A {",
                "  @Option(names = \"--x\", description = \"annotations are the English help\") String x;",
                "  void f() {",
                "    b.setText(\"Run the script\"); // \"a comment\"",
                "    b.setText(\"Speed:\"); b.setText(\"\\u00dcber\"); t.setText(\"実行\");",
                "    prefs.put(\"run.speed\", \"yes\"); s.replace(\"<states>\", \"\\t\"); x(\"<up angles=\\\"30\\\"/>\");",
                "    m.setText(UiMsg.MENU_NEW.text() + \"\\tCtrl+N\"); f(\"*.xml\", \"%.2f s\", \"parpe-engine\");",
                "    throw new IllegalStateException(\"parpe.png is missing from the build\");",
                "  }",
                "}");
        assertEquals(List.of("A.java:4: \"Run the script\"", "A.java:5: \"Speed:\"", "A.java:5: \"\\u00dcber\"",
                "A.java:5: \"実行\""), proseLiterals("A.java", java));
    }


    /** The literals of {@code java} (comments and annotations left out) that read as prose: {@code FILE:LINE: "text"}. */
    static List<String> proseLiterals(String file, String java) {
        return ProseLiterals.in(file, java, text -> ALLOWED.contains(text) || KEYS.matcher(text).matches());
    }


    /** Every Java file of parpe-gui's main code (also read by {@link PanelTextTest}). */
    static Stream<Path> sources() {
        try (Stream<Path> s = Files.walk(MAIN)) {
            return s.filter(p -> p.toString().endsWith(".java")).toList().stream();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    static String read(Path p) {
        try {
            return Files.readString(p);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
