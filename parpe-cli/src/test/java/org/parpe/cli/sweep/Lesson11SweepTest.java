package org.parpe.cli.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Cli;

/**
 * Lesson 11's sweep, typed as the lesson prints it, names the best run the lesson names, and that
 * run did not fall over (issue 23, item 1: it crowned run 18, tilted 97.6°, fell=1). The IDE's
 * test of the same sweep (SweepDialogGuiTest) checks against the same line of the lesson.
 */
class Lesson11SweepTest {
    static final Path LESSON = Path.of("../docs/tutorial/11-optimise.md");

    @TempDir
    Path dir;

    @Test
    void theLessonsSweepNamesAnUprightBestRunAndItsPlotSetsFallenRunsApart() throws Exception {
        String text = Files.readString(LESSON);
        Matcher command = Pattern.compile("\n\\./parpe (sweep [^\n]+) --out my-sweep\\.csv\n").matcher(text);
        assertTrue(command.find(), "lesson 11 shows a sweep command");
        Matcher said = Pattern.compile("\n(parpe: best [^\n]+\\(run (\\d+)\\))\n").matcher(text);
        assertTrue(said.find(), "lesson 11 shows the best run");
        List<String> args = new ArrayList<>(List.of(command.group(1).replace(" examples/", " ../examples/").replace(" examples/", " ../examples/").split(" ")));
        Path csv = dir.resolve("my-sweep.csv");
        args.addAll(List.of("--out", csv.toString()));
        Cli r = Cli.run(args);
        assertEquals(0, r.code, r.err);
        assertTrue(r.err.contains(said.group(1) + "\n") || r.err.contains(said.group(1) + "\r\n"), r.err);
        String row = Files.readAllLines(csv).get(1 + Integer.parseInt(said.group(2)));
        assertTrue(row.startsWith(said.group(2) + ","), row);
        assertTrue(row.endsWith(",0,"), "the best run of lesson 11 did not fall over: " + row);
        // Some runs of this sweep fall over: the plot draws them as red rings, the others as grey dots.
        assertTrue(Files.readAllLines(csv).stream().anyMatch(l -> l.endsWith(",1,")));
        BufferedImage plot = ImageIO.read(dir.resolve("my-sweep.png").toFile());
        assertTrue(hasRed(plot), "fallen runs are drawn in red");
    }

    @Test
    void countFallenLetsAFallenRunBeTheBest() throws Exception {
        String text = Files.readString(LESSON);
        Matcher command = Pattern.compile("\n\\./parpe (sweep [^\n]+) --out my-sweep\\.csv\n").matcher(text);
        assertTrue(command.find());
        List<String> args = new ArrayList<>(List.of(command.group(1).replace(" examples/", " ../examples/").replace("--vary bend=10..70:7", "--vary bend=60..70:2").split(" ")));
        args.addAll(List.of("--out", "-", "--count-fallen"));
        Cli r = Cli.run(args);
        assertEquals(0, r.code, r.err);
        assertTrue(r.err.contains(", fell over)"), r.err);
        Cli upright = Cli.run(args.subList(0, args.size() - 1));
        // Every run with a bend of 60 or 70 fell over: by default none of them is the best.
        assertFalse(upright.err.contains("parpe: best"), upright.err);
        assertTrue(upright.err.contains("parpe: no best run: every run failed or fell over"), upright.err);
    }

    private static boolean hasRed(BufferedImage img) {
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                int rgb = img.getRGB(x, y);
                if (((rgb >> 16) & 0xff) > 180 && ((rgb >> 8) & 0xff) < 90 && (rgb & 0xff) < 90) {
                    return true;
                }
            }
        }
        return false;
    }
}
