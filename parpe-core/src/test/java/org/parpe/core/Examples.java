package org.parpe.core;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/** The repository's example scripts. */
final class Examples {
    private Examples() {
    }

    static Path dir() {
        for (Path p = Path.of("").toAbsolutePath(); p != null; p = p.getParent()) {
            if (Files.isDirectory(p.resolve("examples")) && Files.exists(p.resolve("examples/hello-snake.xml"))) {
                return p.resolve("examples");
            }
        }
        throw new IllegalStateException("examples/ not found above " + Path.of("").toAbsolutePath());
    }

    static List<Path> all() throws IOException {
        try (var s = Files.list(dir())) {
            return s.filter(p -> p.toString().endsWith(".xml")).sorted().toList();
        }
    }
}
