package org.parpe.serial.servo.profile;

import java.util.List;
import org.parpe.core.diag.SourcePos;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.bus.SafeMode;
import org.parpe.serial.g1.Protocol;
import org.parpe.serial.servo.ServoModel;
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

    /**
     * The profile of G1 modules driven without a profile file (the command line's {@code --port},
     * the IDE's Hardware target without a profile): each module of {@code moduleIds} that can be
     * on the bus (IDs 0..254) is its own device, a {@code g1-segment} with the joint range
     * ±90° ({@link Protocol#JOINT_LIMIT_DEG}); baud, safe mode and watchdog are {@code config}'s.
     */
    public static HardwareProfile ofModules(String port, BusConfig config, int[] moduleIds) {
        ServoModel segment = ServoModel.defaultFor(ServoProtocol.G1);
        List<ServoMapping> servos = new java.util.ArrayList<>();
        for (int id : moduleIds) {
            if (id <= Protocol.MAX_MODULE_ID) {
                servos.add(new ServoMapping(id, id, segment, 0, 1, -Protocol.JOINT_LIMIT_DEG, Protocol.JOINT_LIMIT_DEG,
                        SourcePos.NONE));
            }
        }
        return new HardwareProfile("bus " + port, ServoProtocol.G1, port, config.baud(), config.safeMode(),
                config.watchdogMs(), servos);
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
