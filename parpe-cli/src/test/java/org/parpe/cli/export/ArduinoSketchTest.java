package org.parpe.cli.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.parpe.cli.Cli;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;
import org.parpe.core.run.Engine;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.StimulusParser;
import org.parpe.serial.bus.Crc16;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.feetech.FeetechCodec;

/**
 * The Arduino sketch compiles with the host compiler against a tiny Arduino API shim
 * ({@code src/test/resources/export/shim}) and runs: its servo pulses or bus packets carry the
 * interpreter's setpoints tick by tick, a console command changes a control as a stimulus does,
 * and every Dynamixel packet has a valid CRC and every Feetech packet a valid checksum (checked
 * with parpe-serial's codecs).
 */
class ArduinoSketchTest {
    static final Path SCRIPT = ExportEqualityTest.ROOT.resolve("examples/teleop-dirwave.xml");
    static final Path SHIM = Path.of("src/test/resources/export/shim").toAbsolutePath();
    static final int TICKS = 12;

    @TempDir
    Path tmp;

    @BeforeAll
    static void compilersInstalled() {
        HostCompiler.require("gcc");
        HostCompiler.require("g++");
    }

    /** Each driver on an Uno (bus on Serial, console on SoftwareSerial) and on an ESP32 (bus on Serial2). */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"pwm uno", "dxl uno", "sts uno", "pwm esp32", "dxl esp32", "sts esp32"})
    void sketchDrivesTheServosWithTheInterpretersSetpoints(String variant) throws Exception {
        String servo = variant.split(" ")[0];
        boolean esp32 = variant.endsWith("esp32");
        Cli export = Cli.run(List.of("export", SCRIPT.toString(), "--target",
                "arduino", "--servo", servo, "--board", esp32 ? "esp32" : "uno", "--out", tmp.toString()));
        assertEquals(0, export.code, () -> "export: " + export);
        assertTrue(export.out.contains("memory (" + (esp32 ? "esp32" : "uno") + ", estimate): RAM "), export.out);
        Path sketch = tmp.resolve("teleop_dirwave");
        assertTrue(Files.readString(sketch.resolve("teleop_dirwave.ino")).startsWith(org.parpe.serial.export.ProgramExport.MARK));
        List<String> lines = runSketch(sketch, "direction=backward", esp32).lines().toList();
        List<double[]> expected = interpreter(TICKS + 1, "0.05 $direction=backward\n");
        String console = servo.equals("pwm") || esp32 ? "serial: ok" : "console: ok";
        assertTrue(lines.contains(console), () -> "the command was not accepted:\n" + String.join("\n", lines));
        if (servo.equals("pwm")) {
            // attached (500-2500 us) with its first pulse, not before the first pose: no jump to 0 degrees
            List<String> attach = lines.stream().filter(l -> l.startsWith("attach ")).toList();
            assertEquals(expected.get(0).length, attach.size(), () -> "one attach per servo:\n" + String.join("\n", lines));
            for (String a : attach) {
                String[] f = a.split(" ");
                assertEquals("500 2500", f[2] + " " + f[3], a);
                assertTrue(lines.get(lines.indexOf(a) + 1).startsWith("servo " + f[1] + " "),
                        () -> a + " right before its first pulse:\n" + String.join("\n", lines));
            }
        }
        List<int[]> sent = servo.equals("pwm") ? pulses(lines, expected.get(0).length)
                : packets(lines, servo, esp32 ? "serial2: " : "serial: ");
        assertEquals(TICKS, sent.size(), () -> "one write per tick:\n" + String.join("\n", lines));
        ServoModel model = ServoModel.named(servo.equals("dxl") ? "xl430-w250" : "sts3215");
        for (int t = 0; t < TICKS; t++) {
            double[] angles = expected.get(t);
            for (int i = 0; i < angles.length; i++) {
                int want = servo.equals("pwm") ? ((int) (SimulatedUnoTest.pulseUs(angles[i]) * 2 + 0.5) + 1) / 2
                        : model.ticks(angles[i]);
                assertEquals(want, sent.get(t)[i], "tick " + t + ", module " + i + " (" + angles[i] + " degrees)");
            }
        }
    }

    @Test
    void programTooLargeForAnUnoIsRefusedWithTheMemoryItNeeds() throws Exception {
        Path script = tmp.resolve("long-snake.xml");
        Files.writeString(script, "<program>\n<robot><structure><body elements=\"0..N-1\"/></structure></robot>\n"
                + "<parameters><N value=\"10\"/></parameters><main><go/></main>\n"
                + "<behaviors><go><wave group=\"body\" phase=\"1/$count\"/></go></behaviors>\n"
                + "<automata><wave states=\"up, down\"/></automata><states><up angles=\"30\"/><down angles=\"-30\"/></states>"
                + "</program>\n");
        Cli fits = Cli.run(List.of("export", script.toString(), "--target", "arduino",
                "--servo", "dxl", "--out", tmp.resolve("fits").toString()));
        assertEquals(0, fits.code, () -> "10 modules fit: " + fits);
        Cli export = Cli.run(List.of("export", script.toString(), "--target",
                "arduino", "--servo", "dxl", "--param", "N=60", "--out", tmp.resolve("big").toString()));
        assertEquals(1, export.code, () -> "export: " + export);
        assertTrue(export.err.matches("(?s)[^\\n]*long-snake\\.xml:2:\\d+: error: the program needs about \\d+ bytes of RAM"
                + " on uno .*but it has 2048.*"), export.err);
        assertTrue(Files.notExists(tmp.resolve("big")), "nothing is written when it does not fit");
        assertFalse(fits.err.contains("warning"), fits.err);
        Cli slow = Cli.run(List.of("export", script.toString(), "--target", "arduino", "--servo", "dxl", "--param",
                "N=16", "--out", tmp.resolve("slow").toString()));
        assertEquals(0, slow.code, () -> "16 modules fit: " + slow);
        assertTrue(slow.err.matches("(?s)[^\\n]*long-snake\\.xml:2:\\d+: warning: a tick may take about 1\\d\\.\\d ms to"
                + " compute on uno \\(estimate\\), longer than the tick of 10\\.0 ms.*use --tick 0\\.0\\d+ or more.*"), slow.err);
        Cli esp = Cli.run(List.of("export", script.toString(), "--target",
                "arduino", "--servo", "dxl", "--param", "N=60", "--board", "esp32", "--out", tmp.resolve("esp").toString()));
        assertEquals(0, esp.code, () -> "an ESP32 holds 60 modules: " + esp);
    }

    @Test
    void sensorsTheSketchCannotReadAreRefusedAtTheirDeclaration() {
        String script = ExportEqualityTest.ROOT.resolve("examples/sensor-exit.xml").toString();
        Cli refused = Cli.run(List.of("export", script, "--target", "arduino",
                "--out", tmp.resolve("a").toString()));
        assertEquals(1, refused.code, () -> "export: " + refused);
        assertTrue(refused.err.contains("sensor-exit.xml:12:8: error: an Arduino sketch cannot read 'touch' sensors"),
                refused.err);
        assertTrue(refused.err.contains("sensor-exit.xml:13:8: error: an Arduino sketch cannot read 'accel' sensors"),
                refused.err);
        Cli accepted = Cli.run(List.of("export", script, "--target", "arduino",
                "--console-sensors", "--out", tmp.resolve("b").toString()));
        assertEquals(0, accepted.code, () -> "export: " + accepted);
    }

    @Test
    void badOptionsAreUsageErrors() {
        String script = SCRIPT.toString();
        String out = tmp.resolve("x").toString();
        for (List<String> args : List.of(List.of("--target", "fpga"), List.of("--target", "arduino", "--servo", "can"),
                List.of("--target", "arduino", "--board", "host"), List.of("--servo", "dxl"),
                List.of("--target", "arduino", "--servo", "dxl", "--model", "sts3215"),
                List.of("--target", "arduino", "--pins", "2,3"), List.of("--tick", "0"),
                List.of("--target", "arduino", "--tick", "0.0033333"))) {
            List<String> cmd = new ArrayList<>(List.of("export", script, "--out", out));
            cmd.addAll(args);
            Cli r = Cli.run(cmd);
            int want = args.contains("--pins") ? 1 : 2;
            assertEquals(want, r.code, () -> args + ": " + r);
            assertTrue(r.err.lines().count() >= 1 && !r.err.contains("Exception"), () -> args + ": " + r.err);
        }
    }

    /** Compiles the runtime as C and the sketch as C++ against the shim, then runs TICKS ticks. */
    private String runSketch(Path sketch, String command, boolean esp32) throws Exception {
        List<String> objects = new ArrayList<>();
        try (Stream<Path> s = Files.list(sketch)) {
            for (String c : s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".c")).sorted().toList()) {
                List<String> cmd = new ArrayList<>(List.of("gcc"));
                cmd.addAll(HostCompiler.C_FLAGS);
                cmd.addAll(List.of("-c", c));
                HostCompiler.Result r = HostCompiler.run(sketch, cmd, 120);
                assertEquals(0, r.code(), () -> "gcc " + c + ":\n" + r.err());
                objects.add(c.replace(".c", ".o"));
            }
        }
        List<String> link = new ArrayList<>(List.of("g++", "-std=c++17", "-Wall", "-Werror", "-O2", "-I.", "-I" + SHIM));
        if (esp32) {
            link.add("-DARDUINO_ARCH_ESP32");
        }
        link.addAll(List.of("-x", "c++", "teleop_dirwave.ino", "-x", "none", SHIM.resolve("shim_main.cpp").toString()));
        link.addAll(objects);
        link.addAll(List.of("-o", "sketch", "-lm"));
        HostCompiler.Result r = HostCompiler.run(sketch, link, 120);
        assertEquals(0, r.code(), () -> "g++:\n" + r.err());
        HostCompiler.Result run = HostCompiler.run(sketch, List.of("./sketch", String.valueOf(TICKS), "10000", command), 60);
        assertEquals(0, run.code(), run.err());
        return run.out();
    }

    /** The interpreter's setpoints of ticks 0 … n−1 (the sketch's first write is tick 0). */
    private static List<double[]> interpreter(int n, String stimulus) throws Exception {
        LoadResult r = ScriptLoader.load(SCRIPT, Map.of());
        Program p = r.program();
        Engine e = new Engine(p, new RunOptions(0.01, 0, StimulusParser.parse("stimulus", stimulus, p)));
        List<double[]> rows = new ArrayList<>();
        e.addObserver((tick, time, commanded) -> rows.add(commanded.clone()));
        e.start();
        for (int i = 0; i < n; i++) {
            e.step();
        }
        return rows;
    }

    private static List<int[]> pulses(List<String> lines, int modules) {
        List<Integer> us = lines.stream().filter(l -> l.startsWith("servo ")).map(l -> Integer.parseInt(l.split(" ")[2])).toList();
        List<int[]> out = new ArrayList<>();
        for (int i = 0; i + modules <= us.size(); i += modules) {
            out.add(us.subList(i, i + modules).stream().mapToInt(Integer::intValue).toArray());
        }
        return out;
    }

    /** The goal positions of every SYNC WRITE on the bus, after checking each packet's CRC or checksum. */
    private static List<int[]> packets(List<String> lines, String servo, String port) {
        List<int[]> out = new ArrayList<>();
        boolean dxl = servo.equals("dxl");
        for (String l : lines.stream().filter(x -> x.startsWith(port) && !x.endsWith(": ok")).toList()) {
            String[] hex = l.substring(port.length()).trim().split(" ");
            byte[] b = new byte[hex.length];
            for (int i = 0; i < hex.length; i++) {
                b[i] = (byte) Integer.parseInt(hex[i], 16);
            }
            int n = b.length;
            if (dxl) {
                int crc = (b[n - 2] & 0xFF) | (b[n - 1] & 0xFF) << 8;
                assertEquals(Crc16.DXL2.of(b, 0, n - 2), crc, "CRC of " + l);
                assertEquals(n - 7, (b[5] & 0xFF) | (b[6] & 0xFF) << 8, "LEN of " + l);
            } else {
                assertEquals(FeetechCodec.checksum(b, 2, n - 3), b[n - 1] & 0xFF, "checksum of " + l);
                assertEquals(n - 4, b[3] & 0xFF, "LEN of " + l);
            }
            int inst = dxl ? 7 : 4;
            if ((b[inst] & 0xFF) != 0x83) {
                continue;
            }
            int size = dxl ? 4 : 2;
            int first = inst + (dxl ? 5 : 3);
            List<Integer> goals = new ArrayList<>();
            for (int i = first; i + size < n - (dxl ? 2 : 1) + 1; i += 1 + size) {
                int v = 0;
                for (int k = size - 1; k >= 0; k--) {
                    v = v << 8 | (b[i + 1 + k] & 0xFF);
                }
                goals.add(v);
            }
            out.add(goals.stream().mapToInt(Integer::intValue).toArray());
        }
        return out;
    }
}
