package org.parpe.serial.bus;

import org.parpe.core.text.Msg;
import org.parpe.serial.text.SerialMsg;

/**
 * Settings of the host side of the bus.
 *
 * @param baud          line speed, bits per second (8N1: ten bits per byte)
 * @param readTimeoutMs how long to wait for a reply before retrying
 * @param retries       extra attempts after a timed-out request
 * @param watchdogMs    a module stops on its own after this long without a frame
 * @param safeMode      what a stopped module does
 * @param deadAfterMs   no reply at all for this long means the bus is dead
 * @param keepaliveMs   setpoints are repeated at least this often, to feed the watchdogs
 * @param reconnectMs   how often to look for the modules or the device after a fault
 * @param idleGapMs     silence after which a partial frame is abandoned
 */
public record BusConfig(int baud, int readTimeoutMs, int retries, int watchdogMs, SafeMode safeMode,
                        int deadAfterMs, int keepaliveMs, int reconnectMs, int idleGapMs) {

    /** The default line speed. */
    public static final int DEFAULT_BAUD = 115_200;

    public BusConfig {
        positive(SerialMsg.OPTION_BAUD, baud, 10_000_000);
        positive(SerialMsg.OPTION_READ_TIMEOUT, readTimeoutMs, 10_000);
        if (retries < 0 || retries > 20) {
            throw new IllegalArgumentException(Msg.MUST_BE_IN_RANGE.text(SerialMsg.OPTION_RETRIES.text(), 0, 20, retries));
        }
        positive(SerialMsg.OPTION_WATCHDOG, watchdogMs, 60_000);
        positive(SerialMsg.OPTION_DEAD_AFTER, deadAfterMs, 60_000);
        positive(SerialMsg.OPTION_KEEPALIVE, keepaliveMs, watchdogMs);
        positive(SerialMsg.OPTION_RECONNECT, reconnectMs, 60_000);
        positive(SerialMsg.OPTION_IDLE_GAP, idleGapMs, 10_000);
        if (safeMode == null) {
            throw new IllegalArgumentException(SerialMsg.SAFE_MODE_HOLD_OR_LIMP.text());
        }
    }

    /**
     * The defaults: 115 200 baud, 20 ms read timeout, 2 retries, 50 ms watchdog with hold,
     * dead after 50 ms of silence, keepalive 20 ms, reconnect every 100 ms, 5 ms idle gap.
     */
    public static BusConfig defaults() {
        return new BusConfig(DEFAULT_BAUD, 20, 2, 50, SafeMode.HOLD, 50, 20, 100, 5);
    }

    /** The same settings at another baud rate. */
    public BusConfig withBaud(int b) {
        return new BusConfig(b, readTimeoutMs, retries, watchdogMs, safeMode, deadAfterMs, keepaliveMs,
                reconnectMs, idleGapMs);
    }

    /** The same settings with another safe mode. */
    public BusConfig withSafeMode(SafeMode m) {
        return new BusConfig(baud, readTimeoutMs, retries, watchdogMs, m, deadAfterMs, keepaliveMs,
                reconnectMs, idleGapMs);
    }

    /** The same settings with another read timeout and retry count. */
    public BusConfig withReads(int timeoutMs, int r) {
        return new BusConfig(baud, timeoutMs, r, watchdogMs, safeMode, Math.max(deadAfterMs, timeoutMs),
                keepaliveMs, reconnectMs, idleGapMs);
    }

    private static void positive(SerialMsg what, int v, int max) {
        if (v <= 0 || v > max) {
            throw new IllegalArgumentException(Msg.MUST_BE_IN_RANGE.text(what.text(), 1, max, v));
        }
    }
}
