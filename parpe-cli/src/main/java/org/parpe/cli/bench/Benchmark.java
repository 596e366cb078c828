package org.parpe.cli.bench;

import java.io.PrintStream;

/**
 * One group of measurements printed by {@code parpe bench} as {@code name=value} lines.
 * Implementations are listed in {@code META-INF/services/org.parpe.cli.bench.Benchmark}.
 */
public interface Benchmark {

    /** A short name used by {@code parpe bench --only NAME}. */
    String name();

    /** Runs the measurements and prints {@code name=value} lines to {@code out}. */
    void run(PrintStream out) throws Exception;
}
