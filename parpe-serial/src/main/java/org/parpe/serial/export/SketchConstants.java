package org.parpe.serial.export;

import org.parpe.serial.servo.ServoModel;

/**
 * The numbers a sketch's board code ({@code sketch.inc}) and the export's cost model share,
 * declared once: {@code parsl_servo.h} gets them from here ({@link #appendC}) and
 * {@code sketch.inc} declares none of them (SketchConstantsTest), as {@code parsl_program.h}
 * gets the tables' layout from core's {@code CLayout}. Before, {@code sketch.inc} and
 * {@link SketchOptions#cost} each wrote 64, 128, 100 µs and the packet's size, kept in step by hand.
 */
final class SketchConstants {
    /** The bus packet's alarm (Timer1's compare interrupt) fires this many microseconds before its tick. */
    static final int BUS_WINDOW_US = 100;
    /** Bytes of the bus console's input ring (a power of two: its index wraps by a mask). */
    static final int CONSOLE_IN_RING = 64;
    /** Bytes of the bus console's output ring (a power of two). */
    static final int CONSOLE_OUT_RING = 128;
    /** The console's RAM besides its rings: the receiver's state and the packet's alarm (measured, 9 bytes). */
    static final int CONSOLE_STATE_RAM = 9;
    /** Bytes of a bus packet besides its servos' entries: header, instruction, address, CRC, byte stuffing. */
    static final int PACKET_HEADER = 16;
    /** The AVR boards' clock: 16 MHz. */
    static final int AVR_CYCLES_PER_US = 16;

    private SketchConstants() {
    }

    /** RAM of a bus sketch's own console: its two rings and its state (201 bytes). */
    static int busConsoleRam() {
        return CONSOLE_IN_RING + CONSOLE_OUT_RING + CONSOLE_STATE_RAM;
    }

    /** Cycles of the packet's early alarm on a 16 MHz AVR (1 600). */
    static int busAlarmCycles() {
        return BUS_WINDOW_US * AVR_CYCLES_PER_US;
    }

    /** Bytes of a servo's entry in a packet: ID and goal, twice for room to stuff bytes. */
    static int packetPerServo(ServoModel m) {
        return 2 * (1 + m.registers().goalSize());
    }

    /** Bytes of the packet buffer for {@code modules} servos of model {@code m}. */
    static long packetBytes(ServoModel m, int modules) {
        return PACKET_HEADER + (long) modules * packetPerServo(m);
    }

    /** The constants as C macros, for {@code parsl_servo.h}; {@code m} is the bus's model. */
    static void appendC(StringBuilder h, ServoModel m) {
        h.append("\n/* Shared with the export's cost model (org.parpe.serial.export.SketchConstants). */\n");
        h.append("#define PARSL_BUS_WINDOW_US ").append(BUS_WINDOW_US).append("u\n");
        h.append("#define PARSL_CONSOLE_IN_RING ").append(CONSOLE_IN_RING).append('\n');
        h.append("#define PARSL_CONSOLE_OUT_RING ").append(CONSOLE_OUT_RING).append('\n');
        h.append("#define PARSL_PACKET_HEADER ").append(PACKET_HEADER).append('\n');
        h.append("#define PARSL_PACKET_PER_SERVO ").append(packetPerServo(m)).append('\n');
    }
}
