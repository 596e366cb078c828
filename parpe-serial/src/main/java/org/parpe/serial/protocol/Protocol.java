package org.parpe.serial.protocol;

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

    /** Ping a module: it replies {@link #PONG}. Payload empty. */
    public static final int PING = 0x01;
    /** Broadcast setpoints: {@code seq:u16 first:u8 angle:i16…} for modules first, first+1, …. */
    public static final int SETPOINTS = 0x02;
    /** Ask a module for its sensors: it replies {@link #STATUS}. Payload empty. */
    public static final int READ = 0x03;
    /** Turn the servo off so the joint can be back-driven; disarms the watchdog. */
    public static final int LIMP = 0x04;
    /**
     * Hold with the servo on and disarm the watchdog: {@code mode:u8} optional, 0 (default) stops
     * at the current angle, 1 finishes the move to the last setpoint.
     */
    public static final int HOLD = 0x05;
    /** Emergency stop, latched until {@link #RESUME}: {@code mode:u8} (0 hold, 1 limp). */
    public static final int ESTOP = 0x06;
    /** Clear an emergency stop and a watchdog trip; setpoints are obeyed again. */
    public static final int RESUME = 0x07;
    /** Set {@code watchdogMs:u16 safeMode:u8 speedDegPerS:u16}. */
    public static final int CONFIG = 0x08;
    /** Bit set in the command of a reply. */
    public static final int REPLY = 0x80;
    /** Reply to PING: {@code version:u8 kind:u8 flags:u8 angle:i16}. */
    public static final int PONG = PING | REPLY;
    /** Reply to READ: {@code angle:i16 ax:i8 ay:i8 az:i8 touch:u8 flags:u8 rxErrors:u16}. */
    public static final int STATUS = READ | REPLY;
    /** Payload length of a PONG. */
    public static final int PONG_LEN = 5;
    /** Payload length of a STATUS. */
    public static final int STATUS_LEN = 9;

    /** Status flag: the servo is off. */
    public static final int FLAG_LIMP = 1;
    /** Status flag: an emergency stop is latched. */
    public static final int FLAG_ESTOP = 2;
    /** Status flag: the watchdog tripped (no frame for watchdogMs). */
    public static final int FLAG_WATCHDOG = 4;
    /** Touch bit of the +y side. */
    public static final int TOUCH_LEFT = 1;
    /** Touch bit of the −y side. */
    public static final int TOUCH_RIGHT = 2;
    /** Safe mode: hold the current angle. */
    public static final int SAFE_HOLD = 0;
    /** Safe mode: servo off. */
    public static final int SAFE_LIMP = 1;
    /** HOLD payload: stop at the current angle. */
    public static final int HOLD_HERE = 0;
    /** HOLD payload: finish the move to the last setpoint. */
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
        switch (cmd) {
            case PING: return "PING";
            case SETPOINTS: return "SETPOINTS";
            case READ: return "READ";
            case LIMP: return "LIMP";
            case HOLD: return "HOLD";
            case ESTOP: return "ESTOP";
            case RESUME: return "RESUME";
            case CONFIG: return "CONFIG";
            case PONG: return "PONG";
            case STATUS: return "STATUS";
            default: return String.format("0x%02X", cmd);
        }
    }
}
