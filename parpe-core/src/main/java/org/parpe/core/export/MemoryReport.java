package org.parpe.core.export;

import java.util.ArrayList;
import java.util.List;

/**
 * The RAM and flash an exported program needs on a {@link Board}: the runtime state
 * ({@code parsl_rt}: per module, per instance, per sensor reading) in RAM, the tables and the
 * compiled expressions in flash. An estimate from the sizes of the C types, not a linker map.
 *
 * @param board      the board
 * @param stateBytes RAM of the runtime state
 * @param ramBytes   RAM with the board code's share
 * @param flashBytes flash: runtime, expressions and tables
 */
public record MemoryReport(Board board, long stateBytes, long ramBytes, long flashBytes) {

    /** Estimates {@code p} on {@code board}; {@code codeLines} is the number of generated expression statements. */
    public static MemoryReport of(CProgram p, Board board, long codeLines) {
        int d = board.doubleBytes();
        long context = 4L * d + 7 * 2 + 8;
        long inputs = (long) d * (p.controls() == 0 ? 1 : p.controls()) + (long) d * p.macros() + 2L * d * Math.max(1, p.sensorReadings());
        long modules = (2L * d + 1) * p.modules();
        long scheduler = 3L * 4 + 2 + 1 + 2;
        long instances = (3L * d + 5) * p.instances();
        long pool = (8L * d + 3) * p.moduleStates() + (long) d * p.durations();
        long error = board.jmpBuf() + 6 + 2L * d;
        long state = context + inputs + modules + scheduler + instances + pool + error;
        long flash = board.runtimeFlash() + p.tableBytes(d) + 14 * codeLines;
        return new MemoryReport(board, state, state + board.boardRam(), flash);
    }

    /** Whether the program fits the board. */
    public boolean fits() {
        return ramBytes <= board.ram() && flashBytes <= board.flash();
    }

    /** What does not fit, one message per memory; empty if it fits. */
    public List<String> problems() {
        List<String> out = new ArrayList<>();
        if (ramBytes > board.ram()) {
            out.add("the program needs about " + ramBytes + " bytes of RAM on " + board.word() + " (" + stateBytes
                    + " for the scheduler's state, " + board.boardRam() + " for the board code), but it has "
                    + board.ram() + "; use fewer modules or instances per <main> entry, or a board with more RAM (esp32)");
        }
        if (flashBytes > board.flash()) {
            out.add("the program needs about " + flashBytes + " bytes of flash on " + board.word() + ", but it has "
                    + board.flash());
        }
        return out;
    }

    /** The report printed by {@code parpe export}. */
    public String format() {
        if (board == Board.HOST) {
            return "memory (host): " + stateBytes + " bytes of state, " + flashBytes + " bytes of code and tables (estimate)";
        }
        return "memory (" + board.word() + ", estimate): RAM " + ramBytes + " of " + board.ram() + " bytes (state "
                + stateBytes + ", board code " + board.boardRam() + "), flash " + flashBytes + " of " + board.flash()
                + " bytes";
    }
}
