package org.parpe.serial.servo.profile;

import java.util.List;
import org.parpe.serial.bus.SafeMode;
import org.parpe.serial.servo.ServoProtocol;

/**
 * A robot's servo hardware: the bus and, per PARSL module, its servo.
 *
 * @param file       where the profile was read from (for messages)
 * @param protocol   the bus protocol
 * @param port       the serial device, or null when the command line must give it
 * @param baud       line speed
 * @param onFault    what servos do on an emergency stop or when the host falls silent
 * @param watchdogMs the servos' own watchdog, where they have one; 0 turns it off
 * @param servos     one mapping per module, in the order of the file
 */
public record HardwareProfile(String file, ServoProtocol protocol, String port, int baud, SafeMode onFault,
                              int watchdogMs, List<ServoMapping> servos) {

    /** The default watchdog: the servos stop 60 ms after the last packet. */
    public static final int DEFAULT_WATCHDOG_MS = 60;

    public HardwareProfile {
        servos = List.copyOf(servos);
    }

    /** The mapping of PARSL module {@code module}, or null. */
    public ServoMapping forModule(int module) {
        for (ServoMapping m : servos) {
            if (m.module() == module) {
                return m;
            }
        }
        return null;
    }

    /** The same profile with {@code servos} instead. */
    public HardwareProfile withServos(List<ServoMapping> s) {
        return new HardwareProfile(file, protocol, port, baud, onFault, watchdogMs, s);
    }

    /** The same profile on another port (the command line's {@code --port} wins over the file's). */
    public HardwareProfile withPort(String p) {
        return new HardwareProfile(file, protocol, p, baud, onFault, watchdogMs, servos);
    }
}
