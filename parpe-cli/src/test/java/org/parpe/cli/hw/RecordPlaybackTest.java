package org.parpe.cli.hw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayOutputStream;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.Cli;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Automaton;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.link.PtyPair;
import picocli.CommandLine;

/**
 * Posable programming end to end: the emulator's limp modules are posed by hand, {@code parpe
 * record} captures each pose on Enter, and {@code parpe run} plays the file back so that the
 * modules pass through the captured poses.
 */
@Timeout(value = 90, unit = TimeUnit.SECONDS)
class RecordPlaybackTest {
    static final double[][] POSES = {{10, -20, 30}, {45.5, 0, -60.25}, {-15, 70, 5}};
    static final String ROBOT = """
            <program>
              <robot><structure><arm elements="4, 2, 3"/><rest elements="0, 1"/></structure></robot>
            </program>
            """;

    @TempDir
    Path dir;

    @BeforeAll
    static void needSocat() {
        assumeTrue(PtyPair.available(), "socat is not installed (./test-all installs it)");
    }

    @Test
    void recordedPosesPlayBackThroughTheSameModules() throws Exception {
        Path robot = dir.resolve("robot.xml");
        Files.writeString(robot, ROBOT);
        Path rec = dir.resolve("arm-rec.xml");
        int[] arm = {4, 2, 3};
        try (EmulatedBus bus = new EmulatedBus(dir, EmulatorOptions.of(0, 1, 2, 3, 4))) {
            PipedOutputStream keys = new PipedOutputStream();
            RecordCommand cmd = new RecordCommand();
            cmd.input = new PipedInputStream(keys);
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            CommandLine cl = new CommandLine(cmd);
            cl.setExecutionExceptionHandler(org.parpe.cli.Main::failed); // as parpe sets it
            cl.setErr(new PrintWriter(err, true, StandardCharsets.UTF_8));
            CompletableFuture<Integer> code = CompletableFuture.supplyAsync(() -> cl.execute("--port", bus.port(),
                    "--group", "arm", "--script", robot.toString(), "--out", rec.toString()));
            awaitLimp(bus, arm);
            for (int p = 0; p < POSES.length; p++) {
                for (int k = 0; k < arm.length; k++) {
                    assertTrue(bus.emulator.backDrive(arm[k], POSES[p][k]), "module " + arm[k] + " is limp");
                }
                Thread.sleep(p == 0 ? 50 : 300 + 200 * p);
                keys.write('\n');
                keys.flush();
                // A capture that a loaded machine made time out is announced; press Enter again.
                for (int attempt = 0; !awaitRows(rec, p + 1); attempt++) {
                    assertTrue(attempt < 3, "pose " + p + " was never captured: " + err.toString(StandardCharsets.UTF_8));
                    keys.write('\n');
                    keys.flush();
                }
            }
            keys.close();
            assertEquals(0, code.get(20, TimeUnit.SECONDS), err.toString(StandardCharsets.UTF_8));
            assertTrue(err.toString(StandardCharsets.UTF_8).contains("3 poses saved in " + rec), err.toString());
            Thread.sleep(100);
            for (int id : new int[] {0, 1, 2, 3, 4}) {
                assertTrue(!bus.emulator.isLimp(id), "module " + id + " holds after recording");
            }
            double[] times = checkFile(rec);
            playBack(bus, rec, times);
        }
    }

