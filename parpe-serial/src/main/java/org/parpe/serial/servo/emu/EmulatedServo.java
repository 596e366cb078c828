package org.parpe.serial.servo.emu;

import org.parpe.serial.servo.Registers;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;

/**
 * One emulated servo: its control table (the bytes a host reads and writes) and a motor that
 * moves the present position toward the goal at a speed limit while torque is on. A hardware
 * fault turns the torque off, as Dynamixel servos do. The emulator serialises access.
 */
final class EmulatedServo {
    /** Dynamixel X Bus Watchdog value after it tripped (−1). */
    private static final int WATCHDOG_TRIPPED = 0xFF;

    final int id;
    final ServoModel model;
    final byte[] table = new byte[256];
    private final Registers reg;
    private final boolean bigEndian;
    private double angle;
    private long lastPacketNanos = System.nanoTime();

    EmulatedServo(int id, ServoModel model) {
        this.id = id;
        this.model = model;
        this.reg = model.registers();
        this.bigEndian = model.protocol() == ServoProtocol.SCS;
        put(reg.model(), 2, model.number());
        put(reg.goal(), reg.goalSize(), model.ticks(0));
        put(reg.present(), reg.presentSize(), model.ticks(0));
    }

    boolean torqueOn() {
        return table[reg.torque()] != 0;
    }

    double angle() {
        return angle;
    }

    int hardwareError() {
        return table[reg.error()] & 0xFF;
    }

    /** Sets the hardware error bits (0 clears); a fault turns the torque off. */
    void fault(int bits) {
        table[reg.error()] = (byte) bits;
        if (bits != 0) {
            table[reg.torque()] = 0;
        }
    }

    /** A packet for this servo arrived: feeds the Bus Watchdog. */
    void heard(long now) {
        lastPacketNanos = now;
    }

    boolean watchdogTripped() {
        return reg.watchdog() >= 0 && (table[reg.watchdog()] & 0xFF) == WATCHDOG_TRIPPED;
    }

    /**
     * Writes {@code len} bytes at {@code addr} from a host packet; false (nothing written) for
     * an address beyond the table, or a goal while the Bus Watchdog has tripped.
     */
    boolean write(int addr, byte[] data, int off, int len) {
        if (addr < 0 || addr + len > table.length) {
            return false;
        }
        if (watchdogTripped() && addr <= reg.goal() && reg.goal() < addr + len) {
            return false;
        }
        System.arraycopy(data, off, table, addr, len);
        if (addr <= reg.torque() && reg.torque() < addr + len && torqueOn()) {
            if (hardwareError() != 0) {
                table[reg.torque()] = 0;
            } else if (addr > reg.goal() || addr + len <= reg.goal()) {
                // Torque on without a new goal: hold where the servo is.
                put(reg.goal(), reg.goalSize(), model.ticks(angle));
            }
        }
        return true;
    }

    /** Moves a limp servo by hand; false when its torque is on. */
    boolean backDrive(double degrees) {
        if (torqueOn()) {
            return false;
        }
        angle = Math.max(model.minDegrees(), Math.min(model.maxDegrees(), degrees));
        put(reg.present(), reg.presentSize(), model.ticks(angle));
        return true;
    }

    /**
     * One physics step: the motor moves toward the goal at {@code speed} °/s while torque is on;
     * returns true when the Bus Watchdog trips in this step.
     */
    boolean step(long now, double dt, double speed) {
        boolean tripped = false;
        int units = reg.watchdog() >= 0 ? table[reg.watchdog()] & 0xFF : 0;
        if (torqueOn() && units > 0 && units != WATCHDOG_TRIPPED && now - lastPacketNanos > units * 20_000_000L) {
            table[reg.watchdog()] = (byte) WATCHDOG_TRIPPED;
            put(reg.goal(), reg.goalSize(), model.ticks(angle));
            tripped = true;
        }
        if (torqueOn()) {
            double goal = model.degrees(get(reg.goal(), reg.goalSize()), reg.goalSize());
            double d = goal - angle;
            double max = speed * dt;
            angle = Math.abs(d) <= max ? goal : angle + Math.copySign(max, d);
            put(reg.present(), reg.presentSize(), model.ticks(angle));
        }
        return tripped;
    }

    /** Restart (Dynamixel Reboot): errors cleared, torque off, watchdog off. */
    void reboot() {
        table[reg.error()] = 0;
        table[reg.torque()] = 0;
        if (reg.watchdog() >= 0) {
            table[reg.watchdog()] = 0;
        }
    }

    private void put(int addr, int size, int v) {
        for (int i = 0; i < size; i++) {
            table[addr + i] = (byte) (v >>> 8 * (bigEndian ? size - 1 - i : i));
        }
    }

    private int get(int addr, int size) {
        int v = 0;
        for (int i = 0; i < size; i++) {
            v |= (table[addr + i] & 0xFF) << 8 * (bigEndian ? size - 1 - i : i);
        }
        return v;
    }
}
