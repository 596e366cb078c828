package org.parpe.serial.servo.emu;

import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.wire.PacketCodec;

/**
 * One emulated servo: its control table as the maker documents it ({@link ControlTable}), the
 * checks a write must pass (Dynamixel Protocol 2.0 errors: Access, Data Length, Data Range), a
 * motor that moves the present position toward the goal at a speed limit while torque is on, the
 * Dynamixel Bus Watchdog, and a registered (Reg Write) write waiting for Action. A hardware fault
 * turns the torque off, as Dynamixel servos do. The emulator serialises access.
 */
final class EmulatedServo {
    /** Protocol 2.0 error numbers (e-Manual, Protocol 2.0, Status Packet, Error). */
    static final int OK = 0;
    static final int INSTRUCTION_ERROR = 0x02;
    static final int DATA_RANGE_ERROR = 0x04;
    static final int DATA_LENGTH_ERROR = 0x05;
    static final int ACCESS_ERROR = 0x07;
    /** Bus Watchdog(98) while its error is active: −1 in one byte. */
    private static final int WATCHDOG_TRIPPED = 0xFF;

    final ServoModel model;
    final ControlTable ct;
    final byte[] table;
    private final PacketCodec codec;
    private final boolean bigEndian;
    private final ControlTable.Item idItem;
    private final ControlTable.Item torque;
    private final ControlTable.Item goal;
    private final ControlTable.Item present;
    private final ControlTable.Item error;
    private final ControlTable.Item watchdog;
    private final ControlTable.Item returnDelay;
    private final ControlTable.Item statusLevel;
    private final ControlTable.Item registered;
    private final ControlTable.Item minLimit;
    private final ControlTable.Item maxLimit;
    private double angle;
    private long lastPacketNanos = System.nanoTime();
    private final byte[] pending;
    private int pendingAddr = -1;
    private int pendingLen;

    EmulatedServo(int id, ServoModel model) {
        this.model = model;
        this.ct = ControlTable.of(model);
        this.table = new byte[ct.length];
        this.pending = new byte[ct.length];
        this.codec = model.protocol().codec();
        this.bigEndian = model.protocol().bigEndian();
        idItem = ct.named("ID");
        torque = ct.named("Torque Enable");
        goal = ct.named("Goal Position");
        present = ct.named("Present Position");
        error = ct.at(model.registers().error());
        watchdog = ct.has("Bus Watchdog") ? ct.named("Bus Watchdog") : null;
        returnDelay = ct.named("Return Delay Time");
        statusLevel = ct.named(ct.has("Status Return Level") ? "Status Return Level" : "Response Status Level");
        registered = ct.has("Registered Instruction") ? ct.named("Registered Instruction") : null;
        minLimit = ct.named(ct == ControlTable.XL320 ? "CW Angle Limit" : "Min Position Limit");
        maxLimit = ct.named(ct == ControlTable.XL320 ? "CCW Angle Limit" : "Max Position Limit");
        for (ControlTable.Item i : ct.items()) {
            put(i.addr(), i.size(), (int) i.initial());
        }
        put(ct.named("Model Number").addr(), 2, model.number());
        put(idItem.addr(), 1, id);
        put(goal.addr(), goal.size(), model.ticks(0));
        put(present.addr(), present.size(), model.ticks(0));
    }

    /** The ID it answers to (its ID item, which a host may change). */
    int id() {
        return table[idItem.addr()] & 0xFF;
    }

    boolean torqueOn() {
        return table[torque.addr()] != 0;
    }

    double angle() {
        return angle;
    }

    int hardwareError() {
        return table[error.addr()] & 0xFF;
    }

    /** Whether it answers Fast Sync Read: its model has it from the firmware version it reports. */
    boolean fastSyncRead() {
        return codec.knows(PacketCodec.FAST_SYNC_READ) && model.fastSyncRead(table[ct.named("Firmware Version").addr()] & 0xFF);
    }

    /** Return Delay Time in nanoseconds (the item counts units of 2 µs). */
    long returnDelayNanos() {
        return (table[returnDelay.addr()] & 0xFF) * 2_000L;
    }

