package org.parpe.serial.g1;

/**
 * Constants of the bus protocol: a reconstruction in the spirit of PolyBot G1 (one hobby servo
 * and one PIC per module on a shared serial bus). A frame is
 * {@code A5 5A ADDR LEN_LO LEN_HI CMD PAYLOAD… CRC_HI CRC_LO}; the CRC-16/CCITT-FALSE covers
 * ADDR through the last payload byte. See docs/hardware-protocol.md.
 */
public final class Protocol {
    /** First sync byte. */
    public static final int SYNC1 = 0xA5;
    /** Second sync byte. */
    public static final int SYNC2 = 0x5A;
    /** Address every module listens to; modules never reply to it. */
    public static final int BROADCAST = 0xFF;
    /** Highest module address. */
    public static final int MAX_MODULE_ID = 0xFE;
    /** Bytes before the payload: two sync bytes, address, two length bytes, command. */
    public static final int HEADER = 6;
    /** Bytes of a frame besides its payload (header and CRC). */
    public static final int OVERHEAD = HEADER + 2;
    /** Largest payload a decoder accepts (a setpoint frame for 255 modules fits). */
    public static final int MAX_PAYLOAD = 3 + 2 * 256;
    /** Largest frame. */
    public static final int MAX_FRAME = MAX_PAYLOAD + OVERHEAD;
    /** Protocol version reported in a PONG. */
    public static final int VERSION = 1;
    /** Module kind reported in a PONG: a G1-style one-degree-of-freedom segment. */
    public static final int KIND_SEGMENT = 1;

    /** The bits of the flags byte of a PONG and a STATUS; a flag's bit is {@code 1 << ordinal()}. */
    public enum Flag {
        /** The servo is off. */
        LIMP,
        /** An emergency stop is latched. */
        ESTOP,
        /** The watchdog tripped (no frame for watchdogMs). */
        WATCHDOG;

        /** Its bit in the flags byte. */
        public int bit() {
            return 1 << ordinal();
        }
    }

    /** The bits of the touch byte of a STATUS; a side's bit is {@code 1 << ordinal()}. */
    public enum Touch {
        /** The +y side. */
        LEFT,
        /** The −y side. */
        RIGHT;

        /** Its bit in the touch byte. */
        public int bit() {
            return 1 << ordinal();
        }
    }

    /** HOLD's payload byte: finish the move to the last setpoint (0, the default, stops at the current angle). */
    public static final int HOLD_TARGET = 1;

    /** The joint range, degrees either side of zero; no frame ever carries more. */
    public static final double JOINT_LIMIT_DEG = 90.0;
    /** Wire value of a setpoint slot that leaves the module as it is. */
    public static final short NO_CHANGE = Short.MIN_VALUE;
    /** Wire angle unit: hundredths of a degree. */
    public static final double WIRE_UNITS_PER_DEG = 100.0;

    private Protocol() {
    }

    /** Frame length of a payload of {@code payload} bytes. */
    public static int frameLength(int payload) {
        return payload + OVERHEAD;
    }

    /** Bytes of the setpoint frame covering {@code span} consecutive module IDs. */
    public static int setpointFrameLength(int span) {
        return frameLength(3 + 2 * span);
    }

    /**
     * The wire value of an angle already inside the joint range: hundredths of a degree,
     * rounded half away from zero.
     */
    public static short toWire(double degrees) {
        long w = Math.round(Math.abs(degrees) * WIRE_UNITS_PER_DEG);
        return (short) (degrees < 0 ? -w : w);
    }

    /** Degrees of a wire angle. */
    public static double fromWire(int wire) {
        return wire / WIRE_UNITS_PER_DEG;
    }

    /** Whether a wire angle is inside the joint range. */
    public static boolean wireInRange(int wire) {
        return Math.abs(wire) <= (int) (JOINT_LIMIT_DEG * WIRE_UNITS_PER_DEG);
    }

    /** A readable name of a command code, for messages. */
    public static String commandName(int cmd) {
        Command c = Command.of(cmd);
        return c != null ? c.name() : String.format("0x%02X", cmd);
    }
}
