package org.parpe.serial.export;

import org.parpe.core.text.Msg;
import java.util.List;
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
public record SketchOptions(Driver driver, List<Integer> pins, int baud, ServoModel model, boolean consoleSensors) {
    /**
     * The most PWM servos a sketch drives: on an AVR its Timer1 pulses them one after another, and 12
     * pulses of up to 2.5 ms stretch the 20 ms frame to 30 ms, as the Arduino Servo library allows.
     */
    public static final int MAX_PWM = 12;

    /** The servo drivers of a sketch. */
    public enum Driver { PWM, DXL, STS }

    /**
     * The options as {@code parpe export} and the IDE's export window take them ({@code servo}: pwm,
     * dxl or sts; {@code modelName} null for the protocol's default).
     *
     * @throws IllegalArgumentException naming the option and the value it refuses
     */
    public static SketchOptions of(String servo, List<Integer> pins, int baud, String modelName, boolean consoleSensors) {
        Driver d = switch (servo) {
            case "pwm" -> Driver.PWM;
            case "dxl" -> Driver.DXL;
            case "sts" -> Driver.STS;
            default -> throw new IllegalArgumentException(Msg.BAD_SERVO.text(servo));
        };
        if (d != Driver.PWM && !pins.isEmpty()) {
            throw new IllegalArgumentException(Msg.PINS_FOR_PWM.text(servo));
        }
        for (int p : pins) {
            if (p < 0 || p > 99) {
                throw new IllegalArgumentException(Msg.BAD_PIN.text(p));
            }
        }
        if (!(baud >= 9600 && baud <= 4_500_000)) {
            throw new IllegalArgumentException(Msg.BAD_BAUD.text(baud));
        }
        if (d == Driver.PWM) {
            if (modelName != null) {
                throw new IllegalArgumentException(Msg.MODEL_FOR_BUS.text());
            }
            return new SketchOptions(d, List.copyOf(pins), baud, null, consoleSensors);
        }
        ServoProtocol protocol = d == Driver.DXL ? ServoProtocol.DXL2 : ServoProtocol.STS;
        ServoModel m = modelName == null ? ServoModel.defaultFor(protocol) : ServoModel.named(modelName);
        if (m == null || m.protocol() != protocol) {
            throw new IllegalArgumentException(Msg.MODEL_NOT_OF_SERVO.text(modelName, servo, ServoModel.names(protocol)));
        }
        return new SketchOptions(d, List.of(), baud, m, consoleSensors);
    }

    /**
     * What the sketch's servo driver adds for {@code modules} modules on an AVR board, measured
     * with avr-gcc 5.4 and Debian 12's Arduino core (SimulatedUnoTest prints the figures). RAM: per
     * PWM servo its pulse width, port and pin mask (5 bytes); on a bus the packet buffer and the
     * sketch's own console ({@link SketchConstants}, which {@code sketch.inc} reads from
     * {@code parsl_servo.h}). Flash: the bus code (CRC or checksum, packets, the console) over the
     * PWM timer code. Time: a pulse width per PWM servo (about 600 cycles); on a bus a packet entry
     * sent (3 000) and the packet's alarm, set {@link SketchConstants#BUS_WINDOW_US} early.
     */
    public DriverCost cost(int modules) {
        if (driver == Driver.PWM) {
            return new DriverCost(5L * modules, 0, 600L * modules);
        }
        return new DriverCost(SketchConstants.packetBytes(model, modules) + SketchConstants.busConsoleRam(),
                driver == Driver.DXL ? 1540 : 1400, 3000L * modules + SketchConstants.busAlarmCycles());
    }

    /**
     * Reports what the sketch cannot do: sensors it has no driver for (at their declaration),
     * more PWM servos than it can drive, module IDs that are no servo IDs (at the robot).
     */
    public void check(Program p, DiagnosticSink diags) {
        for (SensorDecl s : p.robot().sensors()) {
            if (!s.type().equals("angle") && !consoleSensors) {
                diags.error(s.pos(), Msg.SKETCH_SENSORS, s.type(),
                        "$" + s.modules().get(0) + "_" + (s.type().equals("touch") ? "touch_left" : "accel_z") + "=1");
            }
        }
        int[] ids = p.moduleIds();
        if (driver == Driver.PWM) {
            if (!pins.isEmpty() && pins.size() != ids.length) {
                diags.error(p.robot().pos(), Msg.PIN_COUNT, pins.size(), ids.length);
            } else if (pins.isEmpty() && ids.length > MAX_PWM) {
                diags.error(p.robot().pos(), Msg.TOO_MANY_PWM, ids.length, MAX_PWM);
            }
            return;
        }
        int max = driver == Driver.DXL ? 252 : 253;
        for (int id : ids) {
            if (id > max) {
                diags.error(p.robot().pos(), Msg.MODULE_NOT_SERVO_ID, id, model.name(), max);
                return;
            }
        }
    }
}
