package org.parpe.cli.bench;

import org.parpe.cli.text.CliMsg;
import org.parpe.core.text.Lang;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.ServiceLoader;
import java.util.concurrent.Callable;
import org.parpe.cli.terminal.ExitCode;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code parpe bench}: runs every registered benchmark and prints {@code name=value} lines, each
 * figure that has a goal with the goal and whether it holds beside it; saves a run and puts two
 * side by side.
 */
@Command(name = "bench", mixinStandardHelpOptions = true, description = "Measure speed: scheduler, loading, simulator,"
        + " serial bus. Prints name=value lines, each with its goal and whether it holds.")
public final class BenchCommand implements Callable<Integer> {
    @Option(names = "--only", paramLabel = "NAME", description = "Run only the benchmarks with these names (repeatable).")
    List<String> only = new ArrayList<>();

    @Option(names = "--list", description = "List the benchmark names and exit.")
    boolean list;

    @Option(names = "--no-fork", description = "Run every benchmark in this JVM (by default each gets a fresh one, as JMH does,"
            + " so that one benchmark's JIT profile does not slow the next).")
    boolean noFork;

    @Option(names = "--save", paramLabel = "FILE", description = "Also write this run's figures to FILE (name=value lines).")
    String save;

    @Option(names = "--compare", paramLabel = "FILE", description = "Show this run beside an earlier one (a --save file or a"
            + " saved output); given twice, show the two files side by side without running anything.")
    List<Path> compare = new ArrayList<>();

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        List<Benchmark> all = new ArrayList<>();
        ServiceLoader.load(Benchmark.class).forEach(all::add);
        all.sort((a, b) -> a.name().compareTo(b.name()));
        if (list) {
            all.forEach(b -> out.println(b.name()));
            return 0;
        }
        for (String name : only) {
            if (all.stream().noneMatch(b -> b.name().equals(name))) {
                return usage(CliMsg.UNKNOWN_BENCHMARK.text(name));
            }
        }
        if (compare.size() > 2 || compare.size() == 2 && (save != null || !only.isEmpty())) {
            return usage(CliMsg.COMPARE_USAGE.text());
        }
        org.parpe.cli.options.OutputFile saved = save == null ? null
                : org.parpe.cli.options.OutputFile.of(org.parpe.cli.options.OutputFile.plan(compare), "--save", save);
        List<Goal> everyGoal = all.stream().flatMap(b -> b.goals().stream()).toList();
        List<BenchResults> earlier = new ArrayList<>();
        for (Path file : compare) {
            try {
                earlier.add(BenchResults.read(file, everyGoal));
            } catch (java.io.IOException e) {
                return usage(CliMsg.CANNOT_READ_RUN.text(file, e.getMessage()));
            }
        }
        if (compare.size() == 2) {
            BenchResults.compare(out, compare.get(0).toString(), earlier.get(0), compare.get(1).toString(), earlier.get(1));
            out.flush();
            return 0;
        }
        List<Benchmark> chosen = all.stream().filter(b -> only.isEmpty() || only.contains(b.name())).toList();
        BenchResults results = new BenchResults(chosen.stream().flatMap(b -> b.goals().stream()).toList());
        PrintStream shown = results.printer(out);
        Machine.lines().forEach(shown::println);
        for (Benchmark b : chosen) {
            if (noFork || chosen.size() == 1 && b.jvmOptions().isEmpty()) {
                shown.println("# " + b.name());
                b.run(shown);
                shown.flush();
            } else if (fork(b, shown) != 0) {
                spec.commandLine().getErr().println("parpe: " + CliMsg.BENCHMARK_FAILED.text(b.name()));
                return ExitCode.INTERNAL_ERROR;
            }
        }
        out.println(results.summary());
        out.flush();
        if (saved != null) {
            saved.write(results.text());
        }
        if (!earlier.isEmpty()) {
            out.println();
            BenchResults.compare(out, compare.get(0).toString(), earlier.get(0), CliMsg.THIS_RUN.text(), results);
            out.flush();
        }
        return 0;
    }

    private int usage(String message) {
        spec.commandLine().getErr().println("parpe: " + message);
        return 2;
    }

    /**
     * Runs one benchmark in a fresh JVM with the same class path and the benchmark's JIT options,
     * passing its lines to {@code shown} as they come.
     */
    private static int fork(Benchmark b, PrintStream shown) throws Exception {
        String java = ProcessHandle.current().info().command().orElse("java");
        List<String> command = new ArrayList<>(List.of(java));
        command.addAll(b.jvmOptions());
        command.addAll(List.of("-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"),
                "org.parpe.cli.Main", "bench", "--only", b.name(), "--no-fork", "--lang", Lang.current().toLanguageTag()));
        Process p = new ProcessBuilder(command).redirectInput(ProcessBuilder.Redirect.INHERIT)
                .redirectError(ProcessBuilder.Redirect.INHERIT).start();
        try (BufferedReader in = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
            for (String line = in.readLine(); line != null; line = in.readLine()) {
                // the parent's machine lines and summary stand for the whole run
                if (!line.startsWith("# goals:") && !line.startsWith(Machine.PREFIX)) {
                    shown.println(line);
                }
            }
        }
        return p.waitFor();
    }
}
