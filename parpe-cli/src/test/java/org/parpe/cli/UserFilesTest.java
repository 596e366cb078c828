package org.parpe.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Issue 31 item 5: the outputs and inputs users hit in the fault and bad-input campaigns. */
class UserFilesTest {
    @TempDir
    Path dir;

    /** {@code chmod 444 t.csv; parpe run … --trace t.csv} replaced the file (the CI runs as root, who may write it). */
    @Test
    void aWriteProtectedOutputIsRefusedAndKept() throws Exception {
        Path x = Files.writeString(dir.resolve("x.xml"), CliContractTest.GOOD);
        Path t = Files.writeString(dir.resolve("t.csv"), "mine\n");
        Files.setPosixFilePermissions(t, PosixFilePermissions.fromString("r--r--r--"));
        Cli r = Cli.run("run", x.toString(), "--duration", "0.1", "--trace", t.toString());
        assertEquals(2, r.code, r.toString());
        assertEquals("parpe: cannot write --trace file '" + t + "': it is write-protected; make it writable (chmod u+w)"
                + " or choose another name\n", r.err);
        assertEquals("mine\n", Files.readString(t));
        assertEquals("r--r--r--", PosixFilePermissions.toString(Files.getPosixFilePermissions(t)));
    }

    /** A script with a 251-byte name: its sketch's {@code .ino} has 251 bytes, its temporary name had 273. */
    @Test
    void theSketchOfAScriptWithTheLongestNameIsWritten() throws Exception {
        Path script = dir.resolve("s".repeat(247) + ".xml");
        Files.copy(Path.of("..", "examples", "hello-snake.xml"), script);
        Path out = dir.resolve("out");
        Cli r = Cli.run(List.of("export", script.toString(), "--target", "arduino", "--out", out.toString()));
        assertEquals(0, r.code, r.toString());
        Path ino = out.resolve("s".repeat(247)).resolve("s".repeat(247) + ".ino");
        assertTrue(Files.readString(ino).contains("setup"), ino.toString());
    }

    /** A profile given to {@code check} was read as a script: seven "unknown attribute" errors. */
    @Test
    void aHardwareProfileGivenToCheckIsNamed() throws Exception {
        Path prof = Files.writeString(dir.resolve("prof.xml"),
                "<hardware protocol=\"dxl2\" port=\"/dev/null\" baud=\"1000000\">\n  <servo id=\"0\"/>\n</hardware>\n");
        Cli r = Cli.run("check", prof.toString());
        assertEquals(1, r.code, r.toString());
        assertEquals(prof + ":1:2: error: this is a hardware profile, not a PARSL script; give it to run, record or"
                + " calibrate with --hardware\n" + prof + ": 1 error\n", r.err + r.out);
    }

    /** "cannot read the hardware profile 'DIR'" said no reason. */
    @Test
    void anUnreadableProfileSaysWhy() {
        Path x = dir.resolve("x.xml");
        Cli r = Cli.run("run", "../examples/hello-snake.xml", "--duration", "0.1", "--hardware", dir.toString());
        assertEquals(2, r.code, r.toString());
        assertTrue(r.err.contains("cannot read the hardware profile '" + dir + "': it is a directory"), r.err);
        assertTrue(!Files.exists(x));
    }

    /** merge of a header-only file said "runs are missing: -1 of 0". */
    @Test
    void mergingAHeaderOnlyFileSaysItHoldsNoRuns() throws Exception {
        Path h = Files.writeString(dir.resolve("h.csv"), "run,runs,combination,repeat,seed,bend,duration_s,distance_m,"
                + "forward_m,forward_speed_mps,speed_mps,max_tilt_deg,joint_travel_deg,fell,error\n");
        Cli r = Cli.run("merge", h.toString());
        assertEquals(1, r.code, r.toString());
        assertEquals("parpe: the files hold no runs, only the header; merge the files of a sweep's shards\n", r.err);
    }

    /** Whole numbers too large were "not whole numbers". */
    @Test
    void wholeNumbersTooLargeAreCalledTooLarge() throws Exception {
        Path snake = Files.writeString(dir.resolve("snake.xml"), OutputPolicyTest.WAVE);
        Cli shard = Cli.run("sweep", snake.toString(), "--sim", "snake:n=2", "--duration", "0.1", "--vary", "bend=20..40:2",
                "--shard", "1/9999999", "--out", dir.resolve("s.csv").toString());
        assertEquals(2, shard.code, shard.toString());
        assertEquals("parpe: --shard 1/9999999: N must be at most 999999 shards, got 9999999\n", shard.err);
        Cli vary = Cli.run("sweep", snake.toString(), "--sim", "snake:n=2", "--duration", "0.1", "--vary",
                "bend=0..40:2147483648", "--out", dir.resolve("v.csv").toString());
        assertEquals(2, vary.code, vary.toString());
        assertTrue(vary.err.contains("K (the number of values) is 2147483648, more than the 10000000 runs one sweep"
                + " may have; use fewer values or --random COUNT"), vary.err);
    }
}
