package org.parpe.core.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The translators' check of PARPE's messages (docs/cli.md, "Translating PARPE"): run it with
 * {@code mvn -B -o -pl parpe-core test -Dtest=MessagesTest}; a failure lists what is missing,
 * unused or mismatched, per language.
 */
class MessagesTest {
    /** The sources of every module, from parpe-core where Maven runs this test. */
    private static final Path ROOT = Path.of("..");

    @Test
    void everyBundleHasEveryKeyNoOtherAndTheEnglishPlaceholders() {
        List<String> problems = BundleCheck.problems(Msg.BUNDLE, List.of(Msg.values()));
        assertEquals(List.of(), problems, "fix the bundles of org.parpe.core.text.Msg:\n" + String.join("\n", problems));
    }

    @Test
    void everyKeyIsUsedByTheCode() throws IOException {
        // Msg.java counts from its helpers on, not its list of constants
        String code = mainSources().map(p -> p.endsWith("text/Msg.java") ? afterConstants(read(p)) : read(p))
                .reduce("", String::concat);
        // KIND_ constants are reached by name from the kind words (Msg.kind)
        List<String> unused = BundleCheck.unusedIn(code, java.util.Arrays.stream(Msg.values())
                .filter(m -> !m.name().startsWith("KIND_")).toList(), "");
        assertEquals(List.of(), unused, "keys no code uses: remove them from Msg and every bundle");
    }

    private static String afterConstants(String msgJava) {
        return msgJava.substring(msgJava.indexOf("public static final String BUNDLE"));
    }

    @Test
    void everyKindWordTheLoaderUsesHasAKey() throws IOException {
        Set<String> kinds = new TreeSet<>();
        Matcher m = Pattern.compile("(?:validName\\([^,]+, |define\\([^,]+, |named\\()\"([a-z ]+)\"")
                .matcher(mainSources().map(MessagesTest::read).reduce("", String::concat));
        while (m.find()) {
            kinds.add(m.group(1));
        }
        assertTrue(kinds.contains("radio word") && kinds.contains("group"), "the scan finds the kinds: " + kinds);
        for (String k : kinds) {
            assertEquals(Message.of(Msg.valueOf("KIND_" + k.toUpperCase(java.util.Locale.ROOT).replace(' ', '_'))),
                    Msg.kind(k), k);
        }
    }

    /**
     * The message-producing code converted to the bundles (the loader, expressions, the run's
     * errors and warnings, the export's diagnostics, input files) holds no English prose: a
     * string literal of two or more words is a message that bypasses the bundles. Literals that
     * are PARSL words, file formats or code are on the allow-list with their reason.
     */
    @Test
    void convertedCodeHasNoProseLiterals() throws IOException {
        List<String> found = new ArrayList<>();
        for (Path p : (Iterable<Path>) converted()::iterator) {
            String text = withoutComments(read(p));
            Matcher m = Pattern.compile("\"((?:[^\"\\\\\\n]|\\\\.)*)\"").matcher(text);
            while (m.find()) {
                String s = m.group(1);
                // a literal with a backslash escape is a pattern (the parser's place note), not prose
                if (PROSE.matcher(s).find() && !ALLOWED.contains(s) && !s.contains("\\\\")) {
                    found.add(p.getFileName() + ": \"" + s + "\"");
                }
            }
        }
        assertEquals(List.of(), found, "user-visible text outside the bundles (add a key to Msg)");
    }

    /** Two words of letters with a space: prose, not a name, a number or an operator. */
    private static final Pattern PROSE = Pattern.compile("[A-Za-z]{2,}[ ,;:]+[A-Za-z]{2,}");

    /** Literals of two words that are not messages. */
    private static final Set<String> ALLOWED = Set.of(
            "radio word",                              // a kind of name; its text is KIND_RADIO_WORD
            "PARSL evaluates its own node tree",       // an exp4j callback PARPE never calls (internal)
            "Message:",                                // a marker in the XML parser's own message
            "ParseError at [",                         // the same
            "Expected a quote",                        // words of the XML parser's message, matched
            "simulated robot ",                        // a place, as "bus /dev/ttyUSB0": places stay as they are
            "#ifdef PARSL_KEEP");                      // C code the export writes

    /**
     * Issue 38: "a test fails on any user-visible string literal ... in messages outside the
     * bundles". Every literal of parpe-core's main code that reads as prose ({@link ProseLiterals})
     * is a text outside the bundles unless {@link #CORE_ALLOWED} gives its reason or the file is one
     * of {@link #WRITES_C}.
     */
    @Test
    void noProseLiteralOutsideTheBundles() throws IOException {
        List<String> found = ProseLiterals.inTree(ROOT.resolve("parpe-core/src/main/java"), WRITES_C::contains,
                s -> CORE_ALLOWED.values().stream().anyMatch(a -> a.contains(s)));
        assertEquals(List.of(), found, "text for the user outside the bundles: give it a key in Msg, DiagramMsg or EditMsg\n"
                + String.join("\n", found));
    }

    /** The files that write the exported program's C source: code and its comments, English as C is (a file format). */
    private static final Set<String> WRITES_C = Set.of("org/parpe/core/export/CProgram.java",
            "org/parpe/core/export/CTables.java", "org/parpe/core/export/CExpressions.java",
            "org/parpe/core/export/CFastForm.java", "org/parpe/core/export/CText.java", "org/parpe/core/export/CLayout.java");

