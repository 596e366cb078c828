package org.parpe.cli.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

/** The host C compiler for the export tests: gcc/g++, which must be installed (test-all installs them). */
final class HostCompiler {
    /** The flags of the issue: C99, every warning an error. */
    static final List<String> C_FLAGS = List.of("-std=c99", "-Wall", "-Werror", "-O2");

    private HostCompiler() {
    }

    /** Fails the test with a clear message when {@code tool} ({@code gcc}, {@code g++}) is missing. */
    static void require(String tool) {
        if (installed(tool)) {
            return;
        }
        fail(tool + " is not installed: the export tests compile the generated C with the host compiler;"
                + " install it with 'sudo apt-get install " + tool + "' (./test-all installs it)");
    }

    /** Whether {@code tool --version} runs and succeeds. */
    static boolean installed(String tool) {
        try {
            Process p = new ProcessBuilder(tool, "--version").redirectErrorStream(true).start();
            p.getInputStream().readAllBytes();
            return p.waitFor(30, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    /** The finished process's exit code and output. */
    record Result(int code, String out, String err) {
    }

    /** Runs {@code command} in {@code dir}, failing the test after {@code seconds}. */
    static Result run(Path dir, List<String> command, int seconds) throws IOException, InterruptedException {
        Path out = Files.createTempFile(dir, "out", ".txt");
        Path err = Files.createTempFile(dir, "err", ".txt");
        Process p = new ProcessBuilder(command).directory(dir.toFile()).redirectOutput(out.toFile())
                .redirectError(err.toFile()).start();
        if (!p.waitFor(seconds, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            fail(String.join(" ", command) + " did not finish within " + seconds + " s");
        }
        return new Result(p.exitValue(), Files.readString(out, StandardCharsets.UTF_8),
                Files.readString(err, StandardCharsets.UTF_8));
    }

    /** Compiles every {@code .c} file of {@code dir} into {@code dir/program} with the flags, in one gcc call. */
    static Path compile(Path dir) throws IOException, InterruptedException {
        return compile(dir, "program");
    }

    /** As {@link #compile(Path)}, into {@code dir/name}, with {@code flags} after the issue's. */
    static Path compile(Path dir, String name, String... flags) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of("gcc"));
        cmd.addAll(C_FLAGS);
        cmd.addAll(List.of(flags));
        cmd.addAll(List.of("-o", name));
        try (Stream<Path> s = Files.list(dir)) {
            s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".c")).sorted().forEach(cmd::add);
        }
        cmd.add("-lm");
        Result r = run(dir, cmd, 120);
        assertEquals(0, r.code(), () -> "gcc failed:\n" + r.err());
        return dir.resolve(name);
    }
}
