package org.parpe.serial.servo.host;

import java.io.IOException;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.g1.G1Bus;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.servo.ServoBus;
import org.parpe.serial.servo.ServoProtocol;

/** Opens the {@link ServoBus} of a protocol. */
public final class ServoBuses {
    private ServoBuses() {
    }

    /**
     * Opens the device through {@code opener} and starts speaking {@code protocol} with the line
     * speed and read timeout of {@code config}.
     *
     * @throws IOException with a user message when the device cannot be opened
     */
    public static ServoBus open(ServoProtocol protocol, LinkOpener opener, BusConfig config) throws IOException {
        if (!protocol.controlTable()) {
            return new G1Bus(opener.open(), config);
        }
        return new ControlTableBus(protocol, opener.open(), config.baud(), config.readTimeoutMs());
    }
}
