package org.parpe.core.export;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Stream;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.Expression;
import org.parpe.core.model.Control;
import org.parpe.core.model.Program;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;

/**
 * Exports a loaded program as C for the embedded runtime: checks what the target cannot do,
 * generates {@code parsl_program.h} and {@code parsl_program.c}, and estimates the memory.
 * Problems go to the sink as located errors; nothing is generated then.
 */
public final class CExport {
    /** The tables hold {@code int16_t}. */
    static final int TABLE_LIMIT = Short.MAX_VALUE;

    private CExport() {
    }

    /**
     * The generated files and their memory estimate.
     *
     * @param files  file name to content
     * @param memory the estimate for the board
     */
    public record Result(Map<String, String> files, MemoryReport memory) {
    }

    /** Exports {@code program} run with tick {@code dt} for {@code board}; {@code null} after reporting errors. */
    public static Result export(Program program, double dt, Board board, DiagnosticSink diags) {
        return export(program, dt, board, DriverCost.NONE, diags);
    }

    /**
     * Exports {@code program} for {@code board} whose board code's servo driver costs {@code driver};
     * {@code null} after reporting errors.
     */
    public static Result export(Program program, double dt, Board board, DriverCost driver, DiagnosticSink diags) {
        SourcePos root = new SourcePos(program.file(), 1, 1);
        if (program.main() == null) {
            diags.error(root, Msg.EXPORT_NEEDS_MAIN);
            return null;
        }
        if (!(dt > 0) || !Double.isFinite(dt)) {
            diags.error(root, Msg.TICK_NOT_POSITIVE, dt);
            return null;
        }
        for (Control k : program.controls()) {
            for (String name : Stream.concat(Stream.of(k.name()), k.words().stream()).toList()) {
                if (name.length() > CText.MAX_LITERAL) {
                    diags.error(k.pos(), Msg.NAME_TOO_LONG_FOR_C, name.substring(0, 20), name.length(), CText.MAX_LITERAL);
                    return null;
                }
            }
        }
        if (refusePlateActions(program, diags)) {
            return null;
        }
        CProgram c = CProgram.of(program, dt);
        if (c.largestTableValue() > TABLE_LIMIT || c.modules() > TABLE_LIMIT / 6) {
            diags.error(program.robot().pos(), Msg.TABLES_TOO_LARGE, TABLE_LIMIT / 6, TABLE_LIMIT);
            return null;
        }
        Map<String, String> files = new LinkedHashMap<>();
        files.put("parsl_program.h", c.header());
        String source = c.source();
        files.put("parsl_program.c", source);
        MemoryReport m = MemoryReport.of(c, board, statements(source), driver);
        for (Message problem : m.problems()) {
            diags.report(new org.parpe.core.diag.Diagnostic(org.parpe.core.diag.Severity.ERROR, program.robot().pos(), problem));
        }
        if (board.cyclesPerSecond() > 0) {
            double seconds = tickCycles(c, driver) / (double) board.cyclesPerSecond();
            if (seconds > dt) {
                diags.warning(program.robot().pos(), Msg.TICK_TOO_SLOW, String.format(Locale.ROOT, "%.1f", seconds * 1e3),
                        board.word(), String.format(Locale.ROOT, "%.1f", dt * 1e3),
                        BigDecimal.valueOf(seconds * 1.2).round(new MathContext(2, RoundingMode.UP)).toPlainString());
            }
        }
        if (board.doubleBytes() == 4) {
            warnOfClockWaves(c, board, diags);
        }
        return m.fits() ? new Result(files, m) : null;
    }

    /**
     * Reports each state of the program's automata that arms or releases connection plates
     * (PARSL.md §14): an exported program drives joints only and has no latches to work, and a
     * plate action is never to be dropped silently. True if there was one.
     */
    private static boolean refusePlateActions(Program program, DiagnosticSink diags) {
        java.util.Set<String> seen = new java.util.HashSet<>();
        for (org.parpe.core.model.Automaton a : program.automata()) {
            for (org.parpe.core.model.StateDef s : a.states()) {
                if (s.hasPlateActions() && seen.add(s.name())) {
                    diags.error(s.pos(), s.latch().isEmpty() ? Msg.EXPORT_RELEASES_PLATES : Msg.EXPORT_ARMS_PLATES, s.name());
                }
            }
        }
        return !seen.isEmpty();
    }

    /**
     * On a board with 32-bit floats, warns at each expression that is a periodic function of
     * $time or $btime: the float holding the clock has steps of 0.24 ms after an hour, 7.8 ms
     * after a day and 62.5 ms after a week, and such a wave's phase is off by up to a step's share
     * of its period, more where its argument (2*pi*$time) rounds again (docs/embedded.md has the
     * measured figures).
     */
    private static void warnOfClockWaves(CProgram c, Board board, DiagnosticSink diags) {
        for (Expression e : c.expressions()) {
            if (ClockWaves.periodicOfClock(e)) {
                diags.warning(e.pos(), Msg.FLOAT_CLOCK_WAVE, board.word());
            }
        }
    }

    /**
     * The memory estimate of {@code program} on {@code board}, whether or not it fits (for
     * reports and benchmarks); {@code program} must have a {@code <main>}.
     */
    public static MemoryReport estimate(Program program, double dt, Board board) {
        CProgram c = CProgram.of(program, dt);
        return MemoryReport.of(c, board, statements(c.source()), DriverCost.NONE);
    }

    /**
     * Cycles an AVR board takes for one tick of {@code c}: about 9 500 per module (advancing its
     * automaton and evaluating its state's angle in 32-bit software floating point), 4 000 for
     * the scheduler, plus the driver's. Measured by SimulatedUnoTest on simavr (the cycles the CPU
     * is awake per tick: 30 000–120 000 for the examples); an estimate for a warning, not a bound.
     */
    static long tickCycles(CProgram c, DriverCost driver) {
        return 4000 + 9500L * c.modules() + driver.cycles();
    }

    /**
     * Generated statements (indented lines), the measure of expression code for the flash
     * estimate; the lines that keep values per module and the common case of a tick ({@link
     * CFastForm}) are not compiled on AVR and not counted.
     */
    private static long statements(String source) {
        long n = 0;
        boolean keep = false;
        for (String l : source.lines().toList()) {
            if (l.equals("#ifdef PARSL_KEEP") || l.equals(CFastForm.GUARD)) {
                keep = true;
            } else if (keep && l.equals("#endif")) {
                keep = false;
            } else if (!keep && l.startsWith("    ")) {
                n++;
            }
        }
        return n;
    }
}
