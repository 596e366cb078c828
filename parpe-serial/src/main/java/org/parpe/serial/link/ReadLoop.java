package org.parpe.serial.link;

import java.io.IOException;
import java.util.concurrent.locks.Lock;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;

/**
 * The loop of a host's reader thread, the same for every bus: reads what the link delivers
 * and feeds the decoder under {@code lock}, abandons a packet the line left unfinished for
 * longer than the idle gap, and stops at the first read failure, which it hands to
 * {@code failed} with the lock held.
 */
public final class ReadLoop {
    private ReadLoop() {
    }

    /** Runs until {@code running} turns false or a read fails. */
    public static void run(ByteLink link, BooleanSupplier running, Lock lock, StreamDecoder rx, long idleGapNanos,
                           int bufferSize, Consumer<IOException> failed) {
        byte[] in = new byte[bufferSize];
        long lastByte = System.nanoTime();
        while (running.getAsBoolean()) {
            int n;
            try {
                n = link.read(in);
            } catch (IOException e) {
                lock.lock();
                try {
                    failed.accept(e);
                } finally {
                    lock.unlock();
                }
                return;
            }
            long now = System.nanoTime();
            lock.lock();
            try {
                if (n > 0) {
                    lastByte = now;
                    rx.feed(in, 0, n);
                } else if (rx.pending() > 0 && now - lastByte > idleGapNanos) {
                    rx.idle();
                }
            } finally {
                lock.unlock();
            }
        }
    }
}
