package org.parpe.core.export;

import java.util.ArrayList;
import java.util.List;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;

/**
 * The RAM and flash an exported program needs on a {@link Board}: the runtime state
 * ({@code parsl_rt}: per module, per instance, per sensor reading) in RAM, the tables and the
 * compiled expressions in flash. An estimate from the sizes of the C types, not a linker map.
 *
 * @param board      the board
 * @param stateBytes RAM of the runtime state
 * @param boardBytes RAM of the board code around it (the board's own share plus the driver's buffers)
 * @param ramBytes   RAM in all, with the values kept per module where they are (64-bit doubles; {@link ModuleConstants})
 * @param flashBytes flash: runtime, expressions and tables
 */
public record MemoryReport(Board board, long stateBytes, long boardBytes, long ramBytes, long flashBytes) {
    /** Flash of four generated expression statements (see {@link #of}). */
    static final int FLASH_PER_4_STATEMENTS = 8;
    /** Flash of one control's code (see {@link #of}). */
    static final int FLASH_PER_CONTROL = 150;

    /**
     * Estimates {@code p} on {@code board}; {@code codeLines} is the number of generated expression
     * statements, {@code driver} what the board code's servo driver adds. Each generated statement
     * is taken as 2 bytes of AVR code and each control as
     * {@value #FLASH_PER_CONTROL} (its name compared, its value parsed): fitted to what avr-gcc -Os
     * with LTO made of the examples and of gait tables of 8–160 rows (SimulatedUnoTest), whose
     * constant expressions it folds into their callers.
     */
    public static MemoryReport of(CProgram p, Board board, long codeLines, DriverCost driver) {
        long state = stateBytes(p, board);
        long flash = board.runtimeFlash() + p.tableBytes(board.doubleBytes()) + (FLASH_PER_4_STATEMENTS * codeLines + 3) / 4
                + FLASH_PER_CONTROL * p.controls() + driver.flash();
        long boardRam = board.boardRam() + driver.ram();
        // kept values (a double and a flag each) are not compiled for AVR boards (32-bit double)
        long kept = board.doubleBytes() == 8 ? 9 * p.keptValues() : 0;
        return new MemoryReport(board, state, boardRam, state + boardRam + kept, flash);
    }

    /** {@code sizeof(parsl_rt)}: the fields of {@code parsl_rt.h} in order, laid out as a C compiler does. */
    static long stateBytes(CProgram p, Board b) {
        int d = b.doubleBytes();
        Layout l = new Layout(b);
        l.add(d, 4).add(2, 6);
        l.add(d, Math.max(1, p.controls())).add(d, p.macros()).add(d, 2L * Math.max(1, p.sensorReadings()));
        l.add(8, 1).add(d, 2L * p.modules()).add(1, p.modules()).add(2, p.modules());
        if (d == 4) {
            // 32-bit double: tick, the clock and the entry's start (two uint32_t each, parsl_rt.h), main_cycle
            l.add(b.longBytes(), 1).add(4, 4).add(b.longBytes(), 1);
        } else {
            l.add(b.longBytes(), 3);
        }
        l.add(2, 1).add(1, 1).add(b.pointerBytes(), 2);
        Layout inst = new Layout(b);
        inst.add(d, 3).add(2, 1).add(1, 3);
        l.add(inst.size(), b.align(d), p.instances());
        // per module: p p0 a0 u uk ph cyc out (with a 32-bit double: u pc for u uk, cyc an int32_t)
        l.add(2, p.moduleStates()).add(1, p.moduleStates()).add(d, 8L * p.moduleStates()).add(d, p.durations());
        l.add(b.jmpBuf(), b.align(8), 1).add(2, 3).add(d, 2);
        return l.size();
    }

    /** Lays out C struct fields: each aligned to its type, the whole padded to the largest alignment. */
    private static final class Layout {
        private final Board board;
        private long offset;
        private int maxAlign = 1;

        Layout(Board board) {
            this.board = board;
        }

        /** {@code count} fields (or one array) of a scalar type of {@code size} bytes. */
        Layout add(int size, long count) {
            return add(size, board.align(size), count);
        }

        Layout add(long size, int align, long count) {
            offset = (offset + align - 1) / align * align + size * count;
            maxAlign = Math.max(maxAlign, align);
            return this;
        }

        long size() {
            return (offset + maxAlign - 1) / maxAlign * maxAlign;
        }
    }

    /** Whether the program fits the board. */
    public boolean fits() {
        return ramBytes <= board.ram() && flashBytes <= board.flash();
    }

    /** What does not fit, one message per memory; empty if it fits. */
    public List<Message> problems() {
        List<Message> out = new ArrayList<>();
        if (ramBytes > board.ram()) {
            out.add(Message.of(Msg.TOO_LITTLE_RAM, ramBytes, board.word(), stateBytes, boardBytes, board.ram()));
        }
        if (flashBytes > board.flash()) {
            out.add(Message.of(Msg.TOO_LITTLE_FLASH, flashBytes, board.word(), board.flash()));
        }
        return out;
    }

    /** The report printed by {@code parpe export}. */
    public String format() {
        if (board == Board.HOST) {
            return Msg.MEMORY_HOST.text(stateBytes, flashBytes);
        }
        long kept = ramBytes - stateBytes - boardBytes;
        return kept > 0
                ? Msg.MEMORY_BOARD_KEPT.text(board.word(), ramBytes, board.ram(), stateBytes, boardBytes, flashBytes, board.flash(), kept)
                : Msg.MEMORY_BOARD.text(board.word(), ramBytes, board.ram(), stateBytes, boardBytes, flashBytes, board.flash());
    }
}
