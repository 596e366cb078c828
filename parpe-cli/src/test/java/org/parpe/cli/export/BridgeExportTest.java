package org.parpe.cli.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Cli;

/**
 * {@code parpe export --target mjcf|urdf|sdf} (issue 34): every generator's robot and every
 * example configuration exports to the three formats, and the real tools accept the results:
 * check_urdf, ign sdf -k (also on the URDF converted by ign sdf -p), MuJoCo 2.2.2's compiler and
 * MuJoCo 3, where the robots step with no warning and the loop robots hold their pose for 20 s
 * with every loop closed within 1 mm. Bad input gets located messages and nothing is written.
 */
class BridgeExportTest {
    static final List<String> ROBOTS = List.of("snake:n=8", "snake:n=12,axes=alternate", "loop", "loop:n=12", "wheel",
            "centipede", "humanoid", "../examples/configs/tee-snake.xml", "../examples/configs/wheel6.xml");

    @TempDir
    Path dir;

    private List<Path> export(String target) {
        List<Path> files = new ArrayList<>();
        for (String robot : ROBOTS) {
            Path out = dir.resolve(target);
            Cli r = Cli.run("export", "--target", target, "--robot", robot, "--out", out.toString());
            assertEquals(0, r.code, robot + ": " + r);
            String name = r.out.substring(r.out.indexOf(": ") + 2, r.out.indexOf('\n')).trim();
            files.add(out.resolve(name));
        }
        return files;
    }

    @Test
    void everyRobotExportsWithItsModulesAsJoints() throws Exception {
        for (String target : List.of("mjcf", "urdf", "sdf")) {
            for (Path f : export(target)) {
                String text = Files.readString(f);
                assertTrue(text.contains("name=\"m0\"") || text.contains("name=\"m1\""), f + " names its joints m<ID>");
            }
        }
        String mjcf = Files.readString(dir.resolve("mjcf/loop.xml"));
        assertTrue(mjcf.contains("<weld name=\"s5_arm__s0_base\""), "the loop is closed by a weld:\n" + mjcf);
        assertEquals(6, mjcf.split("<general name=\"m").length - 1, "one servo per module");
        String urdf = Files.readString(dir.resolve("urdf/loop.urdf"));
        assertTrue(urdf.contains("<gazebo>") && urdf.contains("<joint name=\"s5_arm__s0_base\" type=\"fixed\">"), urdf);
    }

    @Test
    void theRealToolsAcceptEveryExport() throws Exception {
        BridgeTools.require("check_urdf", "ign", "mujoco-compile");
        for (Path f : export("urdf")) {
            String out = BridgeTools.run(dir, List.of("check_urdf", f.toString()));
            assertTrue(out.contains("Successfully Parsed XML"), f + ": " + out);
            Path converted = dir.resolve(f.getFileName() + ".sdf");
            Files.writeString(converted, BridgeTools.run(dir, List.of("ign", "sdf", "-p", f.toString()))
                    .replaceAll("(?m)^Library error.*\\R", ""));
            assertTrue(BridgeTools.run(dir, List.of("ign", "sdf", "-k", converted.toString())).contains("Valid."), converted.toString());
        }
        for (Path f : export("sdf")) {
            assertTrue(BridgeTools.run(dir, List.of("ign", "sdf", "-k", f.toString())).contains("Valid."), f.toString());
        }
        int n = 0;
        for (Path f : export("mjcf")) {
            String out = BridgeTools.run(dir, List.of("mujoco-compile", f.toString(), dir.resolve("m" + n++ + ".mjb").toString()));
            assertTrue(out.contains("Done"), f + ": " + out);
        }
    }

