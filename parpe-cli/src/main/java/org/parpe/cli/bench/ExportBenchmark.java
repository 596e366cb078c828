package org.parpe.cli.bench;

import org.parpe.cli.text.CliMsg;
import java.io.IOException;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.parpe.cli.export.ExportFolder;
import org.parpe.core.export.Board;
import org.parpe.core.export.CExport;
import org.parpe.core.export.MemoryReport;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Program;
import org.parpe.core.run.Engine;
import org.parpe.core.run.RunOptions;

/**
 * {@code parpe bench --only export}: ticks per second of CPU time of the generated C (gcc -O2) for
 * the 1 000-module benchmark snake of {@link CoreBenchmark} against the Java scheduler (five
 * rounds of each, taken in turn, the ratio the median of the five pairs' ratios; per CPU second,
 * as the scheduler's own figure, because on a shared machine the wall clock also counts the time
 * other processes had the core), and the RAM the exported
 * hello-world snake and centipede need on an Arduino Uno and on the host.
 */
public final class ExportBenchmark implements Benchmark {
    private static final int MODULES = 1000;
    private static final int ROUNDS = 5;
    private static final long WARM_UP_NANOS = 2_000_000_000L;
    private static final Pattern TIME = Pattern.compile("(\\d+)m([\\d.]+)s");

    @Override
    public String name() {
        return "export";
    }

    @Override
    public List<Goal> goals() {
        return List.of(Goal.atLeast("export.c_over_java", 3));
    }

    @Override
    public void run(PrintStream out) throws Exception {
        Program snake = load(Path.of("bench-snake.xml"), CoreBenchmark.snake(MODULES));
        Path dir = Files.createTempDirectory("parpe-export-bench");
        double[] c = new double[ROUNDS];
        double[] java = new double[ROUNDS];
        double[] ratio = new double[ROUNDS];
        try {
            compile(snake, dir);
            JavaTicks scheduler = new JavaTicks(snake);
            // A round of each in turn: a neighbour that slows the machine for a while slows both
            // sides of a pair, and the ratio is taken pair by pair.
            for (int round = 0; round < ROUNDS; round++) {
                java[round] = scheduler.round();
                c[round] = cTicksPerSecond(dir);
                ratio[round] = c[round] / java[round];
            }
        } finally {
            try (Stream<Path> s = Files.walk(dir)) {
                for (Path f : s.sorted(Comparator.reverseOrder()).toList()) {
                    Files.deleteIfExists(f);
                }
            }
        }
        out.printf(Locale.ROOT, "export.modules=%d%n", MODULES);
        out.printf(Locale.ROOT, "export.c_ticks_per_s=%.0f%n", median(c));
        out.printf(Locale.ROOT, "export.java_ticks_per_s=%.0f%n", median(java));
        out.printf(Locale.ROOT, "export.c_over_java=%.2f%n", median(ratio));
        out.printf(Locale.ROOT, "export.c_over_java_min=%.2f%n", Arrays.stream(ratio).min().orElse(0));
        for (String example : List.of("hello-snake", "centipede-walk")) {
            Path file = Benchmark.examples().resolve(example + ".xml");
            Program p = load(file, Files.readString(file));
            for (Board b : List.of(Board.UNO, Board.ESP32, Board.HOST)) {
                MemoryReport m = CExport.estimate(p, 0.01, b);
                out.printf(Locale.ROOT, "export.%s.%s.state_ram_bytes=%d%n", example, b.word(), m.stateBytes());
                if (b != Board.HOST) {
                    out.printf(Locale.ROOT, "export.%s.%s.ram_bytes=%d%n", example, b.word(), m.ramBytes());
                    out.printf(Locale.ROOT, "export.%s.%s.flash_bytes=%d%n", example, b.word(), m.flashBytes());
                    out.printf(Locale.ROOT, "export.%s.%s.fits=%s%n", example, b.word(), m.fits());
                }
            }
        }
    }

    /** The Java scheduler on the benchmark snake, compiled by the JIT before its first round. */
    private static final class JavaTicks {
        private final Engine engine;
        private final ThreadMXBean mx = ManagementFactory.getThreadMXBean();

        JavaTicks(Program p) {
            engine = new Engine(p, RunOptions.defaults());
            engine.start();
            // warm up by CPU time, not by ticks: a slower machine needs more ticks before C2 is done
            long start = mx.getCurrentThreadCpuTime();
            while (mx.getCurrentThreadCpuTime() - start < WARM_UP_NANOS) {
                steps(100);
            }
        }

        /** Ticks per second of this thread's CPU time over one round of 0.6 s. */
        double round() {
            long start = mx.getCurrentThreadCpuTime();
            long ticks = 0;
            while (mx.getCurrentThreadCpuTime() - start < 600_000_000L) {
                steps(100);
                ticks += 100;
            }
            return ticks / ((mx.getCurrentThreadCpuTime() - start) / 1e9);
        }

        private void steps(int n) {
            for (int i = 0; i < n; i++) {
                engine.step();
            }
        }
    }

    private static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        return sorted[sorted.length / 2];
    }

    /** Writes the host export of {@code p} to {@code dir} and compiles it there with gcc -O2 to {@code program}. */
    private static void compile(Program p, Path dir) throws IOException, InterruptedException {
        ExportFolder.writeHost(p, 0.01, dir);
        List<String> gcc = new ArrayList<>(List.of("gcc", "-std=c99", "-O2", "-o", "program"));
        try (Stream<Path> s = Files.list(dir)) {
            s.map(f -> f.getFileName().toString()).filter(n -> n.endsWith(".c")).sorted().forEach(gcc::add);
        }
        gcc.add("-lm");
        run(dir, gcc);
    }

    /** One round of the compiled program: ticks per second of its CPU time. */
    private static double cTicksPerSecond(Path dir) throws IOException, InterruptedException {
        int ticks = 60_000; // 1-2 s: the shell counts CPU time in hundredths
        // the shell's times (POSIX) prints its children's user and system CPU time on its second line
        String out = run(dir, List.of("sh", "-c", "./program --duration " + (ticks - 1) * 0.01 + "; times"));
        return ticks / cpuSeconds(out.lines().reduce((a, b) -> b).orElse(""));
    }

    /** The sum of the times of a line of the shell's {@code times}, such as {@code 0m0.352000s 0m0.004000s}. */
    static double cpuSeconds(String timesLine) {
        Matcher m = TIME.matcher(timesLine);
        double s = 0;
        int found = 0;
        while (m.find()) {
            s += Integer.parseInt(m.group(1)) * 60 + Double.parseDouble(m.group(2));
            found++;
        }
        if (found != 2) {
            throw new IllegalStateException("the shell's times printed '" + timesLine + "', not a user and a system time");
        }
        return s;
    }

    private static String run(Path dir, List<String> command) throws IOException, InterruptedException {
        Process p;
        try {
            p = new ProcessBuilder(new ArrayList<>(command)).directory(dir.toFile()).redirectErrorStream(true).start();
        } catch (IOException e) {
            throw new IllegalStateException(CliMsg.NEEDS_GCC.text(command.get(0), e.getMessage()));
        }
        String output = new String(p.getInputStream().readAllBytes());
        if (!p.waitFor(10, TimeUnit.MINUTES) || p.exitValue() != 0) {
            throw new IllegalStateException(String.join(" ", command) + " failed: " + output);
        }
        return output;
    }

    private static Program load(Path name, String text) {
        LoadResult r = ScriptLoader.loadText(name, text, Map.of());
        if (r.program() == null) {
            throw new IllegalStateException(name + " does not load: " + r.diagnostics());
        }
        return r.program();
    }
}
