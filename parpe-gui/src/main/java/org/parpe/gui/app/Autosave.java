package org.parpe.gui.app;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Properties;

/**
 * Keeps a copy of the unsaved editor text in {@code ~/.parpe/autosave/} so that nothing is lost
 * when the IDE is killed. The copy is removed when the text is saved or the IDE closes
 * normally; a copy found at start-up means the last session ended abnormally and is offered
 * for recovery. Writes are atomic (temporary file, then move).
 */
public final class Autosave {
    private final Path dir;

    public Autosave(Path home) {
        this.dir = home.resolve("autosave");
    }

    /** A recovered buffer: the file it belonged to (or {@code null} if untitled) and its text. */
    public record Recovered(Path file, String text) {
    }

    /** Writes {@code text}, the unsaved content of {@code file} (null: untitled). */
    public void write(Path file, String text) throws IOException {
        Files.createDirectories(dir);
        Properties meta = new Properties();
        meta.setProperty("file", file == null ? "" : file.toAbsolutePath().toString());
        Path tmp = dir.resolve("buffer.xml.tmp");
        Files.writeString(tmp, text, StandardCharsets.UTF_8);
        Files.move(tmp, dir.resolve("buffer.xml"), StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        Path metaTmp = dir.resolve("buffer.properties.tmp");
        try (var out = Files.newOutputStream(metaTmp)) {
            meta.store(out, "PARPE autosave");
        }
        Files.move(metaTmp, dir.resolve("buffer.properties"), StandardCopyOption.REPLACE_EXISTING,
                StandardCopyOption.ATOMIC_MOVE);
    }

    /** Removes the copy (the text was saved, or the user discarded it). */
    public void clear() {
        try {
            Files.deleteIfExists(dir.resolve("buffer.xml"));
            Files.deleteIfExists(dir.resolve("buffer.properties"));
        } catch (IOException e) {
            // A stale copy is only offered once more; nothing is lost.
        }
    }

    /** The copy left by an earlier session, or {@code null}. */
    public Recovered find() {
        Path buf = dir.resolve("buffer.xml");
        if (!Files.isRegularFile(buf)) {
            return null;
        }
        try {
            String text = Files.readString(buf, StandardCharsets.UTF_8);
            Properties meta = new Properties();
            Path m = dir.resolve("buffer.properties");
            if (Files.isRegularFile(m)) {
                try (var in = Files.newInputStream(m)) {
                    meta.load(in);
                }
            }
            String f = meta.getProperty("file", "");
            return new Recovered(f.isEmpty() ? null : Path.of(f), text);
        } catch (IOException | IllegalArgumentException e) {
            return null;
        }
    }
}
