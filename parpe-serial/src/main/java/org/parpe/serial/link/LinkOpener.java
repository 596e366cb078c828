package org.parpe.serial.link;

import java.io.IOException;

/** Opens (and after a fault, reopens) the link to the bus. */
@FunctionalInterface
public interface LinkOpener {

    /** Opens the link; throws {@link LinkException} with a user message when it cannot. */
    ByteLink open() throws IOException;

    /** An opener of the serial device {@code path} at {@code baud}. */
    static LinkOpener serial(String path, int baud) {
        return () -> SerialLink.open(path, baud);
    }
}
