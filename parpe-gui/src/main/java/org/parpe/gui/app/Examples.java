package org.parpe.gui.app;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.parpe.gui.Main;

/**
 * Finds the bundled example scripts: the folder named by the system property
 * {@code parpe.examples}, else {@code examples/} beside the repository root found by walking
 * up from the jar (the launcher runs {@code parpe-gui/target/parpe-gui.jar}), else
 * {@code ./examples}.
 */
public final class Examples {
    private Examples() {
    }

    /** The examples folder, or {@code null} if none is found. */
    public static Path folder() {
        String prop = System.getProperty("parpe.examples");
        if (prop != null && Files.isDirectory(Path.of(prop))) {
            return Path.of(prop).toAbsolutePath().normalize();
        }
        try {
            Path p = Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            for (Path d = p; d != null; d = d.getParent()) {
                if (Files.isDirectory(d.resolve("examples")) && Files.exists(d.resolve("pom.xml"))) {
                    return d.resolve("examples");
                }
            }
        } catch (URISyntaxException | SecurityException | NullPointerException e) {
            // Fall through to the working directory.
        }
        Path cwd = Path.of("examples").toAbsolutePath().normalize();
        return Files.isDirectory(cwd) ? cwd : null;
    }

    /** The example scripts, sorted by name; empty if there are none. */
    public static List<Path> list() {
        return scriptsIn(folder());
    }

    /** The tutorial's lesson scripts ({@code examples/tutorial}), sorted by name; empty if there are none. */
    public static List<Path> lessons() {
        Path dir = folder();
        return dir == null ? List.of() : scriptsIn(dir.resolve("tutorial"));
    }

    private static List<Path> scriptsIn(Path dir) {
        if (dir == null || !Files.isDirectory(dir)) {
            return List.of();
        }
        try (Stream<Path> s = Files.list(dir)) {
            return s.filter(p -> p.getFileName().toString().endsWith(".xml"))
                    .sorted().collect(Collectors.toList());
        } catch (IOException e) {
            return List.of();
        }
    }

    /** The tutorial's folder, {@code docs/tutorial} beside the examples folder, or {@code null}. */
    public static Path tutorialFolder() {
        Path examples = folder();
        Path t = examples == null ? null : examples.getParent().resolve("docs").resolve("tutorial");
        return t != null && Files.isDirectory(t) ? t : null;
    }
}
