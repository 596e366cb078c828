package org.parpe.core.io;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Objects;
import org.parpe.core.text.Msg;

/**
 * The files one command reads and writes, checked before it does any work. Every file read
 * (script, includes, robot configuration, hardware profile, stimulus, CSV shards) is registered
 * with {@link #input}; each output is then claimed with {@link #output}, which refuses it when
 * it names an input or an output claimed before (compared as files: links followed, hard links
 * and {@code ./x} spellings included), a directory, anything but a regular file (device, FIFO,
 * socket, dangling link), a missing or read-only folder, or an existing file that may only be
 * replaced by an explicit choice ({@link Existing#KEEP}, for example a default name, or
 * {@code scan}'s profile without {@code --force}), and a file the user could not write in an
 * editor (write-protected, or another user's). Outputs are written through
 * {@link AtomicFiles}.
 */
public final class OutputPlan {
    /** What to do with a regular file already at an output's name. */
    public enum Existing {
        /** Replace it: the user named this file for this output. */
        REPLACE,
        /** Refuse: replacing needs an explicit choice (the hint says which). */
        KEEP
    }

    private final List<Path> inputs = new ArrayList<>();
    private final List<Output> outputs = new ArrayList<>();

    /** Registers a file the command reads. */
    public OutputPlan input(Path file) {
        inputs.add(Objects.requireNonNull(file));
        return this;
    }

    /** Registers files the command reads. */
    public OutputPlan inputs(Collection<Path> files) {
        files.forEach(this::input);
        return this;
    }

    /** Claims {@code path}, the value of {@code option}, as an output that replaces a regular file the user named. */
    public Output output(String option, String path) throws OutputException {
        return output(option, path, Existing.REPLACE, null);
    }

    /**
     * Claims {@code path}, the value of {@code option}, as an output; with {@link Existing#KEEP},
     * an existing file is refused with {@code hint} (what to do instead).
     */
    public Output output(String option, String path, Existing existing, String hint) throws OutputException {
        Path target;
        try {
            target = Path.of(path).toAbsolutePath().normalize();
        } catch (InvalidPathException e) {
            throw cannot(option, path, Msg.NOT_A_VALID_PATH.text());
        }
        if (Files.isDirectory(target)) {
            throw cannot(option, path, Msg.IS_A_DIRECTORY.text());
        }
        boolean exists = Files.exists(target, LinkOption.NOFOLLOW_LINKS);
        if (exists && !Files.isRegularFile(target)) {
            throw cannot(option, path, Msg.OUTPUT_NOT_REGULAR.text());
        }
        Path dir = target.getParent();
        try {
            dir = AtomicFiles.resolve(target).getParent();
        } catch (IOException e) {
            throw cannot(option, path, e.getMessage());
        }
        if (dir == null || !Files.isDirectory(dir)) {
            throw cannot(option, path, Msg.NO_DIRECTORY.text(dir));
        }
        if (!Files.isWritable(dir)) {
            throw cannot(option, path, Msg.DIRECTORY_NOT_WRITABLE.text(dir));
        }
        Object id = identity(target);
        for (Path in : inputs) {
            if (id.equals(identity(in))) {
                throw cannot(option, path, Msg.OUTPUT_IS_INPUT.text(in));
            }
        }
        for (Output o : outputs) {
            if (id.equals(identity(o.target()))) {
                throw cannot(option, path, Msg.OUTPUT_TWICE.text(o.option()));
            }
        }
        if (exists && existing == Existing.KEEP) {
            throw cannot(option, path, hint == null ? Msg.OUTPUT_EXISTS.text() : Msg.OUTPUT_EXISTS_HINT.text(hint));
        }
        try {
            Path real = AtomicFiles.resolve(target);
            AtomicFiles.checkReplaceable(real);
            AtomicFiles.checkOwner(real, AtomicFiles.currentUser());
        } catch (IOException e) {
            throw cannot(option, path, e.getMessage());
        }
        Output o = new Output(option, path, target);
        outputs.add(o);
        return o;
    }

    /** Whether {@code a} and {@code b} name one file (links followed, hard links and other spellings included). */
    public static boolean sameFile(Path a, Path b) {
        return identity(a).equals(identity(b));
    }

    /**
     * What a path is as a file: the file system's key of an existing file (equal for links and
     * hard links to one file), otherwise the real folder and the name.
     */
    static Object identity(Path p) {
        Path abs = p.toAbsolutePath().normalize();
        try {
            Object key = Files.readAttributes(abs, BasicFileAttributes.class).fileKey();
            return key != null ? key : abs.toRealPath();
        } catch (NoSuchFileException e) {
            Path dir = abs.getParent();
            try {
                return dir == null ? abs : dir.toRealPath().resolve(abs.getFileName());
            } catch (IOException again) {
                return abs;
            }
        } catch (IOException e) {
            return abs;
        }
    }

    /** {@code cannot write OPTION file 'PATH': WHY}. */
    private static OutputException cannot(String option, String path, Object why) {
        return new OutputException(Msg.CANNOT_WRITE_OUTPUT.text(option, path, why));
    }
}
