package org.parpe.core.xml;

import java.io.FilterInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import org.parpe.core.text.Msg;

/**
 * Opens every file PARPE reads as input (scripts, included and robot files, stimulus files,
 * simulator robot configurations): only regular files, at most {@link #MAX_BYTES} bytes.
 * Devices such as {@code /dev/zero} and FIFOs are refused before they are opened, so an endless
 * input or a FIFO without a writer ends in a message instead of running out of memory or
 * blocking. Messages of the {@link IOException}s say what is wrong, without the file name, in the
 * chosen language ({@link org.parpe.core.text.Lang}).
 */
public final class InputFiles {
    /** The largest input file, 16 MiB: far beyond any script, small enough to load in little memory. */
    public static final long MAX_BYTES = 16L << 20;

    private InputFiles() {
    }

    /** Whether {@code file} is named as a script ({@code .xml} or {@code .parsl}, any case): what a folder of scripts holds. */
    public static boolean isScript(Path file) {
        Path name = file.getFileName();
        String n = name == null ? "" : name.toString().toLowerCase(java.util.Locale.ROOT);
        return n.endsWith(".xml") || n.endsWith(".parsl");
    }

    /** Checks that {@code file} can be read as an input file, without opening it. */
    public static void check(Path file) throws IOException {
        checkKind(file);
        long size = Files.size(file);
        if (size > MAX_BYTES) {
            throw tooLarge(Msg.N_BYTES.text(size));
        }
    }

    /**
     * Checks that {@code file} is a readable regular file, whatever its size (the IDE opens
     * larger files than the command line reads): the words for a folder, a device or a missing
     * file that every reader of PARPE uses.
     */
    public static void checkKind(Path file) throws IOException {
        if (Files.isDirectory(file)) {
            throw new IOException(Msg.IS_A_DIRECTORY.text());
        }
        if (!Files.exists(file)) {
            throw new IOException(Msg.NO_SUCH_FILE.text());
        }
        if (!Files.isRegularFile(file)) {
            throw new IOException(Msg.NOT_A_REGULAR_FILE.text());
        }
        if (!Files.isReadable(file)) {
            throw new IOException(Msg.PERMISSION_DENIED.text());
        }
    }

    /** Opens {@code file} after {@link #check}; reading past {@link #MAX_BYTES} (a growing file) fails. */
    public static InputStream open(Path file) throws IOException {
        check(file);
        try {
            return new Bounded(Files.newInputStream(file));
        } catch (NoSuchFileException e) {
            throw new IOException(Msg.NO_SUCH_FILE.text(), e);
        } catch (AccessDeniedException e) {
            throw new IOException(Msg.PERMISSION_DENIED.text(), e);
        }
    }

    /** The whole file as UTF-8 text, without a leading byte order mark. */
    public static String readText(Path file) throws IOException {
        byte[] bytes;
        try (InputStream in = open(file)) {
            bytes = in.readAllBytes();
        }
        String s;
        try {
            s = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(ByteBuffer.wrap(bytes)).toString();
        } catch (CharacterCodingException e) {
            throw new IOException(Msg.NOT_UTF8.text(), e);
        }
        return s.startsWith("\uFEFF") ? s.substring(1) : s;
    }

    private static IOException tooLarge(String size) {
        return new IOException(Msg.FILE_TOO_LARGE.text(size, MAX_BYTES >> 20));
    }

    /** Fails once more than {@link #MAX_BYTES} bytes were read. */
    private static final class Bounded extends FilterInputStream {
        private long count;

        Bounded(InputStream in) {
            super(in);
        }

        @Override
        public int read() throws IOException {
            int b = super.read();
            if (b >= 0) {
                count(1);
            }
            return b;
        }

        @Override
        public int read(byte[] buf, int off, int len) throws IOException {
            int n = super.read(buf, off, (int) Math.min(len, MAX_BYTES + 1 - count));
            if (n > 0) {
                count(n);
            }
            return n;
        }

        private void count(int n) throws IOException {
            count += n;
            if (count > MAX_BYTES) {
                throw tooLarge(Msg.MORE_THAN_BYTES.text(MAX_BYTES));
            }
        }
    }
}
