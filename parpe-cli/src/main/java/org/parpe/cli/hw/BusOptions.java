package org.parpe.cli.hw;

import org.parpe.cli.text.CliMsg;
import org.parpe.cli.options.UsageException;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.bus.SafeMode;
import picocli.CommandLine.Option;

/** The bus options shared by {@code run} and {@code record}: baud, fault mode, read timing. */
public class BusOptions {
    @Option(names = "--baud", paramLabel = "N", defaultValue = "115200",
            description = "Serial line speed, bits per second (default ${DEFAULT-VALUE}).")
    int baud;

    @Option(names = "--on-fault", paramLabel = "hold|limp", defaultValue = "hold",
            description = "What modules do when they lose the host or on emergency stop: hold their angle or go limp "
                    + "(default ${DEFAULT-VALUE}).")
    String onFault;

    @Option(names = "--read-timeout", paramLabel = "MS", defaultValue = "20",
            description = "Wait this long for a module's reply before retrying (default ${DEFAULT-VALUE}).")
    int readTimeout;

    @Option(names = "--retries", paramLabel = "N", defaultValue = "2",
            description = "Extra attempts after a read times out (default ${DEFAULT-VALUE}).")
    int retries;

    /** The bus settings these options describe. */
    BusConfig config() throws UsageException {
        SafeMode mode;
        switch (onFault) {
            case "hold" -> mode = SafeMode.HOLD;
            case "limp" -> mode = SafeMode.LIMP;
            default -> throw new UsageException(CliMsg.BAD_ON_FAULT.text(onFault));
        }
        try {
            return BusConfig.defaults().withBaud(baud).withSafeMode(mode).withReads(readTimeout, retries);
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
    }
}
