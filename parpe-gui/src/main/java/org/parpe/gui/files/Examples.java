package org.parpe.gui.files;

import org.parpe.gui.text.UiMsg;
import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * Finds the bundled example scripts: the folder named by the system property
 * {@code parpe.examples}, else {@code examples/} beside the repository root found by walking
 * up from the jar (the launcher runs {@code parpe-gui/target/parpe-gui.jar}), else
 * {@code ./examples}.
 *
 * <p>The installed PARPE (its examples are not in a source checkout) copies them to the user's
 * own {@code ~/PARPE/examples} on first use and uses that copy, so that lessons that write files
 * beside a script (lesson 11's {@code parpe optimize}) work and a student's changes are kept.
 */
public final class Examples {
    private Examples() {
    }

    private static volatile Path folder;

    /** The examples folder, or {@code null} if none is found: the user's copy where PARPE is installed. */
    public static Path folder() {
        Path f = folder;
        if (f == null) {
            Path bundled = bundled();
            f = bundled == null || !installed(bundled) ? bundled
                    : copyForUser(bundled, Path.of(System.getProperty("user.home")));
            folder = f;
        }
        return f;
    }

    /** Whether this is an installed PARPE (its examples are not in a source checkout). */
    public static boolean installed() {
        Path bundled = bundled();
        return bundled != null && installed(bundled);
    }

    /** Whether {@code bundled} is an installed PARPE's examples rather than a source checkout's. */
    static boolean installed(Path bundled) {
        return !Files.exists(bundled.resolveSibling("pom.xml"));
    }

    /**
     * Copies the files of {@code bundled} that {@code home}/PARPE/examples lacks into it (a
     * student's own changes are never overwritten; examples new in an update appear) and returns
     * that folder; returns {@code bundled} when the home folder cannot be written.
     */
    static Path copyForUser(Path bundled, Path home) {
        Path copy = home.resolve("PARPE").resolve("examples");
        try (Stream<Path> all = Files.walk(bundled)) {
            for (Path p : (Iterable<Path>) all::iterator) {
                Path target = copy.resolve(bundled.relativize(p).toString());
                if (Files.isDirectory(p)) {
                    Files.createDirectories(target);
                } else if (!Files.exists(target)) {
                    Files.copy(p, target);
                    // the installed files are read-only; the student's copy is theirs to change
                    target.toFile().setWritable(true, true);
                }
            }
            return copy;
        } catch (IOException | SecurityException e) {
            System.err.println("parpe gui: " + UiMsg.CANNOT_COPY_EXAMPLES.text(copy, e.getMessage()));
            return bundled;
        }
    }

    /** The examples that come with PARPE, or {@code null} if none is found. */
    public static Path bundled() {
        String prop = System.getProperty("parpe.examples");
        if (prop != null && Files.isDirectory(Path.of(prop))) {
            return Path.of(prop).toAbsolutePath().normalize();
        }
        try {
            Path p = Path.of(Examples.class.getProtectionDomain().getCodeSource().getLocation().toURI());
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

    /** The example worlds ({@code examples/worlds}: files whose root element is {@code <world>}), sorted by name. */
    public static List<Path> worlds() {
        Path dir = folder();
        return dir == null ? List.of() : scriptsIn(dir.resolve("worlds")).stream().filter(Examples::isWorld).toList();
    }

    /** Whether {@code p} is a world file (root element {@code <world>}), not a script beside it. */
    private static boolean isWorld(Path p) {
        try {
            return Files.readString(p).contains("<world");
        } catch (IOException e) {
            return false;
        }
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

    /** The tutorial's folder, {@code docs/tutorial} beside the bundled examples folder, or {@code null}. */
    public static Path tutorialFolder() {
        Path examples = bundled();
        Path t = examples == null ? null : examples.getParent().resolve("docs").resolve("tutorial");
        return t != null && Files.isDirectory(t) ? t : null;
    }
}
