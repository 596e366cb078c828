package org.parpe.cli;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.Collection;

/**
 * Every file the command line writes (trace, metrics, plot, recording, emulator log). The target
 * is checked before a run starts: it must be a regular file or a new path in an existing
 * directory, and not one of the run's input files. The content goes to a temporary file beside
 * the target that replaces it atomically once complete, so a failed write never leaves half a
 * file nor touches what was there. A failure is a {@link UsageException} naming the option and
 * the path (exit code 2).
 */
public final class OutputFile {
    /** Writes the content of a file. */
    @FunctionalInterface
    public interface Content {
        /** Writes everything to {@code out}. */
        void writeTo(OutputStream out) throws IOException;
    }

    private final String option;
    private final String shown;
    private final Path target;

    private OutputFile(String option, String shown, Path target) {
        this.option = option;
        this.shown = shown;
        this.target = target;
    }

    /**
     * Checks {@code path}, given to {@code option}, as a target; {@code inputs} are the files the
     * command reads, which it may not overwrite.
     */
    public static OutputFile of(String option, String path, Collection<Path> inputs) throws UsageException {
        Path target;
        try {
            target = Path.of(path).toAbsolutePath().normalize();
        } catch (InvalidPathException e) {
            throw new UsageException("cannot write " + option + " file '" + path + "': not a valid path");
        }
        OutputFile f = new OutputFile(option, path, target);
        f.checkTarget(inputs);
        return f;
    }

    private void checkTarget(Collection<Path> inputs) throws UsageException {
        String cannot = "cannot write " + option + " file '" + shown + "': ";
        if (Files.isDirectory(target)) {
            throw new UsageException(cannot + "it is a directory");
        }
        if (Files.exists(target, LinkOption.NOFOLLOW_LINKS) && !Files.isRegularFile(target)) {
            throw new UsageException(cannot + "it is not a regular file (a device, FIFO, socket or dangling link);"
                    + " outputs replace regular files only");
        }
        Path dir = target.getParent();
        if (dir == null || !Files.isDirectory(dir)) {
            throw new UsageException(cannot + "directory " + dir + " does not exist");
        }
        if (!Files.isWritable(dir)) {
            throw new UsageException(cannot + "directory " + dir + " is not writable");
        }
        for (Path in : inputs) {
            if (sameFile(in, target)) {
                throw new UsageException(cannot + "it is the input file '" + in + "'; choose another name");
            }
        }
    }

    private static boolean sameFile(Path input, Path target) {
        try {
            return Files.exists(target) ? Files.isSameFile(input, target)
                    : input.toAbsolutePath().normalize().equals(target);
        } catch (IOException e) {
            return false; // an input that vanished cannot be overwritten
        }
    }

    /** Checks {@code path} as a target unless it is {@code null} or {@code "-"} (standard output). */
    public static OutputFile ofOptional(String option, String path, Collection<Path> inputs) throws UsageException {
        return path == null || path.equals("-") ? null : of(option, path, inputs);
    }

    /** Writes the whole file. */
    public void write(Content content) throws UsageException {
        Path tmp = temp();
        try {
            try (OutputStream out = create(tmp)) {
                content.writeTo(out);
            }
            commit(tmp);
        } catch (IOException | RuntimeException e) {
            throw failed(tmp, e);
        }
    }

    /** Writes the whole file as UTF-8 text. */
    public void write(String text) throws UsageException {
        write(out -> out.write(text.getBytes(StandardCharsets.UTF_8)));
    }

    /**
     * A writer for streaming content: it writes to the temporary file and, on {@code close()},
     * replaces the target. A failure while writing or closing throws an {@link IOException}
     * whose message names the option and the file.
     */
    public Writer openWriter() throws UsageException {
        Path tmp = temp();
        Writer w;
        try {
            w = new OutputStreamWriter(create(tmp), StandardCharsets.UTF_8);
        } catch (IOException | RuntimeException e) {
            throw failed(tmp, e);
        }
        return new BufferedWriter(new Writer() {
            @Override
            public void write(char[] buf, int off, int len) throws IOException {
                try {
                    w.write(buf, off, len);
                } catch (IOException e) {
                    throw new IOException(failed(tmp, e).getMessage(), e);
                }
            }

            @Override
            public void flush() throws IOException {
                try {
                    w.flush();
                } catch (IOException e) {
                    throw new IOException(failed(tmp, e).getMessage(), e);
                }
            }

            @Override
            public void close() throws IOException {
                try {
                    w.close();
                    commit(tmp);
                } catch (IOException e) {
                    throw new IOException(failed(tmp, e).getMessage(), e);
                }
            }
        }, 1 << 16);
    }

    /** A new name beside the target; the file is created when opened (with the usual permissions). */
    private Path temp() {
        return target.resolveSibling("." + target.getFileName() + "." + ProcessHandle.current().pid() + "."
                + System.nanoTime() + ".tmp");
    }

    private static OutputStream create(Path tmp) throws IOException {
        return Files.newOutputStream(tmp, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
    }

    private void commit(Path tmp) throws IOException {
        try {
            Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING);
        }
    }

    private UsageException failed(Path tmp, Exception e) {
        try {
            Files.deleteIfExists(tmp);
        } catch (IOException ignored) {
            // the first failure is the one to report
        }
        return new UsageException("cannot write " + option + " file '" + shown + "': " + reason(e));
    }

    /** The path as the user gave it. */
    @Override
    public String toString() {
        return shown;
    }

    private static String reason(Exception e) {
        String m = e.getMessage();
        if (e instanceof java.nio.file.FileSystemException fs && fs.getReason() != null) {
            return fs.getReason();
        }
        return m == null ? e.getClass().getSimpleName() : m;
    }
}
