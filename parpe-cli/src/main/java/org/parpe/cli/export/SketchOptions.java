package org.parpe.cli.export;

import java.util.List;
import org.parpe.cli.options.UsageException;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.export.DriverCost;
import org.parpe.core.model.Program;
import org.parpe.core.model.SensorDecl;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;

/**
 * How an Arduino sketch drives the modules: hobby PWM servos on pins, or Dynamixel 2.0 / Feetech
 * STS servos on a UART with the module ID as servo ID.
 *
 * @param driver the driver
 * @param pins   PWM pins in ascending module ID order (empty: 2, 3, 4, …)
 * @param baud   bus baud rate
 * @param model  the servo model of a bus (its units and control table), {@code null} for PWM
 * @param consoleSensors whether {@code accel} and {@code touch} readings may come from console commands
 */
record SketchOptions(Driver driver, List<Integer> pins, int baud, ServoModel model, boolean consoleSensors) {
    /**
     * The most PWM servos a sketch drives: on an AVR its Timer1 pulses them one after another, and 12
     * pulses of up to 2.5 ms stretch the 20 ms frame to 30 ms, as the Arduino Servo library allows.
     */
    static final int MAX_PWM = 12;

    /** The servo drivers of a sketch. */
    enum Driver { PWM, DXL, STS }

    static SketchOptions of(String servo, List<Integer> pins, int baud, String modelName, boolean consoleSensors)
            throws UsageException {
        Driver d = switch (servo) {
            case "pwm" -> Driver.PWM;
            case "dxl" -> Driver.DXL;
            case "sts" -> Driver.STS;
            default -> throw new UsageException("--servo must be pwm, dxl or sts, got '" + servo + "'");
        };
        if (d != Driver.PWM && !pins.isEmpty()) {
            throw new UsageException("--pins is for --servo pwm; a " + servo + " bus addresses servos by ID");
        }
        for (int p : pins) {
            if (p < 0 || p > 99) {
                throw new UsageException("--pins must be pin numbers 0..99, got " + p);
            }
        }
        if (!(baud >= 9600 && baud <= 4_500_000)) {
            throw new UsageException("--baud must be within [9600, 4500000], got " + baud);
        }
        if (d == Driver.PWM) {
            if (modelName != null) {
                throw new UsageException("--model is for --servo dxl or sts");
            }
            return new SketchOptions(d, List.copyOf(pins), baud, null, consoleSensors);
        }
        ServoProtocol protocol = d == Driver.DXL ? ServoProtocol.DXL2 : ServoProtocol.STS;
        ServoModel m = modelName == null ? ServoModel.defaultFor(protocol) : ServoModel.named(modelName);
        if (m == null || m.protocol() != protocol) {
            throw new UsageException("--model '" + modelName + "' is not a " + servo + " servo; known: "
                    + ServoModel.names(protocol));
        }
        return new SketchOptions(d, List.of(), baud, m, consoleSensors);
    }

    /**
     * What the sketch's servo driver adds for {@code modules} modules on an AVR board, measured
     * with avr-gcc 5.4 and Debian 12's Arduino core (SimulatedUnoTest prints the figures). RAM: per
     * PWM servo its pulse width, port and pin mask (5 bytes); on a bus the packet buffer
     * ({@code sketch.inc}: 16 + 2 × (ID + goal) per module, room for byte stuffing) and the
     * sketch's own console ({@value #BUS_CONSOLE_RAM} bytes: its 64-byte input and 128-byte output
     * rings, the receiver, the packet's alarm; docs/decisions.md). Flash: the bus code (CRC or
     * checksum, packets, the console) over the PWM timer code. Time: a pulse width per PWM servo
     * (about 600 cycles); on a bus a packet entry sent (3 000) and the packet's alarm, set
     * {@value #BUS_ALARM_CYCLES} cycles (100 µs) before the packet is due.
     */
    DriverCost cost(int modules) {
        if (driver == Driver.PWM) {
            return new DriverCost(5L * modules, 0, 600L * modules);
        }
        return new DriverCost(16 + 2L * modules * (1 + model.registers().goalSize()) + BUS_CONSOLE_RAM,
                driver == Driver.DXL ? 1540 : 1400, 3000L * modules + BUS_ALARM_CYCLES);
    }

    /** RAM of a bus sketch's console (sketch.inc, QUIET_CONSOLE), measured as above. */
    static final int BUS_CONSOLE_RAM = 201;
    /** The packet's alarm fires 100 µs (BUS_WINDOW_US in sketch.inc) early: 1 600 cycles at 16 MHz. */
    static final int BUS_ALARM_CYCLES = 1600;

    /**
     * Reports what the sketch cannot do: sensors it has no driver for (at their declaration),
     * more PWM servos than it can drive, module IDs that are no servo IDs (at the robot).
     */
    void check(Program p, DiagnosticSink diags) {
        for (SensorDecl s : p.robot().sensors()) {
            if (!s.type().equals("angle") && !consoleSensors) {
                diags.error(s.pos(), "an Arduino sketch cannot read '" + s.type() + "' sensors (it drives servos only);"
                        + " export with --console-sensors to take their readings from console commands such as '$"
                        + s.modules().get(0) + "_" + (s.type().equals("touch") ? "touch_left" : "accel_z")
                        + "=1', or with --target c and read them in your board code (parsl_set_reading)");
            }
        }
        int[] ids = p.moduleIds();
        if (driver == Driver.PWM) {
            if (!pins.isEmpty() && pins.size() != ids.length) {
                diags.error(p.robot().pos(), "--pins names " + pins.size() + " pins but the robot has " + ids.length
                        + " modules; give one pin per module, in ascending ID order");
            } else if (pins.isEmpty() && ids.length > MAX_PWM) {
                diags.error(p.robot().pos(), "the robot has " + ids.length + " modules but an Arduino drives at most "
                        + MAX_PWM + " PWM servos; use --servo dxl or sts (a bus of up to 253 servos)");
            }
            return;
        }
        int max = driver == Driver.DXL ? 252 : 253;
        for (int id : ids) {
            if (id > max) {
                diags.error(p.robot().pos(), "module " + id + " cannot be a " + model.name() + " servo ID (0.." + max
                        + "); the sketch uses module IDs as servo IDs");
                return;
            }
        }
    }
}