    /**
     * Whether a status packet answers an instruction: Ping always; on Dynamixel a Status Return
     * Level of 0 answers Ping only, 1 also Read, 2 everything (e-Manual, X series, Status Return
     * Level(68)); on Feetech a Response Status Level of 0 answers Ping and Read only.
     */
    boolean answers(boolean ping, boolean read) {
        int level = table[statusLevel.addr()] & 0xFF;
        if (ping) {
            return true;
        }
        return codec.answers(level, read);
    }

    /** Sets the hardware error bits (0 clears); a fault turns the torque off. */
    void fault(int bits) {
        table[error.addr()] = (byte) bits;
        if (bits != 0) {
            table[torque.addr()] = 0;
        }
    }

    /** A packet for this servo arrived: feeds the Bus Watchdog. */
    void heard(long now) {
        lastPacketNanos = now;
    }

    boolean watchdogTripped() {
        return watchdog != null && (table[watchdog.addr()] & 0xFF) == WATCHDOG_TRIPPED;
    }

    /** Copies {@code len} bytes from {@code addr} into {@code out}: an error number (0: done). */
    int read(int addr, int len, byte[] out) {
        if (addr < 0 || len < 0 || addr + len > ct.length) {
            return ACCESS_ERROR;
        }
        for (int k = 0; k < len; k++) {
            out[k] = table[indirect(addr + k)];
        }
        return OK;
    }

    /**
     * Writes {@code len} bytes at {@code addr} from {@code data[off…)} as the servo would: an
     * error number, and nothing written, when the write touches a reserved or read-only address
     * or EEPROM with torque on (Access Error), covers part of an item (Data Length Error), puts
     * an item outside its range or a goal while the Bus Watchdog error is active (Data Range
     * Error; e-Manual, X series, Bus Watchdog(98), example step 6).
     */
    int write(int addr, byte[] data, int off, int len) {
        int check = check(addr, data, off, len);
        if (check != OK) {
            return check;
        }
        boolean torqueWas = torqueOn();
        for (int k = 0; k < len; k++) {
            ControlTable.Item i = ct.at(addr + k);
            // Feetech servos ignore bytes written to reserved or read-only addresses.
            if (i != null && i.writable()) {
                table[indirect(addr + k)] = data[off + k];
            }
        }
        if (!codec.errorNumbers() && covers(addr, len, goal)) {
            // Feetech servos keep a goal inside their angle limits. On STS bit 15 is its sign, so
            // −100 (0x8064) lies below the minimum, not above the maximum; SCS goals are unsigned
            // (the SDK's SCSCL WritePos takes a u16).
            int raw = get(goal.addr(), goal.size());
            int g = model.signBit() >= 0 ? model.tick(raw, goal.size()) : raw;
            int kept = Math.max(get(minLimit.addr(), 2), Math.min(get(maxLimit.addr(), 2), g));
            put(goal.addr(), goal.size(), model.encode(kept));
        }
        if (covers(addr, len, torque) && torqueOn()) {
            if (hardwareError() != 0) {
                table[torque.addr()] = 0;
            } else if (!torqueWas && !covers(addr, len, goal)) {
                // Torque on without a new goal: hold where the servo is.
                put(goal.addr(), goal.size(), model.ticks(angle));
            }
        }
        return OK;
    }

    private int check(int addr, byte[] data, int off, int len) {
        if (addr < 0 || len <= 0 || addr + len > ct.length) {
            return ACCESS_ERROR;
        }
        for (int a = addr; a < addr + len; ) {
            ControlTable.Item i = ct.at(a);
            if (i == null || !i.writable()) {
                return codec.errorNumbers() ? ACCESS_ERROR : OK;
            }
            if (i.addr() < addr || i.addr() + i.size() > addr + len) {
                return DATA_LENGTH_ERROR;
            }
            if (codec.errorNumbers() && i.eeprom() && torqueOn()) {
                return ACCESS_ERROR;
            }
            long v = value(data, off + i.addr() - addr, i.size(), i.signed());
            if (i == goal) {
                if (watchdogTripped()) {
                    return DATA_RANGE_ERROR;
                }
                if (codec.errorNumbers() && (v < get(minLimit.addr(), minLimit.size()) || v > get(maxLimit.addr(), maxLimit.size()))) {
                    return DATA_RANGE_ERROR;
                }
            } else if (i.min() != ControlTable.ANY && (v < i.min() || v > i.max())) {
                return DATA_RANGE_ERROR;
            }
            a = i.addr() + i.size();
        }
        return OK;
    }