    private static void awaitLimp(EmulatedBus bus, int[] ids) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (System.nanoTime() < deadline) {
            boolean all = true;
            for (int id : ids) {
                all &= bus.emulator.isLimp(id);
            }
            if (all) {
                return;
            }
            Thread.sleep(10);
        }
        throw new AssertionError("the group never went limp");
    }

    private static boolean awaitRows(Path rec, int rows) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(3);
        while (System.nanoTime() < deadline) {
            if (Files.exists(rec) && count(rec) == rows) {
                return true;
            }
            Thread.sleep(10);
        }
        return false;
    }

    private static int count(Path rec) throws Exception {
        String s = Files.readString(rec);
        if (!s.contains(" poses of group")) {
            return 0;
        }
        return Integer.parseInt(s.substring(s.indexOf("recording (PARSL.md section 12): ") + 33).split(" ")[0]);
    }

    /** The file loads, has one row per pose with the recorded angles; returns its row times. */
    private static double[] checkFile(Path rec) throws Exception {
        LoadResult r = ScriptLoader.load(rec, Map.of());
        assertTrue(r.errors().isEmpty(), r.diagnostics().toString());
        Automaton a = r.program().automaton("rec_arm").orElseThrow();
        assertEquals(POSES.length, a.states().size());
        String text = Files.readString(rec);
        String times = text.substring(text.indexOf("times=\"") + 7);
        double[] t = java.util.Arrays.stream(times.substring(0, times.indexOf('"')).split(","))
                .mapToDouble(s -> Double.parseDouble(s.trim())).toArray();
        assertEquals(POSES.length, t.length);
        for (double v : t) {
            assertTrue(v >= 0.01 && Math.abs(v * 100 - Math.round(v * 100)) < 1e-9, "row times are whole ticks: " + v);
        }
        assertEquals((t[1] + t[2]) / 2, t[0], 0.0051, "the first row takes the mean interval");
        return t;
    }

    /** Plays the file on the bus; at each pose's time, the trace and the modules hold that pose. */
    private void playBack(EmulatedBus bus, Path rec, double[] t) throws Exception {
        bus.received.clear();
        Path trace = dir.resolve("play.csv");
        Cli r = Cli.run("run", rec.toString(), "--port", bus.port(), "--trace", trace.toString());
        assertEquals(0, r.code, r.toString());
        Traces tr = new Traces(trace);
        double at = 0;
        for (int p = 0; p < POSES.length; p++) {
            at += t[p];
            int tick = (int) Math.round(at / 0.01);
            double[] row = tr.rows.get(tick);
            double[] sent = bus.received.get(tick);
            for (int k = 0; k < 3; k++) {
                int col = tr.column("m" + new int[] {4, 2, 3}[k]);
                assertEquals(POSES[p][k], row[col], 1e-6, "trace at pose " + p);
                if (sent != null) {
                    int index = new int[] {4, 2, 3}[k];
                    assertEquals(POSES[p][k], sent[index], 0.005, "module " + index + " received pose " + p);
                }
            }
        }
        for (int k = 0; k < 3; k++) {
            int module = new int[] {4, 2, 3}[k];
            Settle.angle(POSES[2][k], () -> bus.emulator.angle(module), 0.01, () -> "the modules end in the last pose");
        }
    }

    /**
     * The same on Dynamixel servos through a hardware profile: poses are joint angles (the
     * profile's zero and direction undone) and play back through the same servos.
     */
    @Test
    void dynamixelPosesRecordThroughTheProfileAndPlayBack() throws Exception {
        Path robot = dir.resolve("robot.xml");
        Files.writeString(robot, ROBOT);
        Path profile = dir.resolve("profile.xml");
        Files.writeString(profile, """
                <hardware protocol="dxl2" baud="1000000">
                  <servo module="4" id="14" zero="20"/>
                  <servo module="2" id="12" direction="-1"/>
                  <servo module="3" id="13" zero="-5" direction="-1"/>
                </hardware>
                """);
        Path rec = dir.resolve("arm-rec.xml");
        int[] servos = {14, 12, 13};
        double[] zero = {20, 0, -5};
        int[] dir = {1, -1, -1};
        org.parpe.serial.servo.ServoModel xm = org.parpe.serial.servo.ServoModel.named("xm430-w350");
        try (EmulatedServos bus = new EmulatedServos(this.dir, xm, EmulatorOptions.of(12, 13, 14))) {
            PipedOutputStream keys = new PipedOutputStream();
            RecordCommand cmd = new RecordCommand();
            cmd.input = new PipedInputStream(keys);
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            CommandLine cl = new CommandLine(cmd);
            cl.setExecutionExceptionHandler(org.parpe.cli.Main::failed); // as parpe sets it
            cl.setErr(new PrintWriter(err, true, StandardCharsets.UTF_8));
            CompletableFuture<Integer> code = CompletableFuture.supplyAsync(() -> cl.execute("--hardware",
                    profile.toString(), "--port", bus.port(), "--group", "arm", "--script", robot.toString(),
                    "--out", rec.toString()));
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (!(bus.emulator.isLimp(12) && bus.emulator.isLimp(13) && bus.emulator.isLimp(14))) {
                assertTrue(System.nanoTime() < deadline, "the group never went limp: " + err);
                Thread.sleep(10);
            }
            for (int p = 0; p < 2; p++) {
                for (int k = 0; k < 3; k++) {
                    assertTrue(bus.emulator.backDrive(servos[k], zero[k] + dir[k] * POSES[p][k]));
                }
                Thread.sleep(300);
                keys.write('\n');
                keys.flush();
                assertTrue(awaitRows(rec, p + 1), "pose " + p + " captured: " + err);
            }
            keys.close();
            assertEquals(0, code.get(20, TimeUnit.SECONDS), err.toString(StandardCharsets.UTF_8));
            // A servo recording plays back through its profile; it used to suggest "--port PATH".
            assertTrue(err.toString(StandardCharsets.UTF_8).contains("play them with: parpe run " + rec + " --hardware "
                    + profile + " --port " + bus.port()), err.toString(StandardCharsets.UTF_8));
            assertTrue(!bus.emulator.isLimp(12), "the servos hold after recording");
            for (int k = 0; k < 3; k++) {
                bus.emulator.backDrive(servos[k], 0);
            }
            Cli r = Cli.run("run", rec.toString(), "--hardware", profile.toString(), "--port", bus.port());
            assertEquals(0, r.code, r.toString());
            String recorded = Files.readString(rec);
            for (int k = 0; k < 3; k++) {
                int servo = servos[k];
                Settle.angle(zero[k] + dir[k] * POSES[1][k], () -> bus.emulator.angle(servo), 0.2,
                        () -> "servo " + servo + " ends in the last pose; " + r + recorded);
            }
        }
    }
}
