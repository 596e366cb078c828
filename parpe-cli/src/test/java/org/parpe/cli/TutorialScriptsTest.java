package org.parpe.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The tutorial (docs/tutorial) and its scripts (examples/tutorial) cannot drift apart: every
 * script passes {@code parpe check} and starts with a comment, every lesson page links an
 * existing script and an existing picture, every script has its page, and the index lists
 * every page. Paths are relative to the module directory, as Maven runs the tests.
 */
class TutorialScriptsTest {
    static final Path SCRIPTS = Path.of("../examples/tutorial");
    static final Path DOCS = Path.of("../docs/tutorial");
    /** Markdown links and images: {@code [text](target)} and {@code ![alt](target)}. */
    static final Pattern LINK = Pattern.compile("\\]\\(([^)\\s#]+)(?:#[^)]*)?\\)");

    /** A command of a page: {@code ./parpe run ...} or {@code ./parpe race ...}, in a code block or in backquotes. */
    static final Pattern COMMAND = Pattern.compile("\\./parpe ((?:run|race) [^`\\n]+)");
    static final Pattern BREAK = Pattern.compile("<!-- what-went-wrong: replace `([^`]+)` with `([^`]*)`");
    static final Pattern SHOWN = Pattern.compile("(?m)^> (examples/tutorial/[^:\\s]+\\.xml):(\\d+:\\d+: error: .*)$");

    @TempDir
    Path tmp;

    static List<Path> scripts() throws IOException {
        try (Stream<Path> s = Files.list(SCRIPTS)) {
            return s.filter(p -> p.getFileName().toString().endsWith(".xml")).sorted().toList();
        }
    }

    /** The lesson pages: {@code NN-name.md}. */
    static List<Path> lessons() throws IOException {
        try (Stream<Path> s = Files.list(DOCS)) {
            return s.filter(p -> p.getFileName().toString().matches("\\d\\d-.*\\.md")).sorted().toList();
        }
    }

    static List<Path> links(Path page) throws IOException {
        List<Path> out = new ArrayList<>();
        Matcher m = LINK.matcher(Files.readString(page));
        while (m.find()) {
            String target = m.group(1);
            if (!target.contains("://") && !target.startsWith("mailto:")) {
                out.add(page.getParent().resolve(target).normalize());
            }
        }
        return out;
    }

    record Check(int code, String out, String err) {
    }

