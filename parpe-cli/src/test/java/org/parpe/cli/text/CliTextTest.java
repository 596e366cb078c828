package org.parpe.cli.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.ResourceBundle;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.parpe.cli.Main;
import org.parpe.core.text.BundleCheck;
import org.parpe.core.text.Lang;
import picocli.CommandLine;
import picocli.CommandLine.Model.ArgSpec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * The translators' check of the command line (docs/cli.md, "Translating PARPE"): run it with
 * {@code mvn -B -o -pl parpe-cli -am test -Dtest=CliTextTest -Dsurefire.failIfNoSpecifiedTests=false};
 * a failure lists what is missing, unused or mismatched per language.
 */
class CliTextTest {

    @Test
    void everyMessageBundleHasEveryKeyNoOtherAndTheEnglishPlaceholders() {
        List<String> problems = BundleCheck.problems(CliMsg.BUNDLE, List.of(CliMsg.values()));
        assertEquals(List.of(), problems, String.join("\n", problems));
    }

    @Test
    void everyMessageKeyIsUsedByTheCode() throws IOException {
        String code = sources().filter(p -> !p.endsWith("text/CliMsg.java")).map(CliTextTest::read)
                .reduce("", String::concat);
        List<String> unused = BundleCheck.unusedIn(code, List.of(CliMsg.values()), "");
        assertEquals(List.of(), unused, "keys no code uses");
    }

    @Test
    void everyHelpBundleHasExactlyTheHelpKeys() {
        List<String> problems = new ArrayList<>();
        for (Locale l : Lang.SUPPORTED.subList(1, Lang.SUPPORTED.size())) {
            ResourceBundle b = own(Main.HELP, l);
            assertNotNull(b, "no help bundle for " + l);
            Set<String> have = new TreeSet<>(Collections.list(b.getKeys()));
            for (String k : HelpKeys.KEYS) {
                if (!have.contains(k)) {
                    problems.add(l + ": missing " + k);
                }
            }
            for (String k : have) {
                if (!HelpKeys.KEYS.contains(k)) {
                    problems.add(l + ": unused " + k);
                }
            }
        }
        assertEquals(List.of(), problems, String.join("\n", problems));
    }

    /** A key that names no command or option would never be shown: the commands or options were renamed. */
    @Test
    void everyHelpKeyNamesACommandOrOptionThatExists() {
        CommandLine top = new CommandLine(new Main());
        for (String c : HelpKeys.COMMANDS) {
            assertNotNull(top.getSubcommands().get(c), "no command " + c);
        }
        for (String c : HelpKeys.OPTIONS_OF) {
            CommandSpec spec = top.getSubcommands().get(c).getCommandSpec();
            Set<String> keys = new TreeSet<>();
            for (ArgSpec a : spec.args()) {
                keys.add(key(a));
            }
            for (String k : HelpKeys.KEYS) {
                if (k.startsWith("parpe." + c + ".") && !k.startsWith("parpe." + c + ".usage.")) {
                    String arg = k.substring(("parpe." + c + ".").length());
                    assertEquals(true, keys.contains(arg), k + " names no option of " + c + " " + keys);
                }
            }
            // and every option and parameter of the command is translated (help, version, lang: shared keys)
            for (String k : keys) {
                if (!Set.of("help", "version", "lang").contains(k)) {
                    assertEquals(true, HelpKeys.KEYS.contains("parpe." + c + "." + k), "untranslated: parpe." + c + "." + k);
                }
            }
        }
    }

    @Test
    void translationsKeepPicocliDefaultValuePlaceholders() {
        CommandLine top = new CommandLine(new Main());
        for (Locale l : Lang.SUPPORTED.subList(1, Lang.SUPPORTED.size())) {
            ResourceBundle b = own(Main.HELP, l);
            for (String c : HelpKeys.OPTIONS_OF) {
                for (ArgSpec a : top.getSubcommands().get(c).getCommandSpec().args()) {
                    String k = "parpe." + c + "." + key(a);
                    if (b.containsKey(k)) {
                        // picocli shows the English text with ${DEFAULT-VALUE} already put in
                        String shown = String.join(" ", a.description());
                        boolean english = a.defaultValue() != null && (shown.contains("(default " + a.defaultValue() + ")")
                                || shown.contains("(default: " + a.defaultValue() + ")"));
                        assertEquals(english, b.getString(k).contains("${DEFAULT-VALUE}"), l + " " + k);
                    }
                }
            }
        }
    }

