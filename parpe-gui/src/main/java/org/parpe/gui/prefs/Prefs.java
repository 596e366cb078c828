package org.parpe.gui.prefs;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import org.parpe.core.io.AtomicFiles;

/**
 * The IDE's remembered settings (recent files, last parameter values, run target, speed),
 * kept in {@code ~/.parpe/ide.properties}. The folder can be moved with the system property
 * {@code parpe.home} (tests use a folder under {@code target/}). UI thread only.
 */
public final class Prefs {
    private static final int MAX_RECENT = 8;

    private final Path home;
    private final Properties props = new Properties();

    /** Loads the settings of {@code home}; a missing or unreadable file gives the defaults. */
    public Prefs(Path home) {
        this.home = home;
        Path file = home.resolve("ide.properties");
        if (Files.isRegularFile(file)) {
            try (InputStream in = Files.newInputStream(file)) {
                props.load(in);
            } catch (IOException | IllegalArgumentException e) {
                props.clear();
            }
        }
    }

    /** The folder from {@code parpe.home}, or {@code ~/.parpe}. */
    public static Path defaultHome() {
        String p = System.getProperty("parpe.home");
        return p != null && !p.isBlank() ? Path.of(p) : Path.of(System.getProperty("user.home"), ".parpe");
    }

    /** The settings folder. */
    public Path home() {
        return home;
    }

    public String get(String key, String fallback) {
        return props.getProperty(key, fallback);
    }

    public void put(String key, String value) {
        props.setProperty(key, value);
        save();
    }

    /** Recently opened files, newest first. */
    public List<Path> recentFiles() {
        List<Path> out = new ArrayList<>();
        for (int i = 0; i < MAX_RECENT; i++) {
            String p = props.getProperty("recent." + i);
            if (p != null) {
                out.add(Path.of(p));
            }
        }
        return out;
    }

    /** Puts {@code file} first in the recent files. */
    public void addRecent(Path file) {
        Path abs = file.toAbsolutePath().normalize();
        List<Path> list = recentFiles();
        list.remove(abs);
        list.add(0, abs);
        for (int i = 0; i < MAX_RECENT; i++) {
            if (i < list.size()) {
                props.setProperty("recent." + i, list.get(i).toString());
            } else {
                props.remove("recent." + i);
            }
        }
        save();
    }

    /** Forgets every recent file. */
    public void clearRecent() {
        for (int i = 0; i < MAX_RECENT; i++) {
            props.remove("recent." + i);
        }
        save();
    }

    private void save() {
        try {
            Files.createDirectories(home);
            AtomicFiles.write(home.resolve("ide.properties"), out -> props.store(out, "PARPE IDE settings"));
        } catch (IOException e) {
            // Settings are a convenience: a read-only home must not stop the IDE.
        }
    }
}
