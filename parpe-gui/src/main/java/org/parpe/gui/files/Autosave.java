package org.parpe.gui.files;

import org.parpe.gui.text.UiMsg;
import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HexFormat;
import java.util.List;
import java.util.Properties;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.ConcurrentHashMap;
import java.util.stream.Stream;
import org.parpe.core.io.AtomicFiles;

/**
 * Copies of unsaved editor text in {@code ~/.parpe/autosave/}, so that nothing is lost when an
 * IDE is killed. Every IDE instance has its own folder, {@code autosave/INSTANCE/}, holding a
 * {@code lock} file it keeps locked while it lives, and one copy per document (slot): keyed by
 * the file's absolute path, or {@code untitled-N}. An instance deletes only its own copies; a
 * copy in a folder whose lock nobody holds belongs to an IDE that is gone and is offered for
 * recovery ({@link #orphans}); recovering it moves it into the recovering instance's folder
 * ({@link #adopt}), so it stays on disk until that document is saved or discarded. Writes go
 * through the output rules ({@link AtomicFiles}: whole or not at all).
 */
public final class Autosave implements AutoCloseable {
    /** Lock files held by this JVM: probing them through another channel would drop the OS lock. */
    private static final Set<Path> HELD = ConcurrentHashMap.newKeySet();
    private static final String LOCK = "lock";

    private final Path root;
    private final Path mine;
    private final FileChannel channel;
    private final FileLock lock;
    private int untitled;

    /**
     * A copy of unsaved text: its owner's folder, its slot, the file it belongs to (null: untitled),
     * the example it is an unsaved copy of (null: none), its text.
     */
    public record Copy(Path owner, String slot, Path file, Path example, String text, long modified) {
        /** How the user knows the document: the file's name, "a copy of the example NAME", or an untitled script. */
        public String describe() {
            return file != null ? file.getFileName().toString()
                    : example != null ? UiMsg.COPY_OF_EXAMPLE.text(example.getFileName()) : UiMsg.AN_UNTITLED_SCRIPT.text();
        }
    }

    /**
     * Starts this instance's folder under {@code home/autosave} and locks it for the life of the
     * IDE. If the folder cannot be made, the IDE still runs: every {@link #write} then fails
     * and is retried.
     */
    public Autosave(Path home) {
        root = home.resolve("autosave");
        mine = root.resolve("ide-" + ProcessHandle.current().pid() + "-" + UUID.randomUUID().toString().substring(0, 8));
        Path lockFile = mine.resolve(LOCK).toAbsolutePath();
        FileChannel ch = null;
        FileLock l = null;
        try {
            Files.createDirectories(mine);
            ch = FileChannel.open(lockFile, StandardOpenOption.CREATE, StandardOpenOption.WRITE);
            l = ch.tryLock();
            HELD.add(lockFile);
        } catch (IOException e) {
            // Read-only or full home: no copies this session (write reports each failure).
        }
        channel = ch;
        lock = l;
    }

    /** This instance's id (its folder's name). */
    public String instanceId() {
        return mine.getFileName().toString();
    }

    /** The slot of a file: its absolute path, hashed into a file name. */
    public static String slotFor(Path file) {
        try {
            byte[] h = MessageDigest.getInstance("SHA-256")
                    .digest(file.toAbsolutePath().normalize().toString().getBytes(StandardCharsets.UTF_8));
            return "file-" + HexFormat.of().formatHex(h, 0, 10);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is part of every Java runtime", e);
        }
    }

    /** A new slot for an untitled document of this instance. */
    public String untitledSlot() {
        return "untitled-" + ++untitled;
    }

    /** Writes {@code text}, the unsaved content of {@code file} (null: untitled), into this instance's {@code slot}. */
    public void write(String slot, Path file, String text) throws IOException {
        write(slot, file, null, text);
    }

    /** As {@link #write(String, Path, String)} for an untitled copy of the example {@code example} (null: none). */
    public void write(String slot, Path file, Path example, String text) throws IOException {
        Files.createDirectories(mine);
        Properties meta = new Properties();
        meta.setProperty("file", file == null ? "" : file.toAbsolutePath().normalize().toString());
        meta.setProperty("example", example == null ? "" : example.toAbsolutePath().normalize().toString());
        AtomicFiles.write(mine.resolve(slot + ".xml"), text);
        AtomicFiles.write(mine.resolve(slot + ".properties"), out -> meta.store(out, "PARPE autosave"));
    }

    /** Removes this instance's copy in {@code slot} (the text was saved, or the user discarded it). */
    public void clear(String slot) {
        delete(mine, slot);
    }

    /** This instance's copies. */
    public List<Copy> own() {
        return copies(mine);
    }

