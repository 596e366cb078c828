package org.parpe.cli.bench;

import org.parpe.cli.text.CliMsg;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * One group of measurements printed by {@code parpe bench} as {@code name=value} lines.
 * Implementations are listed in {@code META-INF/services/org.parpe.cli.bench.Benchmark}.
 */
public interface Benchmark {

    /** A short name used by {@code parpe bench --only NAME}. */
    String name();

    /** Runs the measurements and prints {@code name=value} lines to {@code out}. */
    void run(PrintStream out) throws Exception;

    /**
     * The goals of the figures this benchmark prints; {@code parpe bench} shows each beside its
     * figure with whether it holds.
     */
    default List<Goal> goals() {
        return List.of();
    }

    /**
     * Options of the JVM the measurements must run in, such as the garbage collector the command
     * being measured runs with; when not empty the benchmark always gets a JVM of its own.
     */
    default List<String> jvmOptions() {
        return List.of();
    }

    /** The examples folder: above the working directory, or above the PARPE jar (parpe-cli/target/parpe.jar). */
    static Path examples() throws java.net.URISyntaxException {
        Path jar = Path.of(Benchmark.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        for (Path start : List.of(Path.of("").toAbsolutePath(), jar.toAbsolutePath())) {
            for (Path p = start; p != null; p = p.getParent()) {
                if (Files.isRegularFile(p.resolve("examples/hello-snake.xml"))) {
                    return p.resolve("examples");
                }
            }
        }
        throw new IllegalStateException(CliMsg.NO_EXAMPLES_FOLDER.text(Path.of("").toAbsolutePath(), jar));
    }
}