    /** Literals of parpe-core that read as prose but are no text for the user in a language, by reason. */
    private static final java.util.Map<String, Set<String>> CORE_ALLOWED = java.util.Map.of(
            "PARSL's words (the file format): the names of keys a radio's keys attribute takes",
            Set.of("Up", "Down", "Left", "Right"),
            "a kind of name as the loader names it inside, read by Msg.kind: its words are the KIND_ keys",
            Set.of("radio word", "gait table"),
            "file formats: C the export writes beside its C files, SVG markup, a trace's numbers",
            Set.of("#ifdef PARSL_KEEP", "\" font-family=\"DejaVu Sans, sans-serif\">\n", "NaN", "Infinity"),
            "a place where a file's name stands before error:, which tools read (SourcePos)",
            Set.of("<no place>"),
            "words of the XML parser's own message, matched to find its place and reason (XmlReader)",
            Set.of("ParseError at [", "Message:", "Expected a quote"),
            "a crash report, English for the bug report (CrashReport)",
            Set.of(" internal error while ", "(could not write a crash file: "),
            "faults of PARPE's own: checks of arguments that PARPE's code passes, never a user's value unchecked"
                    + " (the command line and the IDE check --tick, --duration and a trace's tick in their words first)",
            Set.of("replacements overlap: ", "unknown expression node ", " is one word, got '", "capacity must be at least 2, got ",
                    "duration must be >= 0 seconds, got ", "tick must be > 0 seconds, got ", "speed factor must be > 0, got "),
            "the translators' check, whose report names keys and bundle files (BundleCheck)",
            Set.of(": no bundle ", " is not a valid pattern: ", " has placeholders "),
            "the pseudo-language's accented letters (Pseudo)",
            Set.of("åÅƀçÇđéÉĝĜĥîÎĵķłŁñÑöÖþšŠüÜŵýÝžŽ"));

    private static Stream<Path> converted() throws IOException {
        Path core = ROOT.resolve("parpe-core/src/main/java/org/parpe/core");
        List<Path> files = new ArrayList<>();
        try (Stream<Path> s = Files.list(core.resolve("load"))) {
            s.filter(p -> p.toString().endsWith(".java")).forEach(files::add);
        }
        for (String f : List.of("expr/Lexer.java", "expr/Syntax.java", "expr/ExprCompiler.java", "expr/NameResolver.java",
                "expr/Names.java", "expr/Nodes.java", "expr/Functions.java", "expr/EvalException.java",
                "xml/XmlReader.java", "xml/InputFiles.java", "run/InstanceRun.java", "run/PlatesByHand.java",
                "run/ScriptRuntimeError.java", "run/Engine.java", "export/CExport.java", "export/MemoryReport.java",
                "model/Parameter.java", "sensor/Channel.java", "diag/Diagnostic.java", "xml/FlatXmlFile.java",
                "run/TargetException.java")) {
            files.add(core.resolve(f));
        }
        // the simulator's and the servo buses' file readers and targets (their other messages are still English)
        Path sim = ROOT.resolve("parpe-sim/src/main/java/org/parpe/sim");
        for (String f : List.of("config/ConfigReader.java", "config/GeneratorArgs.java", "config/RobotConfigs.java",
                "config/Kit.java", "internal/ConfigCheck.java", "internal/Placement.java", "internal/Overlaps.java",
                "world/WorldReader.java", "world/Scenery.java", "world/Movables.java", "world/ScoringReader.java",
                "world/ChallengeReader.java")) {
            files.add(sim.resolve(f));
        }
        Path serial = ROOT.resolve("parpe-serial/src/main/java/org/parpe/serial");
        files.add(serial.resolve("servo/profile/ProfileReader.java"));
        files.add(serial.resolve("servo/run/ServoTarget.java"));
        files.add(serial.resolve("export/SketchOptions.java"));
        files.add(serial.resolve("export/ProgramExport.java"));
        return files.stream();
    }

    private static Stream<Path> mainSources() throws IOException {
        List<Path> out = new ArrayList<>();
        for (String module : List.of("parpe-core", "parpe-sim", "parpe-serial", "parpe-cli", "parpe-gui")) {
            Path dir = ROOT.resolve(module).resolve("src/main/java");
            if (Files.isDirectory(dir)) {
                try (Stream<Path> s = Files.walk(dir)) {
                    s.filter(p -> p.toString().endsWith(".java")).forEach(out::add);
                }
            }
        }
        return out.stream();
    }

    private static String withoutComments(String java) {
        return java.replaceAll("(?s)/\\*.*?\\*/", "").replaceAll("(?m)//.*$", "");
    }

    private static String read(Path p) {
        try {
            return Files.readString(p);
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /** The unused-key check itself: a key counts only where its whole name (after the prefix) is written. */
    @Test
    void unusedInListsTheKeysTheCodeNeverNames() {
        Msg a = Msg.values()[0];
        Msg b = Msg.values()[1];
        assertEquals(List.of(b.name()), BundleCheck.unusedIn("f(Msg." + a.name() + ");", List.of(a, b), "Msg."));
        assertEquals(List.of(a.name(), b.name()), BundleCheck.unusedIn("f(" + a.name() + "_MORE, " + b.name() + ");", List.of(a, b), "Msg."));
        assertEquals(List.of(a.name()), BundleCheck.unusedIn("f(X" + a.name() + ", " + b.name() + ");", List.of(a, b), ""));
    }
}
