package org.parpe.core.io;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.parpe.core.text.Msg;

/**
 * One output of a command, checked by {@link OutputPlan}: written whole through
 * {@link AtomicFiles}, and every failure is an {@link OutputException} naming the option and
 * the file as the user wrote it.
 */
public final class Output {
    private final String option;
    private final String shown;
    private final Path target;

    Output(String option, String shown, Path target) {
        this.option = option;
        this.shown = shown;
        this.target = target;
    }

    /** The option that names this output ({@code --trace}). */
    public String option() {
        return option;
    }

    /** The file (absolute). */
    public Path target() {
        return target;
    }

    /** Writes the whole file. */
    public void write(Content content) throws OutputException {
        try {
            AtomicFiles.write(target, content);
        } catch (IOException | RuntimeException e) {
            throw failed(e);
        }
    }

    /** Writes the whole file as UTF-8 text. */
    public void write(String text) throws OutputException {
        write(Content.text(text));
    }

    /**
     * A UTF-8 writer for streaming content: {@code close()} puts the file in place,
     * {@link Stream#abort()} discards it (call it in a {@code finally}: after close it does
     * nothing). Failures while writing throw an {@link IOException} naming the option and file.
     */
    public Stream open() throws OutputException {
        try {
            return new Stream(AtomicFiles.begin(target));
        } catch (IOException | RuntimeException e) {
            throw failed(e);
        }
    }

    /** The failure {@code e} of this output as one message. */
    public OutputException failed(Exception e) {
        return new OutputException(Msg.CANNOT_WRITE_OUTPUT.text(option, shown, reason(e)));
    }

    private static String reason(Exception e) {
        return IoReasons.of(e);
    }

    /** The path as the user gave it. */
    @Override
    public String toString() {
        return shown;
    }

    /** A buffered UTF-8 writer to an output's temporary file. */
    public final class Stream extends Writer {
        private final AtomicFiles.Pending pending;
        private final Writer w;

        private Stream(AtomicFiles.Pending pending) {
            this.pending = pending;
            this.w = new BufferedWriter(new OutputStreamWriter(pending, StandardCharsets.UTF_8), 1 << 16);
        }

        @Override
        public void write(char[] buf, int off, int len) throws IOException {
            try {
                w.write(buf, off, len);
            } catch (IOException e) {
                throw named(e);
            }
        }

        @Override
        public void flush() throws IOException {
            try {
                w.flush();
            } catch (IOException e) {
                throw named(e);
            }
        }

        @Override
        public void close() throws IOException {
            try {
                w.flush();
                pending.close();
            } catch (IOException e) {
                pending.abort();
                throw named(e);
            }
        }

        /** Discards what was written; the target stays as it was. */
        public void abort() {
            pending.abort();
        }

        private IOException named(IOException e) {
            return new IOException(failed(e).getMessage(), e);
        }
    }
}
