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
@Command(name = "bench", description = "Measure speed: scheduler, loading, simulator, serial bus. Prints name=value lines.")
public final class BenchCommand implements Callable<Integer> {
    @Option(names = "--only", paramLabel = "NAME", description = "Run only the benchmarks with these names (repeatable).")
    List<String> only = new ArrayList<>();

    @Option(names = "--list", description = "List the benchmark names and exit.")
    boolean list;

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
        for (Benchmark b : all) {
            if (only.isEmpty() || only.contains(b.name())) {
                out.println("# " + b.name());
                b.run(out);
                out.flush();
            }
        }
        return 0;
    }
}
