package org.parpe.serial.g1;

/**
 * The command byte of a frame (see {@link Protocol} and docs/hardware-protocol.md): what the
 * master asks and what a module replies. A reply's code is its request's with {@link #REPLY_BIT}
 * set and has a fixed payload length.
 */
public enum Command {
    /** Ping a module: it replies {@link #PONG}. Payload empty. */
    PING(0x01, -1),
    /** Broadcast setpoints: {@code seq:u16 first:u8 angle:i16…} for modules first, first+1, …. */
    SETPOINTS(0x02, -1),
    /** Ask a module for its sensors: it replies {@link #STATUS}. Payload empty. */
    READ(0x03, -1),
    /** Turn the servo off so the joint can be back-driven; disarms the watchdog. */
    LIMP(0x04, -1),
    /**
     * Hold with the servo on and disarm the watchdog: {@code mode:u8} optional, 0 (default) stops
     * at the current angle, 1 finishes the move to the last setpoint.
     */
    HOLD(0x05, -1),
    /** Emergency stop, latched until {@link #RESUME}: {@code mode:u8} (0 hold, 1 limp). */
    ESTOP(0x06, -1),
    /** Clear an emergency stop and a watchdog trip; setpoints are obeyed again. */
    RESUME(0x07, -1),
    /** Set {@code watchdogMs:u16 safeMode:u8 speedDegPerS:u16}. */
    CONFIG(0x08, -1),
    /** Reply to PING: {@code version:u8 kind:u8 flags:u8 angle:i16}. */
    PONG(0x01 | Command.REPLY_BIT, 5),
    /** Reply to READ: {@code angle:i16 ax:i8 ay:i8 az:i8 touch:u8 flags:u8 rxErrors:u16}. */
    STATUS(0x03 | Command.REPLY_BIT, 9);

    /** Bit set in the command of a reply. */
    public static final int REPLY_BIT = 0x80;

    private static final Command[] BY_CODE = new Command[256];

    static {
        for (Command c : values()) {
            BY_CODE[c.code] = c;
        }
    }

    private final int code;
    private final int replyLength;

    Command(int code, int replyLength) {
        this.code = code;
        this.replyLength = replyLength;
    }

    /** The byte on the wire. */
    public int code() {
        return code;
    }

    /** The command of wire byte {@code code}, or {@code null} for one the protocol does not have. */
    public static Command of(int code) {
        return code >= 0 && code < BY_CODE.length ? BY_CODE[code] : null;
    }

    /** Whether {@code cmd} is this command. */
    public boolean is(int cmd) {
        return cmd == code;
    }

    /** Whether a frame of command {@code cmd} with {@code len} payload bytes is this reply. */
    public boolean isReply(int cmd, int len) {
        return cmd == code && replyLength >= 0 && len == replyLength;
    }

    /** Whether wire byte {@code cmd} is the command of a reply. */
    public static boolean replies(int cmd) {
        return (cmd & REPLY_BIT) != 0;
    }
}
