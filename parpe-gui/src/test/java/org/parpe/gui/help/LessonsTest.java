package org.parpe.gui.help;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Help → Tutorial in the IDE's language (issue 38): a lesson from the language's folder where
 * it is translated, the English one where it is not, a picture in the language where the tests
 * made one; and the translated lessons of {@code docs/tutorial/LANG/}, whose every link and
 * picture must lead to a file.
 */
class LessonsTest {
    private static final Path TUTORIAL = Path.of("../docs/tutorial");

    @Test
    void translatedPagesComeFromTheLanguagesFolderTheOthersInEnglish(@TempDir Path dir) throws IOException {
        for (String f : List.of("index.md", "01-poses.md", "07-parameters.md", "teachers.md", "de/index.md",
                "de/01-poses.md", "img/a.png", "img/a-de.png")) {
            Files.createDirectories(dir.resolve(f).getParent());
            Files.writeString(dir.resolve(f), "# " + f + "\n");
        }
        List<Path> english = List.of(dir.resolve("index.md"), dir.resolve("01-poses.md"), dir.resolve("07-parameters.md"),
                dir.resolve("teachers.md"));
        assertEquals(english, Lessons.pages(dir, Locale.ENGLISH));
        assertEquals(List.of(dir.resolve("de/index.md"), dir.resolve("de/01-poses.md"), dir.resolve("07-parameters.md"),
                dir.resolve("teachers.md")), Lessons.pages(dir, Locale.GERMAN));
        assertEquals(english, Lessons.pages(dir, Locale.JAPANESE), "no Japanese folder: every page in English");

        assertEquals(dir.resolve("img/a-de.png"), Lessons.picture(dir.resolve("img/a.png"), Locale.GERMAN));
        assertEquals(dir.resolve("img/a.png"), Lessons.picture(dir.resolve("img/a.png"), Locale.JAPANESE));
        assertEquals(dir.resolve("img/a.png"), Lessons.picture(dir.resolve("img/a.png"), Locale.ENGLISH));
    }

    @ParameterizedTest
    @ValueSource(strings = {"de", "es", "ja"})
    void theIndexAndLessonsOneToSixAreTranslatedAndEveryLinkLeadsToAFile(String lang) throws IOException {
        List<Path> pages = Lessons.pages(TUTORIAL, Locale.forLanguageTag(lang));
        Path own = TUTORIAL.resolve(lang);
        List<String> translated = pages.stream().filter(p -> p.startsWith(own)).map(p -> p.getFileName().toString()).toList();
        assertEquals(List.of("index.md", "01-poses.md", "02-gait-tables.md", "03-phase-automata.md",
                "04-travelling-waves.md", "05-parallel-and-mirroring.md", "06-sequences.md"), translated);
        assertEquals(Lessons.pages(TUTORIAL).size(), pages.size(), "every lesson is in the list, translated or not");
        List<String> broken = new ArrayList<>();
        for (Path page : pages.stream().filter(p -> p.startsWith(own)).toList()) {
            Markdown.Page parsed = Markdown.parse(Files.readString(page));
            List<String> targets = new ArrayList<>(parsed.links());
            parsed.blocks().stream().filter(b -> b.kind() == Markdown.Kind.IMAGE).forEach(b -> targets.add(b.target()));
            for (String t : targets) {
                String file = t.replaceFirst("#.*$", "");
                if (!t.startsWith("http") && !file.isEmpty() && !Files.exists(page.getParent().resolve(file))) {
                    broken.add(page.getFileName() + ": " + t);
                }
            }
            assertTrue(Files.readString(page).lines().anyMatch(l -> l.startsWith("# ")), page + " has no title");
        }
        assertEquals(List.of(), broken, "links of docs/tutorial/" + lang + " that lead nowhere");
    }

    /**
     * Issue 38, "the pictures regenerated per language where they show text": every picture a
     * translated lesson shows or links ({@code ../img/NAME.png}) is the IDE in the lesson's language
     * ({@code NAME-de.png}, made by TutorialScreenshotsTest or the lesson's {@code parpe gui --lang}
     * command) and exists, except the diagrams {@code NN-diagram-*.png}, which {@code parpe diagram}
     * draws from the script's own names without the IDE.
     */
    @ParameterizedTest
    @ValueSource(strings = {"de", "es", "ja"})
    void translatedLessonsShowTheIdeInTheirLanguage(String lang) throws IOException {
        List<String> wrong = new ArrayList<>();
        int own = 0;
        for (Path page : Lessons.pages(TUTORIAL, Locale.forLanguageTag(lang))) {
            if (!page.startsWith(TUTORIAL.resolve(lang))) {
                continue;
            }
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("\\(\\.\\./img/([^)]+\\.png)\\)").matcher(Files.readString(page));
            while (m.find()) {
                String name = m.group(1);
                boolean diagram = name.matches("\\d\\d-diagram-.*");
                if (!diagram && !name.endsWith("-" + lang + ".png") || !Files.isRegularFile(TUTORIAL.resolve("img").resolve(name))) {
                    wrong.add(page.getFileName() + ": " + name);
                }
                own += diagram ? 0 : 1;
            }
        }
        assertEquals(List.of(), wrong, "pictures of docs/tutorial/" + lang + " not in its language, or missing");
        assertTrue(own >= 10, "the lessons show the IDE in " + lang + " " + own + " times");
    }
}
