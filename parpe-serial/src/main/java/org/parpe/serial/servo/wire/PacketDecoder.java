package org.parpe.serial.servo.wire;

import org.parpe.serial.link.ReceiveBuffer;
import org.parpe.serial.link.StreamDecoder;

/**
 * Turns a received byte stream into packets: finds the header, waits for the whole packet,
 * checks its CRC or checksum and after a mismatch resynchronises one byte further. Accepts any
 * input without throwing; no allocation after construction; not thread-safe.
 */
public abstract class PacketDecoder implements StreamDecoder {
    private final PacketHandler handler;
    private final ReceiveBuffer rx = new ReceiveBuffer(4 * Packet.MAX_PARAMS + 64);
    /** Received bytes; those not consumed yet are from the position {@link #tryPacket} is given on. */
    protected final byte[] buf = rx.bytes();
    private final Packet packet = new Packet();
    private long packets;
    private long checksumErrors;

    /** A decoder that hands packets to {@code handler}. */
    protected PacketDecoder(PacketHandler handler) {
        this.handler = handler;
    }

    /** Feeds received bytes; complete packets are handed over before it returns. */
    public final void feed(byte[] data, int off, int len) {
        while (len > 0) {
            int n = rx.append(data, off, len);
            off += n;
            len -= n;
            parse();
        }
    }

    /** A silence on the line: a pending partial packet cannot complete, so its bytes are rescanned one further. */
    public final void idle() {
        while (rx.pending() > 0) {
            rx.consumeTo(rx.start() + 1);
            parse();
        }
        rx.clear();
    }

    /** Bytes received but not yet part of a packet. */
    public final int pending() {
        return rx.pending();
    }

    /** Packets recognised. */
    public final long packets() {
        return packets;
    }

    /** Packets whose header and length looked right but whose CRC or checksum did not match. */
    public final long checksumErrors() {
        return checksumErrors;
    }

    /** Outcome of {@link #tryPacket}: no header at this position. */
    protected static final int NO_HEADER = -1;
    /** Outcome of {@link #tryPacket}: a header, but the packet is not complete yet. */
    protected static final int INCOMPLETE = -2;
    /** Outcome of {@link #tryPacket}: a complete packet with a wrong CRC or checksum. */
    protected static final int BAD_CHECK = -3;

    /**
     * Looks for a packet at {@code buf[p]} with {@code avail} bytes available; on success fills
     * {@code out} (id, code, error, params, length) and returns the packet's length on the wire.
     */
    protected abstract int tryPacket(int p, int avail, Packet out);

    private void parse() {
        int p = rx.start();
        int end = rx.end();
        while (p < end) {
            int r = tryPacket(p, end - p, packet);
            if (r == INCOMPLETE) {
                break;
            }
            if (r == NO_HEADER || r == BAD_CHECK) {
                checksumErrors += r == BAD_CHECK ? 1 : 0;
                p++;
                continue;
            }
            System.arraycopy(buf, p, packet.raw, 0, r);
            packet.rawLength = r;
            packets++;
            p += r;
            rx.consumeTo(p);
            handler.onPacket(packet);
        }
        rx.settle(p);
    }
}
