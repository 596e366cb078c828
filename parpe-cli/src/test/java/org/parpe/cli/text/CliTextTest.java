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
            ResourceBundle b = BundleCheck.own(Main.HELP, l);
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
            ResourceBundle b = BundleCheck.own(Main.HELP, l);
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
     * A literal of the command line's code that is text, but not a message to translate: each
     * with its reason. Matched against the whole literal.
     */
    private record NotProse(String file, String literal, String why) {
    }

    private static final List<NotProse> NOT_PROSE = List.of(
            new NotProse("bench/(Core|Sweep)Benchmark\\.java|sim/SimBenchmark\\.java", "(?s).*<.*",
                    "a PARSL script the benchmark loads: the file format"),
            new NotProse("hw/(Serial|Servo)Benchmark\\.java", ".*=skipped \\(socat is not installed\\)",
                    "a bench figure's line NAME=VALUE: scripts and bench --compare read it"),
            new NotProse("hw/ScanCommand\\.java", "written by parpe scan: .*|direction and limits, then run parpe calibrate",
                    "a comment written into the hardware profile (a file, read by anyone who edits it)"),
            new NotProse("hw/CalibrateCommand\\.java", "calibrated by parpe calibrate",
                    "a comment written into the hardware profile"),
            new NotProse("text/ParseErrors\\.java", ".*\\((\\.\\*|\\[\\^'\\]\\+|int\\||\\?:).*",
                    "a pattern of picocli's own English message, which ParseErrors reads to say it in the user's language"),
            new NotProse("bench/Machine\\.java", "model name|cpu MHz", "a field name of Linux's /proc/cpuinfo, which Machine reads"),
            new NotProse("hw/RecordCommand\\.java", "recorded from ", "a comment written into the recorded PARSL file"),
            new NotProse("export/RobotExport\\.java|Ide\\.java", " --out trace\\.csv| \\./parpe gui ",
                    "part of a command line the user copies"),
            new NotProse("hw/(ConsoleCommands|ServoEmulation)\\.java", "(pose|touch|fault) ID .*",
                    "the syntax of an emulator console command: its words are what the console reads"),
            new NotProse("bench/.*Benchmark\\.java|sim/Sim(Benchmark|Run)\\.java|hw/(Serial|Servo)Benchmark\\.java",
                    "(the benchmark world | does not load: |benchmark script |the emulator rejected |emulated servo "
                            + "| did not answer a Ping|the benchmark robot does not assemble: |generated script has "
                            + "|benchmark script does not load: |cannot load |the docking example does not load: "
                            + "|the shell's times printed '|', not a user and a system time)",
                    "a benchmark's own fixed input failing: a failure of PARPE itself, reported as an internal error"
                            + " with a crash file; its words are for the bug report (English, as --lang en gives)"));

    /**
     * Every file of the command line's main code holds no English prose outside picocli's
     * annotations (the English help) and {@link #NOT_PROSE}: a literal of two words is a message
     * that bypasses the bundles.
     */
    @Test
    void convertedCodeHasNoProseLiterals() throws IOException {
        List<String> found = new ArrayList<>();
        Path cli = Path.of("src/main/java/org/parpe/cli");
        for (Path p : sources().filter(p -> p.startsWith(cli)).sorted().toList()) {
            String f = cli.relativize(p).toString().replace('\\', '/');
            String text = withoutAnnotations(read(p).replaceAll("(?s)/\\*.*?\\*/", "").replaceAll("(?m)//.*$", ""));
            Matcher m = Pattern.compile("\"((?:[^\"\\\\\\n]|\\\\.)*)\"").matcher(text);
            while (m.find()) {
                if (Pattern.compile("[A-Za-z]{2,}[ ,;:]+[A-Za-z]{2,}").matcher(m.group(1)).find() && !allowed(f, m.group(1))) {
                    found.add(f + ": \"" + m.group(1) + "\"");
                }
            }
        }
        assertEquals(List.of(), found, "user-visible text outside the bundles (add a key to CliMsg)");
    }

    private static boolean allowed(String file, String literal) {
        String text = literal.replace("\\\"", "\"");
        return NOT_PROSE.stream().anyMatch(a -> file.matches(a.file()) && text.matches(a.literal()));
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
