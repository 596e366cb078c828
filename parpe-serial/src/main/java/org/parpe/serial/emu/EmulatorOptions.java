package org.parpe.serial.emu;

import java.util.Arrays;
import org.parpe.core.text.Msg;
import org.parpe.serial.text.SerialMsg;

/**
 * How {@link org.parpe.serial.g1.emu.BusEmulator} behaves.
 *
 * @param modules        the emulated module IDs (0…254), in any order
 * @param drop           probability that a frame, in either direction, is lost
 * @param corrupt        probability that a frame, in either direction, has one byte changed
 * @param latencyMs      delay before a module replies, milliseconds
 * @param unplugAfterS   seconds after start at which the cable is pulled; negative for never
 * @param unplugForS     seconds the cable stays out; negative for the rest of the run
 * @param speedDegPerS   servo speed limit, degrees per second
 * @param seed           seed of the fault injector, for reproducible faults
 */
public record EmulatorOptions(int[] modules, double drop, double corrupt, double latencyMs,
                              double unplugAfterS, double unplugForS, double speedDegPerS, long seed) {

    public EmulatorOptions {
        modules = modules.clone();
        for (int id : modules) {
            if (id < 0 || id > org.parpe.serial.g1.Protocol.MAX_MODULE_ID) {
                throw new IllegalArgumentException(Msg.MUST_BE_IN_RANGE.text(SerialMsg.EMU_MODULE_ID.text(), 0,
                        org.parpe.serial.g1.Protocol.MAX_MODULE_ID, id));
            }
        }
        if (Arrays.stream(modules).distinct().count() != modules.length) {
            throw new IllegalArgumentException(SerialMsg.EMU_LISTED_TWICE.text(Arrays.toString(modules)));
        }
        checkProbability(SerialMsg.EMU_DROP, drop);
        checkProbability(SerialMsg.EMU_CORRUPT, corrupt);
        if (!(latencyMs >= 0) || latencyMs > 10_000) {
            throw new IllegalArgumentException(SerialMsg.EMU_LATENCY.text(10_000, latencyMs));
        }
        if (!(speedDegPerS > 0)) {
            throw new IllegalArgumentException(SerialMsg.EMU_SPEED.text(speedDegPerS));
        }
    }

    /** Modules with no faults, a 360 °/s servo, never unplugged. */
    public static EmulatorOptions of(int... modules) {
        return new EmulatorOptions(modules, 0, 0, 0, -1, -1, 360, 1);
    }

    /** The same options with other fault settings. */
    public EmulatorOptions withFaults(double drop, double corrupt, double latencyMs) {
        return new EmulatorOptions(modules, drop, corrupt, latencyMs, unplugAfterS, unplugForS, speedDegPerS, seed);
    }

    /** The same options with an unplug schedule. */
    public EmulatorOptions withUnplug(double afterS, double forS) {
        return new EmulatorOptions(modules, drop, corrupt, latencyMs, afterS, forS, speedDegPerS, seed);
    }

    private static void checkProbability(SerialMsg what, double p) {
        if (!(p >= 0 && p <= 1)) {
            throw new IllegalArgumentException(Msg.MUST_BE_IN_RANGE.text(what.text(), 0, 1, p));
        }
    }
}
