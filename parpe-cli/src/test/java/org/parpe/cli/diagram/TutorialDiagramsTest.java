package org.parpe.cli.diagram;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.parpe.cli.Cli;

/**
 * The diagrams of tutorial lessons 3–6 and 14, drawn by {@code parpe diagram} from the lessons'
 * own scripts into {@code docs/tutorial/img/} (folder: system property
 * {@code parpe.tutorialImages}) on every test run, so that the pictures always match the
 * scripts. Each must be drawn (many colours, the scene's width) and the command must succeed.
 */
class TutorialDiagramsTest {

    static Stream<DiagramCommandTest.Snapshot> pictures() {
        String t = "../examples/tutorial/";
        return Stream.of(
                new DiagramCommandTest.Snapshot("03-diagram-ring", t + "03-hello-snake.xml", List.of("--view", "ring")),
                new DiagramCommandTest.Snapshot("03-diagram-gait", t + "03-hello-snake.xml", List.of("--view", "gait", "--duration", "3")),
                new DiagramCommandTest.Snapshot("04-diagram-phase", t + "04-waves-snake.xml", List.of("--view", "phase")),
                new DiagramCommandTest.Snapshot("04-diagram-gait", t + "04-waves-snake.xml", List.of("--view", "gait", "--duration", "3")),
                new DiagramCommandTest.Snapshot("05-diagram-lanes", t + "05-centipede-mirror.xml", List.of("--view", "lanes")),
                new DiagramCommandTest.Snapshot("05-diagram-ring-step", t + "05-centipede-mirror.xml", List.of("--view", "ring", "--automaton", "step")),
                new DiagramCommandTest.Snapshot("06-diagram-program", t + "06-standup-walk-centipede.xml", List.of("--view", "program")),
                new DiagramCommandTest.Snapshot("06-diagram-gait", t + "06-standup-walk-centipede.xml", List.of("--view", "gait", "--duration", "20")));
    }

    @ParameterizedTest
    @MethodSource("pictures")
    void eachLessonDiagramIsDrawnFromItsScript(DiagramCommandTest.Snapshot p) throws Exception {
        Path dir = Path.of(System.getProperty("parpe.tutorialImages", "../docs/tutorial/img"));
        Files.createDirectories(dir);
        Path png = dir.resolve(p.name() + ".png");
        List<String> args = new ArrayList<>(List.of("diagram", p.script()));
        args.addAll(p.args());
        args.addAll(List.of("--out", png.toString()));
        Cli r = Cli.run(args.toArray(String[]::new));
        assertEquals(0, r.code, r::toString);
        BufferedImage img = ImageIO.read(png.toFile());
        assertTrue(img.getWidth() >= 400, png + " is " + img.getWidth() + " px wide");
        Set<Integer> colours = new HashSet<>();
        for (int y = 0; y < img.getHeight(); y += 3) {
            for (int x = 0; x < img.getWidth(); x += 3) {
                colours.add(img.getRGB(x, y) & 0xffffff);
            }
        }
        assertTrue(colours.size() >= 6, png + " has only " + colours.size() + " colours: not drawn");
    }
}
