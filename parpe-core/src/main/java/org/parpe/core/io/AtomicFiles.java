package org.parpe.core.io;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.UserPrincipal;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.parpe.core.text.Msg;

/**
 * The one way PARPE puts a file in place. The content goes to a new file with a random name
 * beside the target, created with {@code CREATE_NEW} (so a link planted at that name is never
 * followed), is forced to disk, gets the permissions of the file it replaces, and is then moved
 * over the target atomically: a reader sees the old file or the new one, never half of one, and
 * a failure (a full disk) leaves the old file and no temporary file. A target that is a symbolic
 * link is written through: the file it points to is replaced and the link stays. Only a regular
 * file or a new name is ever replaced, and never one the user could not write in an editor: a
 * file without its owner's write permission (mode 0444; refused for root too, who could write
 * it) or a file of another user (the rename would leave one of ours in its place) is refused
 * ({@link #checkReplaceable}). The temporary name keeps within the file system's 255 bytes for
 * a name, however long the target's. Whether a target may be replaced at all is otherwise the
 * caller's question ({@link OutputPlan}).
 */
public final class AtomicFiles {
    private static final SecureRandom RANDOM = new SecureRandom();
    /** The longest file name (in UTF-8 bytes) of the file systems PARPE runs on (ext4, APFS, NTFS). */
    private static final int NAME_MAX = 255;
    /** What the temporary name adds to the target's: a dot, a dot and 16 hex digits, {@code .tmp}. */
    private static final int TMP_EXTRA = 1 + 1 + 16 + 4;

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
                throw new IOException(Msg.DANGLING_LINK.text());
            }
            return abs.toRealPath();
        }
        return abs;
    }

    /** Starts writing {@code target}: a stream to a new temporary file that {@link Pending#close()} moves into place. */
    public static Pending begin(Path target) throws IOException {
        Path real = resolve(target);
        int bytes = real.getFileName().toString().getBytes(StandardCharsets.UTF_8).length;
        if (bytes > NAME_MAX) {
            throw new IOException(Msg.NAME_TOO_LONG.text(bytes, NAME_MAX));
        }
        checkReplaceable(real);
        Path dir = real.getParent();
        if (dir == null || !Files.isDirectory(dir)) {
            throw new IOException(Msg.NO_DIRECTORY.text(dir));
        }
        for (int attempt = 0; ; attempt++) {
            byte[] r = new byte[8];
            RANDOM.nextBytes(r);
            Path tmp = dir.resolve("." + tmpStem(real.getFileName().toString()) + "." + HexFormat.of().formatHex(r) + ".tmp");
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

    /**
     * The part of {@code name} a temporary name starts with: all of it, or as many whole
     * characters as keep the temporary name within {@link #NAME_MAX} bytes (a 251-byte export
     * name could not be written when the temporary name was 22 bytes longer).
     */
    static String tmpStem(String name) {
        int room = NAME_MAX - TMP_EXTRA;
        if (name.getBytes(StandardCharsets.UTF_8).length <= room) {
            return name;
        }
        int end = 0;
        int bytes = 0;
        while (end < name.length()) {
            int cp = name.codePointAt(end);
            int n = new String(Character.toChars(cp)).getBytes(StandardCharsets.UTF_8).length;
            if (bytes + n > room) {
                break;
            }
            bytes += n;
            end += Character.charCount(cp);
        }
        return name.substring(0, end);
    }

    private static void place(Path tmp, Path real) throws IOException {
        checkReplaceable(real);
        checkOwner(real, ownerOf(tmp));
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

    /**
     * Refuses a target that exists and is not a regular file (a directory, device, FIFO or
     * socket), or is write-protected: without its owner's write permission (mode 0444, as
     * {@code chmod a-w} leaves it), or read-only on a file system without POSIX permissions.
     * The permission bit is read rather than asking {@link Files#isWritable}, which says yes to
     * root for every file; an editor refuses such a file for root too.
     */
    static void checkReplaceable(Path real) throws IOException {
        if (Files.isDirectory(real, LinkOption.NOFOLLOW_LINKS)) {
            throw new IOException(Msg.IS_A_DIRECTORY.text());
        }
        if (!Files.exists(real, LinkOption.NOFOLLOW_LINKS)) {
            return;
        }
        if (!Files.isRegularFile(real, LinkOption.NOFOLLOW_LINKS)) {
            throw new IOException(Msg.NOT_REPLACEABLE.text());
        }
        boolean writable;
        try {
            writable = Files.getPosixFilePermissions(real).contains(PosixFilePermission.OWNER_WRITE);
        } catch (UnsupportedOperationException e) {
            writable = Files.isWritable(real);
        }
        if (!writable) {
            throw new IOException(Msg.WRITE_PROTECTED.text());
        }
    }

    /**
     * Refuses to replace {@code real} when it belongs to another user than {@code writer}, the
     * owner of the file that would take its place: the rename would leave a file of ours where
     * theirs was, a change of owner no editor makes. Root is no exception (a file of a student
     * replaced by root's would no longer be the student's). POSIX file systems only: on Windows
     * an administrator's files belong to the Administrators group, not to the user.
     */
    static void checkOwner(Path real, UserPrincipal writer) throws IOException {
        if (writer == null || !Files.exists(real, LinkOption.NOFOLLOW_LINKS)
                || !real.getFileSystem().supportedFileAttributeViews().contains("posix")) {
            return;
        }
        UserPrincipal owner;
        try {
            owner = Files.getOwner(real, LinkOption.NOFOLLOW_LINKS);
        } catch (UnsupportedOperationException e) {
            return; // no owners here
        }
        if (!owner.equals(writer)) {
            throw new IOException(Msg.OTHER_OWNER.text(owner.getName(), writer.getName()));
        }
    }

    private static UserPrincipal ownerOf(Path file) throws IOException {
        try {
            return Files.getOwner(file, LinkOption.NOFOLLOW_LINKS);
        } catch (UnsupportedOperationException e) {
            return null;
        }
    }

    /** The user this process writes files as, or {@code null} when the system cannot say. */
    static UserPrincipal currentUser() {
        try {
            return FileSystems.getDefault().getUserPrincipalLookupService()
                    .lookupPrincipalByName(System.getProperty("user.name"));
        } catch (IOException | UnsupportedOperationException e) {
            return null;
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
