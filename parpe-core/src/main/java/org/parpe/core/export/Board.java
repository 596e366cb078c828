package org.parpe.core.export;

import java.util.List;

/**
 * A machine the exported C runs on, with what the memory estimate needs.
 *
 * @param word            the name used on the command line
 * @param ram             RAM in bytes
 * @param flash           flash for the program in bytes
 * @param doubleBytes     bytes of a C {@code double} (32 bits on 8-bit AVR)
 * @param jmpBuf          bytes of a {@code jmp_buf}
 * @param boardRam        RAM taken by the board code around the runtime (serial buffers, servo
 *                        library, stack reserve)
 * @param runtimeFlash    flash taken by the runtime, the C library's maths and the board code
 * @param longBytes       bytes of a C {@code long}
 * @param pointerBytes    bytes of a pointer
 * @param maxAlign        the largest alignment the compiler uses (AVR aligns nothing: 1)
 * @param cyclesPerSecond the clock of a board whose tick time export estimates (the 16 MHz
 *                        ATmega328P, which computes in software floating point); 0 where it does
 *                        not (a PC, an ESP32 with hardware floats)
 */
public record Board(String word, long ram, long flash, int doubleBytes, int jmpBuf, int boardRam, int runtimeFlash,
                    int longBytes, int pointerBytes, int maxAlign, long cyclesPerSecond) {

    /** A PC: the trace program of the equality test; no limit. */
    public static final Board HOST = new Board("host", Long.MAX_VALUE, Long.MAX_VALUE, 8, 200, 0, 0, 8, 8, 8, 0);
    /**
     * Arduino Uno (ATmega328P): 2 KB RAM, 32 KB flash less the 0.5 KB bootloader. Measured with
     * avr-gcc 5.4 and Debian 12's Arduino core 1.8.7 on simavr (SimulatedUnoTest): the sketch's
     * static RAM besides the scheduler's state (serial buffers, the command line, the core:
     * 270 bytes) and a stack reserve of 340 bytes (the deepest stack measured in the examples
     * was 301); flash: runtime, float library, core, serial and PWM code of the smallest
     * example (17.6 KB since the runtime keeps time in integers, issue 21 item 7) with a margin
     * (17 900 bytes).
     */
    public static final Board UNO = new Board("uno", 2048, 32256, 4, 23, 610, 17980, 4, 2, 1, 16_000_000);
    /** Arduino Nano (ATmega328P), the Uno's chip with a larger bootloader. */
    public static final Board NANO = new Board("nano", 2048, 30720, 4, 23, 610, 17980, 4, 2, 1, 16_000_000);
    /** ESP32 (320 KB of data RAM, a 1.25 MB application partition). */
    public static final Board ESP32 = new Board("esp32", 327680, 1310720, 8, 68, 30000, 250000, 4, 4, 8, 0);

    private static final List<Board> ALL = List.of(HOST, UNO, NANO, ESP32);

    /** The alignment of a type of {@code size} bytes (AVR aligns nothing). */
    public int align(int size) {
        return Math.min(size, maxAlign);
    }

    /** The board called {@code name} ({@code uno}, {@code nano}, {@code esp32}, {@code host}), or {@code null}. */
    public static Board of(String name) {
        for (Board b : ALL) {
            if (b.word.equals(name)) {
                return b;
            }
        }
        return null;
    }
}