    @Test
    void mujoco3HoldsEveryRobotWithItsLoopsClosed() throws Exception {
        String py = BridgeTools.python();
        List<String> cmd = new ArrayList<>(List.of(py, Path.of("src/test/resources/bridge/mujoco_check.py").toAbsolutePath().toString()));
        // robots with loops are held for 20 s (the loops must stay closed), the others for 2 s (they load and step)
        export("mjcf").forEach(f -> cmd.add(f + (f.getFileName().toString().startsWith("loop") ? "@20" : "@2")));
        String out = BridgeTools.run(dir, cmd);
        List<String> lines = out.lines().filter(l -> l.contains("loop_mm=")).toList();
        assertEquals(ROBOTS.size(), lines.size(), out);
        for (String l : lines) {
            assertTrue(l.contains("warnings=none"), l);
            assertTrue(l.contains("finite=True"), l);
            double mm = Double.parseDouble(l.replaceAll(".*loop_mm=([0-9.]+).*", "$1"));
            assertTrue(mm <= 1.0, "a loop opened by more than 1 mm: " + l);
        }
    }

    @Test
    void aGaitPlaysInMujocoWithOneRowPerTick() throws Exception {
        String py = BridgeTools.python();
        Path out = dir.resolve("hs");
        Cli r = Cli.run("export", "--target", "mjcf", "--robot", "snake:n=8", "--out", out.toString(), "--duration", "2",
                "../examples/hello-snake.xml");
        assertEquals(0, r.code, r.toString());
        assertTrue(Files.exists(out.resolve("play_mujoco.py")) && Files.exists(out.resolve("snake_n_8.ctrl.csv")), r.out);
        Path trace = dir.resolve("mj.csv");
        BridgeTools.run(dir, List.of(py, out.resolve("play_mujoco.py").toString(), out.resolve("snake_n_8.xml").toString(),
                out.resolve("snake_n_8.ctrl.csv").toString(), "--out", trace.toString()));
        Path parpe = dir.resolve("parpe.csv");
        Cli run = Cli.run("run", "../examples/hello-snake.xml", "--sim", "snake:n=8", "--duration", "2", "--trace", parpe.toString());
        assertEquals(0, run.code, run.toString());
        assertEquals(Files.readAllLines(parpe).size(), Files.readAllLines(trace).size(), "one row per tick in both");
        assertTrue(Files.readAllLines(trace).get(0).matches("time(,a[0-9]+){8},com_x,com_y,com_z"), "PARPE's trace columns");
        // how far it goes in both is MujocoCrossCheckTest's
    }

    /**
     * Issue 35 item 3: a script with latches (PARSL 1.1 §14) exports its latchable plate pair as
     * inactive welds that both MuJoCo 2.2.2's compiler and MuJoCo 3 load with no warning; the
     * gait carries the run's plate actions, and played in MuJoCo the curled snake's ends latch
     * (a weld switches on) and the release parts them (it switches off).
     */
    @Test
    void aDockingSnakeLatchesAndLetsGoInMujoco() throws Exception {
        BridgeTools.require("mujoco-compile");
        String py = BridgeTools.python();
        Path out = dir.resolve("dock");
        Cli r = Cli.run("export", "--target", "mjcf", "--robot", "snake:n=10", "--out", out.toString(), "--duration", "25",
                "../examples/docking-snake-loop.xml");
        assertEquals(0, r.code, r.toString());
        assertTrue(r.out.contains("1 latchable plate pair"), r.out);
        Path model = out.resolve("snake_n_10.xml");
        String mjcf = Files.readString(model);
        // the end modules 0 and 9 carry the latches; their free plates are 0.0 and 9.1, four welds (one per 90° step)
        assertEquals(4, mjcf.split("<weld name=\"latch_plate0_0__plate9_1_r").length - 1, mjcf);
        assertEquals(4, mjcf.split("active=\"false\"").length - 1, mjcf);
        List<String> gait = Files.readAllLines(out.resolve("snake_n_10.ctrl.csv"));
        assertTrue(gait.get(0).endsWith(",m9,plate0_0,plate9_1"), gait.get(0));
        assertTrue(gait.stream().anyMatch(l -> l.endsWith(",2,2")), "the let_go state releases both plates");
        assertTrue(BridgeTools.run(dir, List.of("mujoco-compile", model.toString(), dir.resolve("dock.mjb").toString()))
                .contains("Done"));
        String check = BridgeTools.run(dir, List.of(py, Path.of("src/test/resources/bridge/mujoco_check.py")
                .toAbsolutePath().toString(), model + "@1"));
        assertTrue(check.contains("warnings=none") && check.contains("finite=True"), check);
        Path events = dir.resolve("latches.csv");
        BridgeTools.run(dir, List.of(py, out.resolve("play_mujoco.py").toString(), model.toString(),
                out.resolve("snake_n_10.ctrl.csv").toString(), "--out", dir.resolve("mj.csv").toString(), "--latches",
                events.toString()));
        List<String> lines = Files.readAllLines(events);
        assertEquals(3, lines.size(), "one latch, one release: " + lines);
        assertTrue(lines.get(1).matches("[0-9.]+,latch,latch_plate0_0__plate9_1_r[0-9]+"), lines.toString());
        assertTrue(lines.get(2).matches("[0-9.]+,release,latch_plate0_0__plate9_1_r[0-9]+"), lines.toString());
        double latched = Double.parseDouble(lines.get(1).split(",")[0]);
        double released = Double.parseDouble(lines.get(2).split(",")[0]);
        assertTrue(latched < released, lines.toString());
    }

