package org.parpe.sim.grade;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.parpe.core.text.Lang;
import org.parpe.core.xml.FlatXmlFile;
import org.parpe.sim.text.SimMsg;

/**
 * Runs one student in a child JVM ({@link GradeChild}) on the same Java and class path, with a
 * heap limit and a CPU-time limit: a script that hangs, grows without bound or brings the engine
 * down costs only its own row. The CPU time is the child's own ({@link ProcessHandle.Info}),
 * polled; a child that waits without using CPU is stopped at a wall-clock limit of its own.
 */
public final class Isolation {
    /** Exit status of a JVM that ran out of heap with {@code -XX:+ExitOnOutOfMemoryError}. */
    private static final int OUT_OF_MEMORY = 3;
    /** The most of a child's standard output read: the outcome is a few lines. */
    private static final int MAX_OUTPUT = 64 << 10;

    /**
     * The limits of one run.
     *
     * @param cpuSeconds  CPU time the child may use (JVM start included)
     * @param memoryMb    the child's heap, MB
     */
    public record Limits(double cpuSeconds, int memoryMb) {
        /** The default CPU time of a run, s (as text: a command-line option's default). */
        public static final String DEFAULT_CPU_SECONDS = "300";
        /** The default heap of a run, MB. */
        public static final String DEFAULT_MEMORY_MB = "512";
        /** The default limits. */
        public static final Limits DEFAULTS = new Limits(Double.parseDouble(DEFAULT_CPU_SECONDS), Integer.parseInt(DEFAULT_MEMORY_MB));

        double wallSeconds() {
            return 3 * cpuSeconds + 30;
        }
    }

    private Isolation() {
    }

    /** Runs {@code script} (relative to {@code dir}, confined to {@code root}) in the challenge, its trace to {@code trace}. */
    static Outcome run(Path challenge, Path dir, Path script, Path root, Path trace, Limits limits)
            throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>();
        cmd.add(ProcessHandle.current().info().command().orElse(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        // C1 only: a run is a few seconds of CPU, which C2's compiling costs more than it saves
        // (30 race-track runs of 60 s: 27 CPU-s instead of 60); the results are the same (strict
        // floating point since Java 17), so the report is too.
        cmd.addAll(List.of("-Xmx" + limits.memoryMb() + "m", "-XX:+ExitOnOutOfMemoryError", "-XX:+UseSerialGC",
                "-XX:TieredStopAtLevel=1",
                "-XX:MaxMetaspaceSize=128m", "-Xss2m", "-Xshare:auto", "-Djava.awt.headless=true",
                "-cp", System.getProperty("java.class.path"), GradeChild.class.getName(),
                challenge.toAbsolutePath().toString(), script.toString(), root.toString(), trace.toAbsolutePath().toString(),
                Lang.current().toLanguageTag()));
        Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectError(ProcessBuilder.Redirect.DISCARD).start();
        p.getOutputStream().close();
        CompletableFuture<String> out = CompletableFuture.supplyAsync(() -> read(p.getInputStream()));
        String stopped;
        try {
            stopped = watch(p, limits);
        } catch (InterruptedException e) {
            p.destroyForcibly(); // grading stopped (the IDE's Stop): no child outlives it
            throw e;
        }
        if (stopped != null) {
            return Outcome.failed(stopped);
        }
        if (p.exitValue() == OUT_OF_MEMORY) {
            return Outcome.failed(SimMsg.GRADE_OUT_OF_MEMORY.text(limits.memoryMb()));
        }
        Outcome o = Outcome.parse(out.join());
        return o != null ? o : Outcome.failed(SimMsg.GRADE_NO_RESULT.text(p.exitValue()));
    }

    /** Waits for {@code p}; kills it and says why when it breaks a limit (null: it ended by itself). */
    private static String watch(Process p, Limits limits) throws InterruptedException {
        long wallEnd = System.nanoTime() + (long) (limits.wallSeconds() * 1e9);
        while (!p.waitFor(50, TimeUnit.MILLISECONDS)) {
            double cpu = p.toHandle().info().totalCpuDuration().map(Duration::toNanos).orElse(0L) / 1e9;
            String why = cpu > limits.cpuSeconds()
                    ? SimMsg.GRADE_CPU_LIMIT.text(FlatXmlFile.plain(limits.cpuSeconds()))
                    : System.nanoTime() > wallEnd
                    ? SimMsg.GRADE_WALL_LIMIT.text(FlatXmlFile.plain(limits.wallSeconds()))
                    : null;
            if (why != null) {
                p.destroyForcibly().waitFor();
                return why;
            }
        }
        return null;
    }

    private static String read(InputStream in) {
        try (in) {
            byte[] b = in.readNBytes(MAX_OUTPUT);
            in.transferTo(OutputStream.nullOutputStream());
            return new String(b, StandardCharsets.UTF_8);
        } catch (IOException e) {
            return "";
        }
    }
}
