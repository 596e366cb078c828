package org.parpe.core.io;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermission;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The one way PARPE puts a file in place. The content goes to a new file with a random name
 * beside the target, created with {@code CREATE_NEW} (so a link planted at that name is never
 * followed), is forced to disk, gets the permissions of the file it replaces, and is then moved
 * over the target atomically: a reader sees the old file or the new one, never half of one, and
 * a failure (a full disk) leaves the old file and no temporary file. A target that is a symbolic
 * link is written through: the file it points to is replaced and the link stays. Only a regular
 * file or a new name is ever replaced. Whether a target may be replaced at all is the caller's
 * question ({@link OutputPlan}).
 */
public final class AtomicFiles {
    private static final SecureRandom RANDOM = new SecureRandom();

    private AtomicFiles() {
    }

    /** Writes {@code content} to {@code target}, replacing a regular file there atomically. */
    public static void write(Path target, Content content) throws IOException {
        Pending p = begin(target);
        try {
            content.writeTo(p);
            p.close();
        } finally {
            p.abort();
        }
    }

    /** Writes {@code text} as UTF-8 to {@code target}. */
    public static void write(Path target, String text) throws IOException {
        write(target, Content.text(text));
    }

    /**
     * Writes several files as one change: every file is written in full (and forced to disk)
     * before any replaces its old version, so a failure while writing (a full disk) leaves all
     * of them as they were; only then are they moved into place, one rename each.
     */
    public static void writeAll(Map<Path, Content> files) throws IOException {
        List<Pending> pending = new ArrayList<>();
        try {
            for (Map.Entry<Path, Content> f : files.entrySet()) {
                Pending p = begin(f.getKey());
                pending.add(p);
                f.getValue().writeTo(p);
                p.finish();
            }
            for (Pending p : pending) {
                p.close();
            }
        } finally {
            for (Pending p : pending) {
                p.abort();
            }
        }
    }

    /**
     * The file a write to {@code target} changes: the final target of a symbolic link, otherwise
     * {@code target} itself (absolute).
     *
     * @throws IOException if {@code target} is a link to nothing
     */
    public static Path resolve(Path target) throws IOException {
        Path abs = target.toAbsolutePath().normalize();
        if (Files.isSymbolicLink(abs)) {
            if (!Files.exists(abs)) {
                throw new IOException("it is a dangling link");
            }
            return abs.toRealPath();
        }
        return abs;
    }

    /** Starts writing {@code target}: a stream to a new temporary file that {@link Pending#close()} moves into place. */
    public static Pending begin(Path target) throws IOException {
        Path real = resolve(target);
        checkReplaceable(real);
        Path dir = real.getParent();
        if (dir == null || !Files.isDirectory(dir)) {
            throw new IOException("directory " + dir + " does not exist");
        }
        for (int attempt = 0; ; attempt++) {
            byte[] r = new byte[8];
            RANDOM.nextBytes(r);
            Path tmp = dir.resolve("." + real.getFileName() + "." + HexFormat.of().formatHex(r) + ".tmp");
            try {
                FileChannel ch = FileChannel.open(tmp, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
                return new Pending(real, tmp, ch);
            } catch (FileAlreadyExistsException e) {
                if (attempt == 9) {
                    throw e;
                }
            }
        }
    }

    /**
     * Moves the complete file {@code written} (beside the target, in the same folder) over
     * {@code target} atomically, as every write of this class ends: through a link to the file
     * it points to, only over a regular file, keeping the permissions of the file it replaces.
     * For a writer that must keep its own visible file while it works (a cluster shard's
     * {@code .partial}), so that it too ends the one way.
     */
    public static void moveIntoPlace(Path written, Path target) throws IOException {
        place(written, resolve(target));
    }

    private static void place(Path tmp, Path real) throws IOException {
        checkReplaceable(real);
        if (Files.exists(real)) {
            try {
                Set<PosixFilePermission> perms = Files.getPosixFilePermissions(real);
                Files.setPosixFilePermissions(tmp, perms);
            } catch (UnsupportedOperationException e) {
                // no POSIX permissions here (Windows): nothing to keep
            }
        }
        try {
            Files.move(tmp, real, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(tmp, real, StandardCopyOption.REPLACE_EXISTING);
        }
    }

    /** Refuses a target that exists and is not a regular file (a directory, device, FIFO or socket). */
    private static void checkReplaceable(Path real) throws IOException {
        if (Files.isDirectory(real, LinkOption.NOFOLLOW_LINKS)) {
            throw new IOException("it is a directory");
        }
        if (Files.exists(real, LinkOption.NOFOLLOW_LINKS) && !Files.isRegularFile(real, LinkOption.NOFOLLOW_LINKS)) {
            throw new IOException("it is not a regular file (a device, FIFO or socket); only regular files are replaced");
        }
    }

    /**
     * A file being written: a stream to its temporary file. {@link #close()} puts it in place;
     * {@link #abort()} (harmless after close) deletes the temporary file instead.
     */
    public static final class Pending extends OutputStream {
        private final Path target;
        private final Path tmp;
        private final FileChannel channel;
        private final OutputStream out;
        private boolean finished;
        private boolean done;

        private Pending(Path target, Path tmp, FileChannel channel) {
            this.target = target;
            this.tmp = tmp;
            this.channel = channel;
            this.out = Channels.newOutputStream(channel);
        }

        /** The file this replaces (a link's target, absolute). */
        public Path target() {
            return target;
        }

        @Override
        public void write(int b) throws IOException {
            out.write(b);
        }

        @Override
        public void write(byte[] b, int off, int len) throws IOException {
            out.write(b, off, len);
        }

        /** Forces the content to disk and closes the temporary file. */
        void finish() throws IOException {
            if (!finished) {
                finished = true;
                try {
                    channel.force(true);
                } finally {
                    channel.close();
                }
            }
        }

        /** Puts the complete file in place, keeping the permissions of the file it replaces. */
        @Override
        public void close() throws IOException {
            if (done) {
                return;
            }
            try {
                finish();
                place(tmp, target);
                done = true;
            } catch (IOException | RuntimeException e) {
                abort();
                throw e;
            }
        }

        /** Discards the temporary file unless the file was put in place. */
        public void abort() {
            if (done) {
                return;
            }
            done = true;
            try {
                channel.close();
            } catch (IOException e) {
                // the delete below is what matters
            }
            try {
                Files.deleteIfExists(tmp);
            } catch (IOException e) {
                // the first failure is the one to report
            }
        }
    }
}
