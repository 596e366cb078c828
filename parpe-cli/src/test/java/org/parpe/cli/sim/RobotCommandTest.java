package org.parpe.cli.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Cli;
import org.parpe.core.diagram.Labels;
import org.parpe.core.diagram.Scene;

/**
 * {@code parpe robot}: located problems with {@code --check} and {@code --kit}, and the
 * worksheet drawing, compared byte for byte with the golden SVGs in
 * {@code src/test/resources/robots} (rendered as PNG and looked at when they were made; run with
 * {@code -Dparpe.updateGolden=true} to write them again, and with them docs/images/robots).
 */
class RobotCommandTest {
    private static final Path GOLDEN = Path.of("src/test/resources/robots");
    private static final Path DOCS = Path.of("../docs/images/robots");
    private static final boolean UPDATE = Boolean.getBoolean("parpe.updateGolden");

    @TempDir
    Path dir;

    @ParameterizedTest
    @ValueSource(strings = {"tee-snake", "wheel6"})
    void theSheetOfAnExampleIsItsGoldenSvg(String name) throws Exception {
        Path out = dir.resolve(name + ".svg");
        Cli r = Cli.run("robot", "../examples/configs/" + name + ".xml", "--out", out.toString());
        assertEquals(0, r.code, r::toString);
        String svg = Files.readString(out);
        Path golden = GOLDEN.resolve(name + ".svg");
        if (UPDATE) {
            Files.writeString(golden, svg);
            Files.createDirectories(DOCS);
            assertEquals(0, Cli.run("robot", "../examples/configs/" + name + ".xml", "--out",
                    DOCS.resolve(name + ".png").toString()).code);
        }
        assertEquals(Files.readString(golden), svg, "differs from " + golden + "; look at both, then update");
    }

    /** A module-ID label of the sheet's views: bold, 11 px, centred. */
    private static final Pattern ID_LABEL = Pattern.compile("<text x=\"([0-9.]+)\" y=\"([0-9.]+)\" font-size=\"11\""
            + " text-anchor=\"middle\" font-weight=\"bold\" fill=\"#222222\">([^<]*)</text>");

    /**
     * In each of the three views no two module IDs meet or stand closer than 2 px side by side,
     * where "52" and "50" would read "5250" (boxes as {@link Labels#box} estimates them), and
     * every hinge's ID is still there, alone or in a merged label "3, 4" or "5-9"
     * (humanoid15's front view also moves labels aside with a leader line; the 55-module
     * centipede of the paper's Fig. 2, 197 cm long in a 300 px view, crowds every view: issue 33
     * item 5 found its IDs printed over each other).
     */
    @ParameterizedTest
    @CsvSource({"../examples/configs/tee-snake.xml, 5", "../examples/configs/wheel6.xml, 6",
        "../examples/configs/humanoid15.xml, 15", "centipede, 55"})
    void theModuleIdsOfAViewNeverOverlap(String robot, int hinges) throws Exception {
        Path out = dir.resolve("sheet.svg");
        assertEquals(0, Cli.run("robot", robot, "--out", out.toString()).code);
        List<List<Scene.Text>> views = List.of(new ArrayList<>(), new ArrayList<>(), new ArrayList<>());
        Matcher m = ID_LABEL.matcher(Files.readString(out));
        while (m.find()) {
            Scene.Text t = new Scene.Text(Double.parseDouble(m.group(1)), Double.parseDouble(m.group(2)), m.group(3), 11, 0,
                    0x222222, true);
            views.get((int) ((t.x() - 20) / 320)).add(t);
        }
        for (int v = 0; v < 3; v++) {
            List<Scene.Text> texts = views.get(v);
            TreeSet<Integer> ids = new TreeSet<>();
            for (Scene.Text t : texts) {
                for (String run : t.text().split(", ")) {
                    String[] ends = run.split("-");
                    for (int id = Integer.parseInt(ends[0]); id <= Integer.parseInt(ends[ends.length - 1]); id++) {
                        assertTrue(ids.add(id), "view " + v + " shows " + id + " twice");
                    }
                }
            }
            assertEquals(hinges, ids.size(), "view " + v + " shows " + ids);
            for (int i = 0; i < texts.size(); i++) {
                for (int j = i + 1; j < texts.size(); j++) {
                    Labels.Box a = Labels.box(texts.get(i));
                    Labels.Box apart = new Labels.Box(a.x() - 2, a.y(), a.w() + 4, a.h());
                    assertFalse(apart.overlaps(Labels.box(texts.get(j))), "view " + v + ": '"
                            + texts.get(i).text() + "' meets '" + texts.get(j).text() + "'");
                }
            }
        }
    }