    static Check check(Path file, String... options) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        List<String> args = new ArrayList<>(List.of("check", file.toString()));
        args.addAll(List.of(options));
        int code = Main.execute(args.toArray(String[]::new), new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
        return new Check(code, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    static String name(Path p) {
        return p.getFileName().toString();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scripts")
    void passesCheckAndStartsWithAComment(Path script) throws IOException {
        Check c = check(script);
        String errors = c.err();
        assertEquals(0, c.code(), script + " does not pass check:\n" + errors);
        assertFalse(errors.contains("warning"), script + " has warnings:\n" + errors);
        // the prologue: the XML declaration and the world the lesson is written for (<?parpe world?>)
        String text = Files.readString(script).replaceFirst("^<\\?xml[^>]*\\?>\\s*(<\\?parpe [^>]*\\?>\\s*)?", "");
        assertTrue(text.startsWith("<!--"), script + " should start with a comment saying what the lesson shows");
    }

    @Test
    void theIndexListsEveryLesson() throws IOException {
        List<Path> pages = lessons();
        assertTrue(pages.size() >= 10, "expected at least ten lesson pages in " + DOCS + ", found " + pages);
        List<Path> linked = links(DOCS.resolve("index.md"));
        for (Path page : pages) {
            assertTrue(linked.contains(page.normalize()), "index.md does not link " + name(page));
        }
        assertTrue(Files.isRegularFile(DOCS.resolve("teachers.md")), "no teachers.md");
    }

    /** Numbers as the documents write them, from one. */
    static final List<String> NUMBER_WORDS = List.of("one", "two", "three", "four", "five", "six", "seven", "eight",
            "nine", "ten", "eleven", "twelve", "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen",
            "nineteen", "twenty");
    /** A count of lessons in prose: "ten short lessons", "is 14 lessons". */
    static final Pattern LESSON_COUNT = Pattern.compile("(?i)\\b(" + String.join("|", NUMBER_WORDS)
            + "|\\d+)\\s+(?:short\\s+)?lessons\\b");

    /**
     * Issue 31 item 3.7: the README promised "ten short lessons" when there were fourteen. Every
     * count of lessons in the README and the documents is the number of lesson pages.
     */
    @Test
    void everyCountOfLessonsInTheDocumentsIsTheNumberOfLessons() throws IOException {
        int lessons = lessons().size();
        List<Path> documents = new ArrayList<>(List.of(Path.of("../README.md")));
        try (Stream<Path> s = Files.walk(Path.of("../docs"))) {
            s.filter(p -> p.toString().endsWith(".md")).sorted().forEach(documents::add);
        }
        List<String> counts = new ArrayList<>();
        for (Path doc : documents) {
            Matcher m = LESSON_COUNT.matcher(Files.readString(doc));
            while (m.find()) {
                String n = m.group(1).toLowerCase(java.util.Locale.ROOT);
                int count = n.matches("\\d+") ? Integer.parseInt(n) : NUMBER_WORDS.indexOf(n) + 1;
                counts.add(doc + ": '" + m.group() + "'");
                assertEquals(lessons, count, doc + " says '" + m.group() + "', but " + DOCS + " has " + lessons + " lessons");
            }
        }
        assertTrue(counts.stream().anyMatch(c -> c.startsWith("../README.md")), "the README names the number of lessons: "
                + counts);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("lessons")
    void everyLessonLinksAnExistingScriptAndPicture(Path page) throws IOException {
        List<Path> linked = links(page);
        assertTrue(linked.stream().anyMatch(p -> name(p).endsWith(".xml") && p.startsWith(SCRIPTS.normalize())),
                name(page) + " links no script of examples/tutorial: " + linked);
        assertTrue(linked.stream().anyMatch(p -> name(p).endsWith(".png")), name(page) + " shows no picture");
        for (Path p : linked) {
            assertTrue(Files.exists(p), name(page) + " links " + p + ", which does not exist");
        }
    }

    @Test
    void everyScriptHasItsLessonPageWithItsOwnPicture() throws IOException {
        List<Path> all = new ArrayList<>();
        for (Path page : lessons()) {
            all.addAll(links(page));
        }
        for (Path script : scripts()) {
            assertTrue(all.contains(script.normalize()), "no lesson page links " + script);
            Path png = DOCS.resolve("img").resolve(name(script).replaceFirst("\\.xml$", ".png")).normalize();
            assertTrue(all.contains(png), "no lesson page shows " + png + " (made by TutorialScreenshotsTest in parpe-gui)");
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("lessons")
    void theWhatWentWrongBoxShowsWhatCheckPrints(Path page) throws IOException {
        whatWentWrong(page);
    }

    /** The translated lessons (issue 38): {@code docs/tutorial/LANG/NN-name.md}. */
    static List<Path> translatedLessons() throws IOException {
        List<Path> out = new ArrayList<>();
        for (java.util.Locale l : org.parpe.core.text.Lang.SUPPORTED.subList(1, org.parpe.core.text.Lang.SUPPORTED.size())) {
            Path dir = DOCS.resolve(l.getLanguage());
            if (Files.isDirectory(dir)) {
                try (Stream<Path> s = Files.list(dir)) {
                    s.filter(p -> p.getFileName().toString().matches("\\d\\d-.*\\.md")).sorted().forEach(out::add);
                }
            }
        }
        return out;
    }

    /** A translated lesson's box shows what {@code parpe check --lang LANG} prints, in that language. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("translatedLessons")
    void aTranslatedWhatWentWrongBoxShowsWhatCheckPrintsInItsLanguage(Path page) throws IOException {
        assertTrue(Files.isRegularFile(DOCS.resolve(name(page))), name(page) + " translates no lesson of " + DOCS);
        whatWentWrong(page, "--lang", page.getParent().getFileName().toString());
    }

    private void whatWentWrong(Path page, String... options) throws IOException {
        String text = Files.readString(page);
        Matcher edit = BREAK.matcher(text);
        assertTrue(edit.find(), name(page) + " has no <!-- what-went-wrong: replace `OLD` with `NEW` --> comment");
        Matcher shown = SHOWN.matcher(text);
        List<String> expected = new ArrayList<>();
        String script = null;
        while (shown.find()) {
            script = shown.group(1);
            expected.add(name(Path.of(script)) + ":" + shown.group(2));
        }
        assertFalse(expected.isEmpty(), name(page) + " shows no error message of a tutorial script");
        Path original = SCRIPTS.resolve(Path.of(script).getFileName());
        String source = Files.readString(original);
        assertTrue(source.contains(edit.group(1)), name(original) + " no longer contains `" + edit.group(1) + "`");
        Path broken = tmp.resolve(original.getFileName());
        Files.writeString(broken, source.replaceFirst(Pattern.quote(edit.group(1)), Matcher.quoteReplacement(edit.group(2))));
        Check c = check(broken, options);
        assertEquals(1, c.code(), "the broken copy should have errors:\n" + c.err());
        List<String> printed = c.err().lines().filter(l -> l.contains(": error: "))
                .map(l -> l.substring(l.lastIndexOf(name(original)))).toList();
        assertEquals(expected, printed, name(page) + ": the box no longer matches what parpe check prints");
    }

    static List<Path> pages() throws IOException {
        List<Path> out = new ArrayList<>(lessons());
        out.add(DOCS.resolve("index.md"));
        return out;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("pages")
    void theCommandsOfAPageRunAsPrinted(Path page) throws IOException {
        Matcher m = COMMAND.matcher(Files.readString(page));
        while (m.find()) {
            String[] args = m.group(1).trim().split("\\s+");
            boolean ours = true;
            for (int i = 0; i < args.length; i++) {
                if (args[i].endsWith(".xml")) {
                    ours &= args[i].startsWith("examples/tutorial/") || args[i].startsWith("examples/worlds/");
                    args[i] = "../" + args[i];
                }
            }
            if (!ours) {
                continue; // a student's own file, e.g. team-anna.xml
            }
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            // "--metrics -" writes to System.out itself (as SimCommandLineTest also captures it).
            PrintStream oldOut = System.out;
            PrintStream captured = new PrintStream(out, true, StandardCharsets.UTF_8);
            int code;
            try {
                System.setOut(captured);
                code = Main.execute(args, captured, new PrintStream(err, true, StandardCharsets.UTF_8));
            } finally {
                System.setOut(oldOut);
            }
            String e = err.toString(StandardCharsets.UTF_8);
            assertEquals(0, code, name(page) + ": './parpe " + m.group(1) + "' failed:\n" + e);
            assertFalse(e.contains("error") || e.contains("warning"), name(page) + ": './parpe " + m.group(1) + "' complained:\n" + e);
            String o = out.toString(StandardCharsets.UTF_8);
            assertTrue(o.contains("distance"), name(page) + ": './parpe " + m.group(1) + "' printed no distance:\n" + o);
        }
    }
}
