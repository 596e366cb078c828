/**
 * parpe bench: the Benchmark service interface with each benchmark's {@link org.parpe.cli.bench.Goal}s,
 * the command that runs them (a fresh JVM each), the results it checks against the goals, saves
 * and compares, and the core, export, sweep and diagram benchmarks. A new benchmark implements
 * Benchmark, declares its goals and is listed in META-INF/services/org.parpe.cli.bench.Benchmark.
 */
package org.parpe.cli.bench;
