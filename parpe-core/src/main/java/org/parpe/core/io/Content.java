package org.parpe.core.io;

import java.io.IOException;
import java.io.OutputStream;

/** Writes the whole content of one file. */
@FunctionalInterface
public interface Content {
    /** Writes everything to {@code out}. */
    void writeTo(OutputStream out) throws IOException;

    /** The UTF-8 bytes of {@code text}. */
    static Content text(String text) {
        return out -> out.write(text.getBytes(java.nio.charset.StandardCharsets.UTF_8));
    }
}
