package org.parpe.serial.g1;

import org.parpe.serial.bus.Crc16;
import org.parpe.serial.link.ReceiveBuffer;
import org.parpe.serial.link.StreamDecoder;

/**
 * Turns a byte stream into frames. It finds the sync bytes, checks the length bound and the CRC,
 * and after any mismatch resynchronises one byte further, so garbage, cut frames and corrupted
 * bytes cost at most the frames they touch. No allocation after construction; any input is
 * accepted (it never throws on bytes). Not thread-safe.
 */
public final class FrameDecoder implements StreamDecoder {
    private final FrameHandler handler;
    private final ReceiveBuffer rx = new ReceiveBuffer(2 * Protocol.MAX_FRAME);
    private final byte[] buf = rx.bytes();
    private long frames;
    private long checksumErrors;
    private long garbageBytes;

    /** A decoder that passes frames to {@code handler}. */
    public FrameDecoder(FrameHandler handler) {
        this.handler = handler;
    }

    /** Feeds {@code len} received bytes; complete frames are handed over before it returns. */
    public void feed(byte[] data, int off, int len) {
        while (len > 0) {
            int n = rx.append(data, off, len);
            off += n;
            len -= n;
            parse();
        }
    }

    /**
     * Declares a silence on the line: a partial frame still pending cannot be completed (its
     * length was probably corrupted), so it is dropped byte by byte and the rest rescanned.
     */
    public void idle() {
        while (rx.pending() > 0) {
            rx.consumeTo(rx.start() + 1);
            garbageBytes++;
            parse();
        }
        rx.clear();
    }

    /** Bytes received but not yet part of a complete frame. */
    public int pending() {
        return rx.pending();
    }

    /** Frames recognised so far. */
    public long frames() {
        return frames;
    }

    /** Frames whose sync and length looked right but whose CRC did not match. */
    public long checksumErrors() {
        return checksumErrors;
    }

    /** Bytes skipped while looking for a frame. */
    public long garbageBytes() {
        return garbageBytes;
    }

    private void parse() {
        int p = rx.start();
        int end = rx.end();
        while (true) {
            while (p < end && (buf[p] & 0xFF) != Protocol.SYNC1) {
                p++;
                garbageBytes++;
            }
            if (end - p < Protocol.HEADER) {
                break;
            }
            if ((buf[p + 1] & 0xFF) != Protocol.SYNC2) {
                p++;
                garbageBytes++;
                continue;
            }
            int len = FrameHandler.u16(buf, p + 3);
            if (len > Protocol.MAX_PAYLOAD) {
                p++;
                garbageBytes++;
                continue;
            }
            int total = len + Protocol.OVERHEAD;
            if (end - p < total) {
                break;
            }
            int crc = Crc16.CCITT_FALSE.of(buf, p + 2, len + 4);
            int got = (buf[p + 6 + len] & 0xFF) << 8 | (buf[p + 7 + len] & 0xFF);
            if (crc != got) {
                checksumErrors++;
                p++;
                continue;
            }
            frames++;
            rx.consumeTo(p + total);
            handler.onFrame(buf[p + 2] & 0xFF, buf[p + 5] & 0xFF, buf, p + 6, len);
            p += total;
        }
        rx.settle(p);
    }
}