    /**
     * The command line's message code converted to the bundles holds no English prose outside
     * picocli's annotations (the English help): a literal of two words is a message that
     * bypasses the bundles.
     */
    @Test
    void convertedCodeHasNoProseLiterals() throws IOException {
        List<String> found = new ArrayList<>();
        Path cli = Path.of("src/main/java/org/parpe/cli");
        for (String f : List.of("Main.java", "CheckCommand.java", "RunCommand.java", "options/Inputs.java", "options/ParamValues.java",
                // (the Arduino sketch's options and checks are in parpe-serial now: core's MessagesTest scans them)
                "options/ClockOptions.java", "terminal/Progress.java", "export/ExportCommand.java", "sim/SimOptions.java",
                "sim/RaceCommand.java", "sim/RobotCommand.java", "diagram/DiagramCommand.java", "diagram/ScenePng.java",
                "sweep/SimSweepOptions.java")) {
            String text = withoutAnnotations(read(cli.resolve(f)).replaceAll("(?s)/\\*.*?\\*/", "").replaceAll("(?m)//.*$", ""));
            Matcher m = Pattern.compile("\"((?:[^\"\\\\\\n]|\\\\.)*)\"").matcher(text);
            while (m.find()) {
                if (Pattern.compile("[A-Za-z]{2,}[ ,;:]+[A-Za-z]{2,}").matcher(m.group(1)).find()) {
                    found.add(f + ": \"" + m.group(1) + "\"");
                }
            }
        }
        assertEquals(List.of(), found, "user-visible text outside the bundles (add a key to CliMsg)");
    }

    /** The text without picocli's annotations, whose strings are the English help. */
    private static String withoutAnnotations(String java) {
        StringBuilder out = new StringBuilder();
        Matcher m = Pattern.compile("@(Command|Option|Parameters)\\(").matcher(java);
        int from = 0;
        while (m.find(from)) {
            out.append(java, from, m.start());
            int depth = 0;
            int i = m.end() - 1;
            boolean quoted = false;
            for (; i < java.length(); i++) {
                char c = java.charAt(i);
                if (quoted) {
                    if (c == '\\') {
                        i++;
                    } else if (c == '"') {
                        quoted = false;
                    }
                } else if (c == '"') {
                    quoted = true;
                } else if (c == '(') {
                    depth++;
                } else if (c == ')' && --depth == 0) {
                    break;
                }
            }
            from = i + 1;
        }
        return out.append(java.substring(Math.min(from, java.length()))).toString();
    }

    private static String key(ArgSpec a) {
        if (a.descriptionKey() != null && a.descriptionKey().startsWith("mixinStandardHelpOptions.")) {
            return a.descriptionKey().substring("mixinStandardHelpOptions.".length());
        }
        if (a.descriptionKey() != null && !a.descriptionKey().isEmpty()) {
            return a.descriptionKey();
        }
        return ((CommandLine.Model.OptionSpec) a).longestName().replaceFirst("^-+", "");
    }

    private static ResourceBundle own(String base, Locale l) {
        try {
            return ResourceBundle.Control.getControl(ResourceBundle.Control.FORMAT_PROPERTIES)
                    .newBundle(base, l, "java.properties", CliTextTest.class.getClassLoader(), true);
        } catch (ReflectiveOperationException | IOException e) {
            return null;
        }
    }

    private static Stream<Path> sources() throws IOException {
        try (Stream<Path> s = Files.walk(Path.of("src/main/java"))) {
            return s.filter(p -> p.toString().endsWith(".java")).toList().stream();
        }
    }

    private static String read(Path p) {
        try {
            return Files.readString(p);
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
