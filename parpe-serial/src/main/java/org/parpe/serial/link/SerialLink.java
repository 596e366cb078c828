package org.parpe.serial.link;

import org.parpe.serial.text.SerialMsg;
import com.fazecast.jSerialComm.SerialPort;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.locks.LockSupport;

/**
 * A serial device (a USB adapter, a UART, or one end of a {@code socat} pty pair) at a fixed
 * baud rate, 8N1, no flow control. Reads poll without blocking because the kernel's read
 * timeout only has tenths of a second (VTIME), too coarse for the bus's millisecond timeouts.
 */
public final class SerialLink implements ByteLink {
    private static final long POLL_NANOS = 200_000;
    private static final int POLLS_PER_READ = 5;
    private static final long WRITE_STALL_NANOS = 50_000_000;

    private final SerialPort port;
    private final String path;
    private volatile boolean closed;

    private SerialLink(SerialPort port, String path) {
        this.port = port;
        this.path = path;
    }

    /**
     * The serial devices present now, as the system names them ({@code /dev/ttyUSB0},
     * {@code COM3}, {@code /dev/cu.usbserial-…}), USB adapters first; empty when none can be listed.
     */
    public static java.util.List<String> availablePorts() {
        try {
            return java.util.Arrays.stream(SerialPort.getCommPorts())
                    .map(SerialPort::getSystemPortPath)
                    .sorted(java.util.Comparator.comparing((String p) -> !p.matches(".*(USB|ACM|usb).*"))
                            .thenComparing(java.util.Comparator.naturalOrder()))
                    .distinct()
                    .toList();
        } catch (RuntimeException | LinkageError e) {
            return java.util.List.of(); // no native library for this system: the user types the port
        }
    }

    /**
     * Opens {@code path} at {@code baud}.
     *
     * @throws LinkException with a message naming the path and the reason
     */
    public static SerialLink open(String path, int baud) throws LinkException {
        if (baud <= 0) {
            throw new LinkException(SerialMsg.LINK_BAD_BAUD.text(baud));
        }
        Path p = Path.of(path);
        if (!Files.exists(p)) {
            throw new LinkException(SerialMsg.LINK_NO_DEVICE.text(path));
        }
        if (Files.isDirectory(p) || Files.isRegularFile(p)) {
            throw new LinkException(SerialMsg.LINK_NOT_SERIAL.text(path));
        }
        if (!Files.isReadable(p) || !Files.isWritable(p)) {
            throw new LinkException(SerialMsg.LINK_NO_PERMISSION.text(path));
        }
        SerialPort port;
        try {
            port = SerialPort.getCommPort(path);
        } catch (RuntimeException e) {
            throw new LinkException(SerialMsg.LINK_CANNOT_USE.text(path, e.getMessage()));
        }
        port.setComPortParameters(baud, 8, SerialPort.ONE_STOP_BIT, SerialPort.NO_PARITY);
        port.setFlowControl(SerialPort.FLOW_CONTROL_DISABLED);
        port.setComPortTimeouts(SerialPort.TIMEOUT_NONBLOCKING, 0, 0);
        if (!port.openPort()) {
            throw new LinkException(openFailure(path, port.getLastErrorCode()));
        }
        return new SerialLink(port, path);
    }

    /**
     * Why {@code path} would not open, from the system's error number: on Linux and macOS 25
     * (ENOTTY) is a device that is no serial port, 16 (EBUSY) one another program holds, 13
     * (EACCES) one without permission; other numbers are given as they are.
     */
    static String openFailure(String path, int errno) {
        String os = System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT);
        if (!os.startsWith("windows")) {
            switch (errno) {
                case 25:
                    return SerialMsg.LINK_NOT_TTY.text(path);
                case 16:
                    return SerialMsg.LINK_BUSY.text(path);
                case 13:
                    return SerialMsg.LINK_NO_PERMISSION.text(path);
                default:
                    break;
            }
        }
        return SerialMsg.LINK_CANNOT_OPEN.text(path, errno);
    }

    /**
     * Runs {@code action} when the JVM shuts down (Ctrl-C), before jSerialComm closes the open
     * ports, so that last frames (an emergency stop) can still be sent.
     */
    public static void beforePortsClose(Runnable action) {
        SerialPort.addShutdownHook(new Thread(action, "serial-last-words"));
    }

    @Override
    public void write(byte[] b, int off, int len) throws IOException {
        long deadline = 0;
        while (len > 0) {
            if (closed) {
                throw new LinkException(SerialMsg.LINK_CLOSED.text(path));
            }
            int n = port.writeBytes(b, len, off);
            if (n < 0 || n == 0 && port.bytesAvailable() < 0) {
                throw new LinkException(SerialMsg.LINK_GONE.text(path));
            }
            if (n == 0) {
                // A full output buffer: a real UART drains at the baud rate, a pty only when read.
                long now = System.nanoTime();
                if (deadline == 0) {
                    deadline = now + WRITE_STALL_NANOS;
                } else if (now - deadline > 0) {
                    throw new LinkException(SerialMsg.LINK_STALLED.text(path, WRITE_STALL_NANOS / 1_000_000));
                }
                LockSupport.parkNanos(POLL_NANOS);
                continue;
            }
            deadline = 0;
            off += n;
            len -= n;
        }
    }

    @Override
    public int read(byte[] b) throws IOException {
        for (int i = 0; i < POLLS_PER_READ; i++) {
            if (closed) {
                throw new LinkException(SerialMsg.LINK_CLOSED.text(path));
            }
            int n = port.readBytes(b, b.length);
            if (n < 0) {
                throw new LinkException(SerialMsg.LINK_GONE.text(path));
            }
            if (n > 0) {
                return n;
            }
            LockSupport.parkNanos(POLL_NANOS);
        }
        return 0;
    }

    @Override
    public int pendingOutput() {
        return closed ? 0 : Math.max(0, port.bytesAwaitingWrite());
    }

    @Override
    public String name() {
        return path;
    }

    @Override
    public void close() {
        if (!closed) {
            closed = true;
            port.closePort();
        }
    }
}
