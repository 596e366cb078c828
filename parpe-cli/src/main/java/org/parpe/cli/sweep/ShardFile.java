package org.parpe.cli.sweep;

import org.parpe.cli.text.CliMsg;
import java.io.BufferedWriter;
import java.io.FilterOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import org.parpe.cli.options.UsageException;
import org.parpe.core.io.AtomicFiles;
import org.parpe.sim.sweep.SweepCsv;

/**
 * The file of one shard ({@code sweep --shard K/N --out FILE}), written for clusters whose tasks
 * may be cancelled, run out of time or be killed: the rows go to a visible {@code FILE.partial}
 * as each one finishes (a killed task keeps them), framed by {@link SweepCsv#shardStart}; only a
 * shard that ran to its end gets its last line and is renamed to {@code FILE}. So a shard under
 * its proper name is always whole, and {@code parpe merge} can name what is missing.
 */
final class ShardFile {
    private final Path target;
    private final Path partial;
    /** The open, locked {@code .partial} while this task writes it. */
    private FileChannel channel;

    private ShardFile(Path target) {
        this.target = target;
        this.partial = target.resolveSibling(target.getFileName() + ".partial");
    }

    /** The shard file {@code out} (already checked as an output target). */
    static ShardFile of(String out) throws UsageException {
        ShardFile f = new ShardFile(Path.of(out).toAbsolutePath().normalize());
        // A .partial file that is not a shard's is someone else's: never overwrite it.
        if (Files.exists(f.partial)) {
            String first;
            try (var lines = Files.lines(f.partial, StandardCharsets.UTF_8)) {
                first = lines.findFirst().orElse("");
            } catch (IOException | java.io.UncheckedIOException e) {
                first = "";
            }
            if (SweepCsv.shardOf(first) == null && !first.isEmpty()) {
                throw new UsageException(CliMsg.PARTIAL_NOT_A_SHARD.text(out + ".partial"));
            }
        }
        return f;
    }

    /**
     * Opens {@code FILE.partial} (replacing an unfinished shard's) for writing, locked for this
     * task until {@link #commit} or {@link #release}: a second sweep given the same {@code --out}
     * while this one runs is refused instead of both writing one file (the lock goes with the
     * process, so a killed task leaves none behind). A link, device or FIFO planted at that name
     * is refused, never followed.
     */
    Writer open() throws IOException {
        if (Files.exists(partial, LinkOption.NOFOLLOW_LINKS) && !Files.isRegularFile(partial, LinkOption.NOFOLLOW_LINKS)) {
            throw new IOException(CliMsg.NOT_A_REGULAR_FILE.text(partial));
        }
        channel = FileChannel.open(partial, StandardOpenOption.CREATE, StandardOpenOption.WRITE, LinkOption.NOFOLLOW_LINKS);
        FileLock lock;
        try {
            lock = channel.tryLock();
        } catch (OverlappingFileLockException e) {
            lock = null; // held by another sweep in this JVM
        }
        if (lock == null) {
            release();
            throw new IOException(CliMsg.SHARD_LOCKED.text(partial));
        }
        channel.truncate(0);
        // closing the writer flushes; the channel and its lock stay until the shard is in place
        OutputStream out = new FilterOutputStream(Channels.newOutputStream(channel)) {
            @Override
            public void write(byte[] b, int off, int len) throws IOException {
                this.out.write(b, off, len);
            }

            @Override
            public void close() throws IOException {
                flush();
            }
        };
        return new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8));
    }

    /**
     * The shard ran to its end and its writer is closed: it takes its proper name, put in place
     * by the output policy (through a link, over a regular file only, keeping its mode), and then
     * lets go of its lock.
     */
    void commit() throws IOException {
        try {
            AtomicFiles.moveIntoPlace(partial, target);
        } finally {
            release();
        }
    }

    /** Lets go of the lock (closes the file); harmless when it is not held. */
    void release() {
        if (channel != null) {
            try {
                channel.close();
            } catch (IOException e) {
                // closing releases the lock whatever it reports
            }
            channel = null;
        }
    }

    /** Where the rows of an unfinished shard are. */
    Path partial() {
        return partial;
    }
}
