package org.parpe.cli.diagram;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.parpe.cli.Cli;

/**
 * {@code parpe diagram}: SVG snapshots of each view, compared byte for byte with the golden files
 * in {@code src/test/resources/diagrams} (drawn, rendered and looked at when they were made; run
 * with {@code -Dparpe.updateGolden=true} to write them again, and with them the pictures of
 * docs/diagrams.md), and the command's errors.
 */
class DiagramCommandTest {
    private static final Path GOLDEN = Path.of("src/test/resources/diagrams");
    private static final Path DOCS = Path.of("../docs/images/diagrams");
    private static final boolean UPDATE = Boolean.getBoolean("parpe.updateGolden");

    /** A snapshot: its name and the command's arguments after the script. */
    record Snapshot(String name, String script, List<String> args) {
        @Override
        public String toString() {
            return name;
        }
    }

    static Stream<Snapshot> snapshots() {
        String centipede = "../examples/centipede-walk.xml";
        return Stream.of(
                new Snapshot("centipede-program", centipede, List.of("--view", "program")),
                new Snapshot("centipede-lanes", centipede, List.of("--view", "lanes")),
                new Snapshot("centipede-ring-step", centipede, List.of("--view", "ring", "--automaton", "step")),
                new Snapshot("centipede-phase-rightswing", centipede, List.of("--view", "phase", "--instance", "1")),
                new Snapshot("centipede-gait", centipede, List.of("--view", "gait", "--duration", "6")),
                new Snapshot("standup-walk-program", "../examples/standup-walk.xml", List.of()),
                new Snapshot("sensor-exit-ring", "../examples/sensor-exit.xml", List.of("--view", "ring")),
                new Snapshot("teleop-lanes", "../examples/teleop-dirwave.xml", List.of("--view", "lanes")),
                new Snapshot("gait-table-12-gait", "../examples/gait-table-12.xml", List.of("--view", "gait", "--duration", "4")),
                new Snapshot("hello-snake-phase", "../examples/hello-snake.xml", List.of("--view", "phase")),
                new Snapshot("island-ring", "src/test/resources/diagrams/island.xml", List.of("--view", "ring")),
                new Snapshot("island-phase", "src/test/resources/diagrams/island.xml", List.of("--view", "phase")),
                // docking (PARSL 1.1 §14): the dock readings an exit waits on, the latch mark of a state
                new Snapshot("docking-program", "../examples/docking-snake-loop.xml", List.of("--view", "program")),
                new Snapshot("docking-ring", "src/test/resources/diagrams/docking-ring.xml",
                        List.of("--view", "ring", "--automaton", "reach")));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("snapshots")
    void eachViewDrawsItsGoldenSvg(Snapshot s, @TempDir Path dir) throws Exception {
        Path out = dir.resolve(s.name() + ".svg");
        List<String> args = new ArrayList<>(List.of("diagram", s.script(), "--out", out.toString()));
        args.addAll(s.args());
        Cli r = Cli.run(args);
        assertEquals(0, r.code, r::toString);
        String svg = Files.readString(out);
        Path golden = GOLDEN.resolve(s.name() + ".svg");
        if (UPDATE) {
            Files.writeString(golden, svg);
            List<String> png = new ArrayList<>(args);
            png.set(3, DOCS.resolve(s.name() + ".png").toString());
            Files.createDirectories(DOCS);
            assertEquals(0, Cli.run(png).code);
        }
        assertEquals(Files.readString(golden), svg, "differs from " + golden + "; look at both, then update");
    }

    @Test
    void aPngHasTheSceneSizeAndIsDrawn(@TempDir Path dir) throws Exception {
        Path out = dir.resolve("ring.png");
        Cli r = Cli.run("diagram", "../examples/centipede-walk.xml", "--view", "ring", "--out", out.toString());
        assertEquals(0, r.code, r::toString);
        BufferedImage img = ImageIO.read(out.toFile());
        assertEquals(760, img.getWidth());
        // the first arc (reach, orange 0xe69f00) lies right of the top of the ring, centred at (380, 290)
        assertEquals(0xe69f00, img.getRGB(380 + 100, 290 - 100) & 0xffffff);
        assertEquals(0xffffff, img.getRGB(380 - 60, 290 + 60) & 0xffffff, "inside the band, beside the words, is empty");
    }

    /** The first point of {@code rgb} whose neighbours two pixels away have that colour too. */
    private static int[] inside(BufferedImage img, int rgb) {
        for (int y = 2; y < img.getHeight() - 2; y++) {
            for (int x = 2; x < img.getWidth() - 2; x++) {
                if ((img.getRGB(x, y) & 0xffffff) == rgb && (img.getRGB(x - 2, y - 2) & 0xffffff) == rgb
                        && (img.getRGB(x + 2, y + 2) & 0xffffff) == rgb && (img.getRGB(x + 2, y - 2) & 0xffffff) == rgb
                        && (img.getRGB(x - 2, y + 2) & 0xffffff) == rgb) {
                    return new int[] {x, y};
                }
            }
        }
        throw new AssertionError("no area of colour " + Integer.toHexString(rgb));
    }

    /**
     * Issue 31 item 3.4: a PNG had only the diagram's own size. {@code --width} scales it; the
     * height follows, and the picture is the same one, larger.
     */
    @Test
    void widthScalesThePng(@TempDir Path dir) throws Exception {
        Path own = dir.resolve("own.png");
        assertEquals(0, Cli.run("diagram", "../examples/centipede-walk.xml", "--view", "ring", "--out", own.toString()).code);
        BufferedImage small = ImageIO.read(own.toFile());
        int width = 2 * small.getWidth();
        Path out = dir.resolve("ring.png");
        Cli r = Cli.run("diagram", "../examples/centipede-walk.xml", "--view", "ring", "--width", String.valueOf(width),
                "--out", out.toString());
        assertEquals(0, r.code, r::toString);
        BufferedImage big = ImageIO.read(out.toFile());
        assertEquals(width, big.getWidth());
        assertEquals(2 * small.getHeight(), big.getHeight());
        // a point well inside the first arc (its colour all round it) is twice as far out in the larger picture
        int[] at = inside(small, 0xe69f00);
        assertEquals(0xe69f00, big.getRGB(2 * at[0], 2 * at[1]) & 0xffffff);
        for (String[] bad : new String[][] {{"--width", "0", "x.png"}, {"--width", "20000", "x.png"},
            {"--width", "800", "x.svg"}}) {
            Cli refused = Cli.run("diagram", "../examples/centipede-walk.xml", "--view", "ring", bad[0], bad[1], "--out",
                    dir.resolve(bad[2]).toString());
            assertEquals(2, refused.code, refused::toString);
            assertTrue(refused.err.startsWith("parpe: --width "), refused.err);
            assertFalse(Files.exists(dir.resolve(bad[2])));
        }
    }

    @Test
    void badRequestsAreUsageErrorsThatWriteNothing(@TempDir Path dir) throws Exception {
        Path out = dir.resolve("x.svg");
        Cli ext = Cli.run("diagram", "../examples/centipede-walk.xml", "--out", dir.resolve("x.pdf").toString());
        assertEquals(2, ext.code, ext::toString);
        assertTrue(ext.err.contains("--out must name a .svg or .png file"), ext.err);
        Cli beh = Cli.run("diagram", "../examples/centipede-walk.xml", "--view", "lanes", "--behavior", "wlak",
                "--out", out.toString());
        assertEquals(2, beh.code, beh::toString);
        assertTrue(beh.err.contains("no behavior 'wlak'") && beh.err.contains("walk"), beh.err);
        Cli inst = Cli.run("diagram", "../examples/centipede-walk.xml", "--view", "phase", "--instance", "9",
                "--out", out.toString());
        assertEquals(2, inst.code, inst::toString);
        assertTrue(inst.err.contains("--instance must be in 0..3"), inst.err);
        Cli longGait = Cli.run("diagram", "../examples/centipede-walk.xml", "--view", "gait", "--duration", "1e6",
                "--out", out.toString());
        assertEquals(2, longGait.code, longGait::toString);
        assertTrue(longGait.err.contains("more than 100000 ticks"), longGait.err);
        assertFalse(Files.exists(out));
        Path input = dir.resolve("in.xml");
        Files.copy(Path.of("../examples/hello-snake.xml"), input);
        Cli same = Cli.run("diagram", input.toString(), "--out", input.toString().replace(".xml", ".svg"));
        assertEquals(0, same.code, same::toString);
        Cli clobber = Cli.run("diagram", input.toString(), "--out", input.toString());
        assertEquals(2, clobber.code, clobber::toString);
        assertEquals(Files.readString(Path.of("../examples/hello-snake.xml")), Files.readString(input), "the script is kept");
    }

    @Test
    void aScriptWithErrorsIsReportedAtItsPlace(@TempDir Path dir) throws Exception {
        Path bad = dir.resolve("bad.xml");
        Files.writeString(bad, "<program>\n  <robot><structure><b elements=\"0\"/></structure></robot>\n"
                + "  <main><nothing/></main>\n</program>\n");
        Cli r = Cli.run("diagram", bad.toString(), "--out", dir.resolve("x.svg").toString());
        assertEquals(1, r.code, r::toString);
        assertTrue(r.err.contains(bad + ":3:"), r.err);
        assertFalse(Files.exists(dir.resolve("x.svg")));
    }

    /**
     * Issue 31 item 5: a PNG had no size limit (10 000 {@code <main>} entries made a program lane
     * over a million pixels wide, gigabytes in memory; beyond, a bare number). A PNG over the
     * limit is refused with the size and the way out; the SVG of the same diagram is exact.
     */
    @Test
    void aPngTooLargeIsRefusedAndTheSvgIsDrawnExactly(@TempDir Path dir) throws Exception {
        StringBuilder main = new StringBuilder();
        for (int i = 0; i < 1000; i++) {
            main.append("<b time=\"1\"/>\n");
        }
        Path script = Files.writeString(dir.resolve("long.xml"), "<program>\n<robot><structure><g elements=\"0, 1\"/>"
                + "</structure></robot>\n<main>\n" + main + "</main>\n<behaviors><b><w group=\"g\"/></b></behaviors>\n"
                + "<automata><w states=\"s\"/></automata>\n<states><s angles=\"10\"/></states>\n</program>\n");
        Path svg = dir.resolve("long.svg");
        Cli ok = Cli.run("diagram", script.toString(), "--out", svg.toString());
        assertEquals(0, ok.code, ok.toString());
        String head = Files.readString(svg).lines().findFirst().orElseThrow();
        String width = head.replaceAll(".* width=\"(\\d+)\".*", "$1");
        assertTrue(Integer.parseInt(width) > ScenePng.MAX_SIDE, head);
        Path png = dir.resolve("long.png");
        Cli r = Cli.run("diagram", script.toString(), "--out", png.toString());
        assertEquals(2, r.code, r.toString());
        assertEquals("parpe: cannot draw the program diagram as --out file '" + png + "': it would be " + width
                + " x 168 px, more than a PNG PARPE draws (at most 32767 px a side and 67108864 pixels, 256 MiB in"
                + " memory); write an .svg file, which is drawn exactly at any size\n", r.err);
        assertFalse(Files.exists(png));
    }
}
