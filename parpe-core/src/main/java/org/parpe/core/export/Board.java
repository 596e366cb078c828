package org.parpe.core.export;

import java.util.Locale;

/**
 * A machine the exported C runs on, with what the memory estimate needs: RAM and flash for the
 * program, the size of a C {@code double} (32 bits on 8-bit AVR), of a {@code jmp_buf}, and the
 * RAM the board code itself takes (serial buffers, servo library, stack reserve).
 */
public enum Board {
    /** A PC: the trace program of the equality test; no limit. */
    HOST(Long.MAX_VALUE, Long.MAX_VALUE, 8, 200, 0, 0, 8, 8, 8, 0),
    /**
     * Arduino Uno (ATmega328P): 2 KB RAM, 32 KB flash less the 0.5 KB bootloader. Measured with
     * avr-gcc 5.4 and Debian 12's Arduino core 1.8.7 on simavr (SimulatedUnoTest): the sketch's
     * static RAM besides the scheduler's state (serial buffers, the command line, the core:
     * 270 bytes) and a stack reserve of 340 bytes (the deepest stack measured in the examples
     * was 301); flash: runtime, float library, core, serial and PWM code of the smallest
     * example (16.7 KB) with a margin (17 100 bytes).
     */
    UNO(2048, 32256, 4, 23, 610, 17100, 4, 2, 1, 16_000_000),
    /** Arduino Nano (ATmega328P), the Uno's chip with a larger bootloader. */
    NANO(2048, 30720, 4, 23, 610, 17100, 4, 2, 1, 16_000_000),
    /** ESP32 (320 KB of data RAM, a 1.25 MB application partition). */
    ESP32(327680, 1310720, 8, 68, 30000, 250000, 4, 4, 8, 0);

    private final long ram;
    private final long flash;
    private final int doubleBytes;
    private final int jmpBuf;
    private final int boardRam;
    private final int runtimeFlash;
    private final int longBytes;
    private final int pointerBytes;
    private final int maxAlign;
    private final long cyclesPerSecond;

    Board(long ram, long flash, int doubleBytes, int jmpBuf, int boardRam, int runtimeFlash, int longBytes,
          int pointerBytes, int maxAlign, long cyclesPerSecond) {
        this.cyclesPerSecond = cyclesPerSecond;
        this.ram = ram;
        this.flash = flash;
        this.doubleBytes = doubleBytes;
        this.jmpBuf = jmpBuf;
        this.boardRam = boardRam;
        this.runtimeFlash = runtimeFlash;
        this.longBytes = longBytes;
        this.pointerBytes = pointerBytes;
        this.maxAlign = maxAlign;
    }

    /**
     * The clock of a board whose tick time export estimates (the 16 MHz ATmega328P, which computes
     * in software floating point); 0 where it does not (a PC, an ESP32 with hardware floats).
     */
    public long cyclesPerSecond() {
        return cyclesPerSecond;
    }

    /** Bytes of a C {@code long}. */
    public int longBytes() {
        return longBytes;
    }

    /** Bytes of a pointer. */
    public int pointerBytes() {
        return pointerBytes;
    }

    /** The alignment of a type of {@code size} bytes (AVR aligns nothing). */
    public int align(int size) {
        return Math.min(size, maxAlign);
    }

    /** The board called {@code name} ({@code uno}, {@code nano}, {@code esp32}, {@code host}), or {@code null}. */
    public static Board of(String name) {
        for (Board b : values()) {
            if (b.word().equals(name)) {
                return b;
            }
        }
        return null;
    }

    /** The name used on the command line. */
    public String word() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** RAM in bytes. */
    public long ram() {
        return ram;
    }

    /** Flash for the program in bytes. */
    public long flash() {
        return flash;
    }

    /** Bytes of a C {@code double}. */
    public int doubleBytes() {
        return doubleBytes;
    }

    /** Bytes of a {@code jmp_buf}. */
    public int jmpBuf() {
        return jmpBuf;
    }

    /** RAM taken by the board code around the runtime (serial buffers, servo library, stack reserve). */
    public int boardRam() {
        return boardRam;
    }

    /** Flash taken by the runtime, the C library's maths and the board code. */
    public int runtimeFlash() {
        return runtimeFlash;
    }
}