    @Test
    void badInputGetsLocatedMessagesAndWritesNothing() throws Exception {
        Path config = dir.resolve("bad.xml");
        Files.writeString(config, """
                <robot-config>
                  <part name="s0" type="segment" id="0"/>
                  <part name="s1" type="segment" id="1"/>
                  <connect from="s0.1" to="s9.0"/>
                </robot-config>
                """);
        Path out = dir.resolve("out");
        Cli r = Cli.run("export", "--target", "urdf", "--robot", config.toString(), "--out", out.toString());
        assertEquals(1, r.code, r.toString());
        assertTrue(r.err.startsWith(config + ":4:"), r.err);
        assertFalse(Files.exists(out), "nothing written");
        Path named = dir.resolve("named.xml");
        Files.writeString(named, "<robot-config>\n  <part name=\"world\" type=\"segment\" id=\"0\"/>\n</robot-config>\n");
        r = Cli.run("export", "--target", "sdf", "--robot", named.toString(), "--out", out.toString());
        assertEquals(1, r.code, r.toString());
        assertTrue(r.err.startsWith(named + ":2:") && r.err.contains("part name 'world' cannot be a SDF name"), r.err);
        assertFalse(Files.exists(out), "nothing written");
        Path file = dir.resolve("file");
        Files.writeString(file, "keep");
        r = Cli.run("export", "--target", "mjcf", "--robot", "snake:n=3", "--out", file.toString());
        assertEquals(2, r.code, r.toString());
        assertTrue(r.err.contains("is a file, not a folder"), r.err);
        assertEquals("keep", Files.readString(file));
        r = Cli.run("export", "--target", "mjcf", "--out", out.toString());
        assertEquals(2, r.code, r.toString());
        assertTrue(r.err.contains("--target mjcf needs --robot"), r.err);
    }

    /** A configuration of several robots (one per root, docs/simulator.md) is refused: an export writes one robot. */
    @Test
    void aConfigurationOfTwoRobotsIsRefused() throws Exception {
        Path out = dir.resolve("two");
        Cli r = Cli.run("export", "--target", "urdf", "--robot", "../examples/configs/two-snakes.xml", "--out", out.toString());
        assertEquals(1, r.code, r.toString());
        assertTrue(r.err.contains("the configuration holds 2 robots (one per <root>)"), r.err);
        assertFalse(Files.exists(out), "nothing written");
    }
}
