package org.parpe.cli.hw;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import picocli.CommandLine;

/** {@code parpe calibrate} run in-process against emulated servos: wait until they are limp, pose them, press Enter. */
final class CalibrateSession {
    private final PipedOutputStream keys = new PipedOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();
    private final CompletableFuture<Integer> code;

    /** Starts {@code parpe calibrate ARGS} and waits until the servos {@code ids} of {@code s} are limp. */
    CalibrateSession(EmulatedServos s, int[] ids, String... args) throws Exception {
        CalibrateCommand cmd = new CalibrateCommand();
        cmd.input = new PipedInputStream(keys);
        CommandLine cl = new CommandLine(cmd);
        cl.setExecutionExceptionHandler(org.parpe.cli.Main::failed); // as parpe sets it
        cl.setErr(new PrintWriter(err, true, StandardCharsets.UTF_8));
        code = CompletableFuture.supplyAsync(() -> cl.execute(args));
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        for (int id : ids) {
            while (!s.emulator.isLimp(id)) {
                assertTrue(System.nanoTime() < deadline, "servo " + id + " never went limp: " + log());
                Thread.sleep(10);
            }
        }
    }

    /** Presses Enter (the robot is posed) and returns the exit code. */
    int enter() throws Exception {
        keys.write('\n');
        keys.flush();
        return code.get(20, TimeUnit.SECONDS);
    }

    /** What calibrate wrote to standard error. */
    String log() {
        return err.toString(StandardCharsets.UTF_8);
    }
}
