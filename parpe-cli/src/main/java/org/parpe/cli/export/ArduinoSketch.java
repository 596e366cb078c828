package org.parpe.cli.export;

import java.nio.file.Path;
import java.util.Locale;
import org.parpe.cli.options.UsageException;
import org.parpe.core.export.CRuntime;
import org.parpe.core.export.CText;
import org.parpe.core.model.Program;

/**
 * The {@code .ino} of an exported sketch: runs the scheduler at the fixed tick from
 * {@code micros()}, sends the setpoints to the servos, and reads control and sensor assignments
 * ({@code speed=1.5}, {@code direction=backward}, {@code $3_touch_left=1}) as lines on the USB
 * serial console. The servo code is {@code sketch.inc} (a resource), driven by {@code parsl_servo.h}.
 */
final class ArduinoSketch {
    private ArduinoSketch() {
    }

    /** The sketch name: the script's file name as a C identifier (Arduino wants NAME/NAME.ino). */
    static String sketchName(Path script) {
        String n = script.getFileName().toString();
        int dot = n.lastIndexOf('.');
        n = (dot > 0 ? n.substring(0, dot) : n).replaceAll("[^A-Za-z0-9_]", "_");
        return Character.isDigit(n.charAt(0)) ? "parsl_" + n : n;
    }

    /**
     * The tick in whole microseconds, as the sketch counts it with {@code micros()}; a tick that is
     * not a whole number of microseconds would make the board's clock run fast or slow against the
     * script's {@code $time}, so it is refused.
     */
    static long tickMicros(double tick) throws UsageException {
        double us = tick * 1e6;
        long whole = Math.round(us);
        if (Math.abs(us - whole) > 1e-9 * us) {
            throw new UsageException("--tick for an Arduino sketch must be a whole number of microseconds (the board"
                    + " counts time with micros()), got " + tick + " s = " + us + " us; use " + whole / 1e6 + " s");
        }
        return whole;
    }

    static String ino(Program p, SketchOptions s, double tick) throws UsageException {
        StringBuilder b = new StringBuilder(ExportFiles.MARK).append(" from ")
                .append(CText.comment(Path.of(p.file()).getFileName().toString())).append(" (")
                .append(s.driver().name().toLowerCase(Locale.ROOT)).append(" servos, tick ").append(tick).append(" s).\n");
        b.append("// Board code may be added below the generated part; parpe export then refuses to overwrite this file.\n");
        b.append("#include <Arduino.h>\n#include \"parsl_servo.h\"\n");
        b.append("#define PARSL_TICK_US ").append(tickMicros(tick)).append("UL\n");
        if (s.driver() == SketchOptions.Driver.PWM) {
            b.append("static const uint8_t PARSL_PINS[] = {");
            int n = p.moduleIds().length;
            for (int i = 0; i < n; i++) {
                b.append(i == 0 ? "" : ", ").append(s.pins().isEmpty() ? 2 + i : s.pins().get(i));
            }
            b.append("};\n");
        }
        b.append(CRuntime.read(CRuntime.SKETCH));
        return b.toString();
    }
}
