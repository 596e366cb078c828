package org.parpe.sim.sweep;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;

/** A small wave snake with bounded parameters, shared by the sweep tests. */
final class Scripts {
    static final Path FILE = Path.of("sweep-snake.xml");
    /** The script's text; the command line's sweep tests read the same file. */
    static final String SNAKE = read(Path.of("src/test/resources/sweep-snake.xml"));

    private Scripts() {
    }

    private static String read(Path file) {
        try {
            return Files.readString(file);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    static Evaluator snake(double duration, Map<String, Double> fixed) throws SweepException {
        return Evaluator.load(new Evaluator.Settings(FILE, SNAKE, fixed, "snake:n=6", duration, 0.01, 90));
    }
}