    /** The copies left by IDEs that no longer run (their lock is free), newest first; their empty folders are removed. */
    public List<Copy> orphans() {
        List<Copy> out = new ArrayList<>();
        for (Path dir : folders()) {
            if (!dir.equals(mine) && !alive(dir)) {
                List<Copy> left = copies(dir);
                out.addAll(left);
                if (left.isEmpty()) {
                    removeIfEmpty(dir); // an IDE killed with nothing unsaved
                }
            }
        }
        out.sort(Comparator.comparingLong(Copy::modified).reversed());
        return out;
    }

    /** Deletes an orphaned copy (the user chose to discard it); nothing if its owner is alive after all. */
    public void discard(Copy c) {
        if (!c.owner().equals(mine) && !alive(c.owner())) {
            delete(c.owner(), c.slot());
            removeIfEmpty(c.owner());
        }
    }

    /**
     * Moves an orphaned copy into this instance's folder (the user recovered it) and returns its
     * slot here; it is then deleted only by {@link #clear}.
     *
     * @throws IOException if the copy cannot be moved, or its owner turned out to be alive
     */
    public String adopt(Copy c) throws IOException {
        if (alive(c.owner())) {
            throw new IOException(UiMsg.COPY_BELONGS_TO_RUNNING.text());
        }
        String slot = c.file() == null ? untitledSlot() : slotFor(c.file());
        write(slot, c.file(), c.example(), c.text());
        delete(c.owner(), c.slot());
        removeIfEmpty(c.owner());
        return slot;
    }

    /** Releases the lock; the copies still here (unsaved work) are offered by the next IDE to start. */
    @Override
    public void close() {
        try {
            if (lock != null) {
                lock.release();
            }
            if (channel != null) {
                channel.close();
            }
        } catch (IOException e) {
            // The lock goes with the process anyway.
        }
        HELD.remove(mine.resolve(LOCK).toAbsolutePath());
        removeIfEmpty(mine);
    }

    private List<Path> folders() {
        if (!Files.isDirectory(root)) {
            return List.of();
        }
        try (Stream<Path> s = Files.list(root)) {
            return s.filter(Files::isDirectory).toList();
        } catch (IOException e) {
            return List.of();
        }
    }

    /** Whether the IDE owning {@code dir} still runs: its lock is held, here or by another process. */
    private static boolean alive(Path dir) {
        Path lockFile = dir.resolve(LOCK).toAbsolutePath();
        if (HELD.contains(lockFile)) {
            return true;
        }
        if (!Files.exists(lockFile)) {
            return false;
        }
        try (FileChannel ch = FileChannel.open(lockFile, StandardOpenOption.WRITE)) {
            FileLock probe = ch.tryLock();
            if (probe == null) {
                return true;
            }
            probe.release();
            return false;
        } catch (OverlappingFileLockException e) {
            return true;
        } catch (IOException e) {
            // Cannot tell: treat as alive, so that nothing of a running IDE is ever deleted.
            return true;
        }
    }

    private static List<Copy> copies(Path dir) {
        List<Copy> out = new ArrayList<>();
        try (Stream<Path> s = Files.list(dir)) {
            for (Path p : s.filter(p -> p.getFileName().toString().endsWith(".xml")).toList()) {
                String name = p.getFileName().toString();
                Copy c = read(dir, name.substring(0, name.length() - ".xml".length()));
                if (c != null) {
                    out.add(c);
                }
            }
        } catch (IOException e) {
            // A folder that vanished meanwhile holds nothing to offer.
        }
        return out;
    }

    private static Copy read(Path dir, String slot) {
        try {
            Path buf = dir.resolve(slot + ".xml");
            String text = Files.readString(buf, StandardCharsets.UTF_8);
            Properties meta = new Properties();
            Path m = dir.resolve(slot + ".properties");
            if (Files.isRegularFile(m)) {
                try (var in = Files.newInputStream(m)) {
                    meta.load(in);
                }
            }
            String f = meta.getProperty("file", "");
            String ex = meta.getProperty("example", "");
            return new Copy(dir, slot, f.isEmpty() ? null : Path.of(f), ex.isEmpty() ? null : Path.of(ex), text,
                    Files.getLastModifiedTime(buf).toMillis());
        } catch (IOException | IllegalArgumentException e) {
            return null;
        }
    }

    private static void delete(Path dir, String slot) {
        try {
            Files.deleteIfExists(dir.resolve(slot + ".xml"));
            Files.deleteIfExists(dir.resolve(slot + ".properties"));
        } catch (IOException e) {
            // A stale copy is only offered once more; nothing is lost.
        }
    }

    /** Removes an instance folder that holds no copy any more (its lock file only). */
    private static void removeIfEmpty(Path dir) {
        if (!copies(dir).isEmpty() || HELD.contains(dir.resolve(LOCK).toAbsolutePath())) {
            return;
        }
        try {
            Files.deleteIfExists(dir.resolve(LOCK));
            Files.deleteIfExists(dir);
        } catch (IOException e) {
            // Left for the next start; an empty folder costs nothing.
        }
    }
}