    /** Reg Write: keeps the write until Action; an error number as {@link #write} would give. */
    int register(int addr, byte[] data, int off, int len) {
        int check = check(addr, data, off, len);
        if (check == OK) {
            System.arraycopy(data, off, pending, 0, len);
            pendingAddr = addr;
            pendingLen = len;
            if (registered != null) {
                table[registered.addr()] = 1;
            }
        }
        return check;
    }

    /** Action: executes the registered write; false when none was registered (Instruction Error). */
    boolean action() {
        if (pendingAddr < 0) {
            return false;
        }
        write(pendingAddr, pending, 0, pendingLen);
        pendingAddr = -1;
        if (registered != null) {
            table[registered.addr()] = 0;
        }
        return true;
    }

    /** Moves a limp servo by hand; false when its torque is on. */
    boolean backDrive(double degrees) {
        if (torqueOn()) {
            return false;
        }
        angle = Math.max(model.minDegrees(), Math.min(model.maxDegrees(), degrees));
        put(present.addr(), present.size(), model.ticks(angle));
        return true;
    }

    /** The goal position in servo degrees. */
    double goalDegrees() {
        return model.degrees(get(goal.addr(), goal.size()), goal.size());
    }

    /** Whether a write of {@code len} bytes at {@code addr} sets the goal position. */
    boolean setsGoal(int addr, int len) {
        return covers(addr, len, goal);
    }

    /**
     * One physics step: the motor moves toward the goal at {@code speed} °/s while torque is on;
     * returns true when the Bus Watchdog trips in this step.
     */
    boolean step(long now, double dt, double speed) {
        boolean tripped = false;
        int units = watchdog == null ? 0 : table[watchdog.addr()] & 0xFF;
        if (torqueOn() && units > 0 && units != WATCHDOG_TRIPPED && now - lastPacketNanos > units * 20_000_000L) {
            table[watchdog.addr()] = (byte) WATCHDOG_TRIPPED;
            put(goal.addr(), goal.size(), model.ticks(angle));
            tripped = true;
        }
        if (torqueOn()) {
            double g = goalDegrees();
            double d = g - angle;
            double max = speed * dt;
            angle = Math.abs(d) <= max ? g : angle + Math.copySign(max, d);
            put(present.addr(), present.size(), model.ticks(angle));
        }
        return tripped;
    }

    /** Restart (Dynamixel Reboot): errors cleared, torque off, watchdog off, nothing registered. */
    void reboot() {
        table[error.addr()] = 0;
        table[torque.addr()] = 0;
        if (watchdog != null) {
            table[watchdog.addr()] = 0;
        }
        pendingAddr = -1;
        if (registered != null) {
            table[registered.addr()] = 0;
        }
    }

    /** Address {@code a}, or the address an X-series Indirect Data item stands for. */
    private int indirect(int a) {
        int slot = ct.indirectSlot(a);
        if (slot < 0) {
            return a;
        }
        int target = get(slot, 2);
        return target >= 0 && target < ct.length ? target : a;
    }

    private static boolean covers(int addr, int len, ControlTable.Item i) {
        return addr <= i.addr() && i.addr() < addr + len;
    }

    private long value(byte[] b, int off, int size, boolean signed) {
        long v = 0;
        for (int k = 0; k < size; k++) {
            v |= (long) (b[off + k] & 0xFF) << 8 * (bigEndian ? size - 1 - k : k);
        }
        if (signed && size < 8) {
            v = v << (64 - 8 * size) >> (64 - 8 * size);
        }
        return v;
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
