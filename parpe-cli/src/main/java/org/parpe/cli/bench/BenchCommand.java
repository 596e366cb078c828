package org.parpe.cli.bench;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;
import java.util.ServiceLoader;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code parpe bench}: runs every registered benchmark and prints {@code name=value} lines. */
@Command(name = "bench", mixinStandardHelpOptions = true, description = "Measure speed: scheduler, loading, simulator, serial bus. Prints name=value lines.")
public final class BenchCommand implements Callable<Integer> {
    @Option(names = "--only", paramLabel = "NAME", description = "Run only the benchmarks with these names (repeatable).")
    List<String> only = new ArrayList<>();

    @Option(names = "--list", description = "List the benchmark names and exit.")
    boolean list;

    @Option(names = "--no-fork", description = "Run every benchmark in this JVM (by default each gets a fresh one, as JMH does,"
            + " so that one benchmark's JIT profile does not slow the next).")
    boolean noFork;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintStream out = System.out;
        List<Benchmark> all = new ArrayList<>();
        ServiceLoader.load(Benchmark.class).forEach(all::add);
        all.sort((a, b) -> a.name().compareTo(b.name()));
        if (list) {
            all.forEach(b -> out.println(b.name()));
            return 0;
        }
        for (String name : only) {
            if (all.stream().noneMatch(b -> b.name().equals(name))) {
                spec.commandLine().getErr().println("parpe: unknown benchmark '" + name + "' (try --list)");
                return 2;
            }
        }
        List<Benchmark> chosen = all.stream().filter(b -> only.isEmpty() || only.contains(b.name())).toList();
        for (Benchmark b : chosen) {
            if (noFork || chosen.size() == 1 && b.jvmOptions().isEmpty()) {
                out.println("# " + b.name());
                b.run(out);
                out.flush();
            } else if (fork(b) != 0) {
                spec.commandLine().getErr().println("parpe: benchmark '" + b.name() + "' failed");
                return org.parpe.cli.Main.INTERNAL_ERROR;
            }
        }
        return 0;
    }

    /**
     * Runs one benchmark in a fresh JVM with the same class path and the benchmark's JVM options,
     * passing its output through.
     */
    private static int fork(Benchmark b) throws Exception {
        String java = ProcessHandle.current().info().command().orElse("java");
        List<String> command = new java.util.ArrayList<>(List.of(java));
        command.addAll(b.jvmOptions());
        command.addAll(List.of("-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"),
                "org.parpe.cli.Main", "bench", "--only", b.name(), "--no-fork"));
        return new ProcessBuilder(command).inheritIO().start().waitFor();
    }
}