    @Test
    void aPngIsTheSheetsSizeAndShowsTheModules(@TempDir Path d) throws Exception {
        Path out = d.resolve("h.png");
        Cli r = Cli.run("robot", "humanoid", "--out", out.toString());
        assertEquals(0, r.code, r::toString);
        BufferedImage img = ImageIO.read(out.toFile());
        assertEquals(980, img.getWidth());
        // three views and 20 rows of parts (the list ends below the views)
        assertTrue(img.getHeight() > 390 + 20 * 16, img.getWidth() + " x " + img.getHeight());
        int segment = 0;
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                segment += (img.getRGB(x, y) & 0xffffff) == 0x0072b2 ? 1 : 0;
            }
        }
        assertTrue(segment > 500, "segments are drawn in their colour: " + segment + " pixels");
    }

    @Test
    void checkReportsEveryProblemLocatedAndExitsOne() throws Exception {
        Path f = dir.resolve("bad.xml");
        Files.writeString(f, """
                <robot-config>
                  <part name="a" type="segment" id="0"/>
                  <part name="b" type="segmnt" id="1"/>
                  <part name="c" type="segment" id="2"/>
                  <connect from="a.1" to="c.0"/>
                  <connect from="a.1" to="c.1"/>
                </robot-config>
                """);
        Cli r = Cli.run("robot", f.toString(), "--check");
        assertEquals(1, r.code, r::toString);
        assertTrue(r.err.contains(f + ":3:3: error: unknown part type 'segmnt'"), r.err);
        assertFalse(r.err.contains("Exception"), r.err);
        Cli ok = Cli.run("robot", "../examples/configs/tee-snake.xml", "--check");
        assertEquals(0, ok.code, ok::toString);
        assertEquals("../examples/configs/tee-snake.xml: ok (5 segments, 1 node, 2 feet)\n", ok.out);
    }

    @Test
    void theKitIsCheckedAndWhatIsLeftIsSaid() throws Exception {
        Path kit = dir.resolve("kit.xml");
        Files.writeString(kit, "<kit>\n  <part type=\"segment\" count=\"8\"/>\n  <part type=\"foot\" count=\"8\"/>\n</kit>\n");
        Cli fits = Cli.run("robot", "snake:n=6", "--kit", kit.toString());
        assertEquals(0, fits.code, fits::toString);
        assertEquals("snake:n=6: ok (6 segments); the kit keeps 2 segments, 0 nodes, 8 feet, 0 hubs\n", fits.out);
        Cli over = Cli.run("robot", "../examples/configs/wheel6.xml", "--kit", kit.toString(), "--check");
        assertEquals(1, over.code, over::toString);
        assertTrue(over.err.contains("wheel6.xml:5:3: error: hub 'hub' is beyond the kit"), over.err);
    }

    @Test
    void usageErrors() {
        assertEquals(2, Cli.run("robot", "snake", "--out", dir.resolve("x.pdf").toString()).code);
        assertEquals(2, Cli.run("robot", "snake", "--check", "--out", dir.resolve("x.svg").toString()).code);
        Cli missing = Cli.run("robot", dir.resolve("nope.xml").toString());
        assertEquals(2, missing.code, missing::toString);
        assertTrue(missing.err.startsWith("parpe: cannot read '"), missing.err);
    }
}
