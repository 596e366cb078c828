package org.parpe.serial.servo.emu;

import java.util.ArrayList;
import java.util.List;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;

/**
 * The control table of a servo family as its maker documents it: each item's address, size,
 * access, whether it lies in EEPROM, its initial value and the range a write must keep to.
 * Transcribed from the sources named in {@link #source}; where a source gives no initial value
 * (present voltage and temperature, firmware version) the value is PARPE's choice and says so.
 */
final class ControlTable {
    private static final String INDIRECT_DATA = "Indirect Data ";
    /** Range bound meaning "no range given". */
    static final long ANY = Long.MIN_VALUE;

    /**
     * One item.
     *
     * @param name     its name in the source
     * @param addr     first address
     * @param size     bytes
     * @param writable RW (true) or R
     * @param eeprom   in the EEPROM area (Dynamixel: locked while torque is on)
     * @param initial  value at power-on
     * @param min      lowest value a write may set ({@link #ANY}: none)
     * @param max      highest value a write may set
     */
    record Item(String name, int addr, int size, boolean writable, boolean eeprom, long initial, long min, long max) {
        boolean signed() {
            return min != ANY && min < 0;
        }
    }

    final String source;
    final int length;
    private final Item[] byAddress;
    /** For an X-series Indirect Data address, the address of its Indirect Address item; else −1. */
    private final int[] indirectSlot;
    private final List<Item> items;

    private ControlTable(String source, int length, List<Item> items) {
        this.source = source;
        this.length = length;
        this.items = List.copyOf(items);
        this.byAddress = new Item[length];
        this.indirectSlot = new int[length];
        java.util.Arrays.fill(indirectSlot, -1);
        for (Item i : items) {
            for (int a = i.addr; a < i.addr + i.size; a++) {
                byAddress[a] = i;
            }
            if (i.name.startsWith(INDIRECT_DATA)) {
                int k = Integer.parseInt(i.name.substring(INDIRECT_DATA.length()));
                indirectSlot[i.addr] = k <= 28 ? 168 + 2 * (k - 1) : 578 + 2 * (k - 29);
            }
        }
    }

    /**
     * The address of the Indirect Address item that says where Indirect Data at {@code addr}
     * reads and writes (e-Manual, X series, Indirect Address and Indirect Data); −1 for others.
     */
    int indirectSlot(int addr) {
        return addr >= 0 && addr < length ? indirectSlot[addr] : -1;
    }

    /** The item that holds address {@code addr}, or null (reserved or beyond the table). */
    Item at(int addr) {
        return addr >= 0 && addr < length ? byAddress[addr] : null;
    }

    /** The item called {@code name}; throws when the table has none (a mistake in PARPE). */
    Item named(String name) {
        for (Item i : items) {
            if (i.name.equals(name)) {
                return i;
            }
        }
        throw new IllegalArgumentException(source + " has no item " + name);
    }

    /** Whether the table has an item called {@code name}. */
    boolean has(String name) {
        return items.stream().anyMatch(i -> i.name.equals(name));
    }

    List<Item> items() {
        return items;
    }

    /** The table of {@code model}'s family. */
    static ControlTable of(ServoModel model) {
        if (model.protocol() == ServoProtocol.STS) {
            return STS;
        }
        if (model.protocol() == ServoProtocol.SCS) {
            return SCS;
        }
        return model.registers() == org.parpe.serial.servo.Registers.DXL_XL320 ? XL320 : X_SERIES;
    }

    private static final class Builder {
        private final List<Item> items = new ArrayList<>();
        private boolean eeprom = true;

        Builder r(String name, int addr, int size, long initial) {
            items.add(new Item(name, addr, size, false, eeprom, initial, ANY, ANY));
            return this;
        }

        Builder rw(String name, int addr, int size, long initial, long min, long max) {
            items.add(new Item(name, addr, size, true, eeprom, initial, min, max));
            return this;
        }

        Builder ram() {
            eeprom = false;
            return this;
        }
    }

    /** PARPE's choice where the tables give no value: a room-temperature servo, firmware as Ping reports it. */
    static final int TEMPERATURE = 28;
    /** Dynamixel firmware version PARPE's emulated servos report (Ping and Firmware Version). */
    static final int DXL_FIRMWARE = 46;

    /**
     * Dynamixel X series, ROBOTIS e-Manual, XL430-W250 page, "Control Table of EEPROM Area" and
     * "Control Table of RAM Area" (addresses 0–661). The model number item is set per model.
     * Present Input Voltage 11.1 V (the XL430's recommended supply) is PARPE's choice.
     */
    static final ControlTable X_SERIES;
    /** Dynamixel XL-320, ROBOTIS e-Manual, XL-320 page, control tables (addresses 0–52). 7.4 V supply (recommended). */
    static final ControlTable XL320;
    /**
     * Feetech STS series (STS3215): addresses, sizes and access of Feetech's STS/SMS memory table
     * as LeRobot transcribes it (lerobot/motors/feetech/tables.py, STS_SMS_SERIES_CONTROL_TABLE,
     * citing Feetech's FT-SMS-STS e-manual). The tables give no initial values; those here are
     * PARPE's: factory ID 1 and 1 Mbaud (index 0 of the baud table), Return Delay Time 0,
     * Response Status Level 1, position limits 0–4095, 7.4 V.
     */
    static final ControlTable STS;
    /** Feetech SCS series (SCS0009), the same source's SCS_SERIES_CONTROL_TABLE; limits 0–1023, 6 V. */
    static final ControlTable SCS;

    static {
        Builder x = new Builder()
                .r("Model Number", 0, 2, 1060)
                .r("Model Information", 2, 4, 0)
                .r("Firmware Version", 6, 1, DXL_FIRMWARE)
                .rw("ID", 7, 1, 1, 0, 252)
                .rw("Baud Rate", 8, 1, 1, 0, 7)
                .rw("Return Delay Time", 9, 1, 250, 0, 254)
                .rw("Drive Mode", 10, 1, 0, 0, 13)
                .rw("Operating Mode", 11, 1, 3, 0, 16)
                .rw("Secondary(Shadow) ID", 12, 1, 255, 0, 255)
                .rw("Protocol Type", 13, 1, 2, 1, 2)
                .rw("Homing Offset", 20, 4, 0, -1_044_479, 1_044_479)
                .rw("Moving Threshold", 24, 4, 10, 0, 1023)
                .rw("Temperature Limit", 31, 1, 72, 0, 100)
                .rw("Max Voltage Limit", 32, 2, 140, 60, 140)
                .rw("Min Voltage Limit", 34, 2, 60, 60, 140)
                .rw("PWM Limit", 36, 2, 885, 0, 885)
                .rw("Velocity Limit", 44, 4, 265, 0, 1023)
                .rw("Max Position Limit", 48, 4, 4095, 0, 4095)
                .rw("Min Position Limit", 52, 4, 0, 0, 4095)
                .rw("Startup Configuration", 60, 1, 0, 0, 3)
                .rw("Shutdown", 63, 1, 52, 0, 255)
                .ram()
                .rw("Torque Enable", 64, 1, 0, 0, 1)
                .rw("LED", 65, 1, 0, 0, 1)
                .rw("Status Return Level", 68, 1, 2, 0, 2)
                .r("Registered Instruction", 69, 1, 0)
                .r("Hardware Error Status", 70, 1, 0)
                .rw("Velocity I Gain", 76, 2, 1000, 0, 16_383)
                .rw("Velocity P Gain", 78, 2, 100, 0, 16_383)
                .rw("Position D Gain", 80, 2, 4000, 0, 16_383)
                .rw("Position I Gain", 82, 2, 0, 0, 16_383)
                .rw("Position P Gain", 84, 2, 640, 0, 16_383)
                .rw("Feedforward 2nd Gain", 88, 2, 0, 0, 16_383)
                .rw("Feedforward 1st Gain", 90, 2, 0, 0, 16_383)
                // Range 1–127 to activate, 0 to deactivate and clear, −1 is the error state (read only).
                .rw("Bus Watchdog", 98, 1, 0, 0, 127)
                .rw("Goal PWM", 100, 2, 0, -885, 885)
                .rw("Goal Velocity", 104, 4, 0, -1023, 1023)
                .rw("Profile Acceleration", 108, 4, 0, 0, 32_767)
                .rw("Profile Velocity", 112, 4, 0, 0, 32_767)
                // Range: Min Position Limit(52) ~ Max Position Limit(48), checked by the servo.
                .rw("Goal Position", 116, 4, 2048, ANY, ANY)
                .r("Realtime Tick", 120, 2, 0)
                .r("Moving", 122, 1, 0)
                .r("Moving Status", 123, 1, 0)
                .r("Present PWM", 124, 2, 0)
                .r("Present Load", 126, 2, 0)
                .r("Present Velocity", 128, 4, 0)
                .r("Present Position", 132, 4, 2048)
                .r("Velocity Trajectory", 136, 4, 0)
                .r("Position Trajectory", 140, 4, 2048)
                .r("Present Input Voltage", 144, 2, 111)
                .r("Present Temperature", 146, 1, TEMPERATURE)
                .r("Backup Ready", 147, 1, 0);
        for (int k = 0; k < 28; k++) {
            x.rw("Indirect Address " + (k + 1), 168 + 2 * k, 2, 224 + k, 64, 661);
        }
        for (int k = 0; k < 28; k++) {
            x.rw(INDIRECT_DATA + (k + 1), 224 + k, 1, 0, 0, 255);
        }
        for (int k = 0; k < 28; k++) {
            x.rw("Indirect Address " + (k + 29), 578 + 2 * k, 2, 634 + k, 64, 661);
        }
        for (int k = 0; k < 28; k++) {
            x.rw(INDIRECT_DATA + (k + 29), 634 + k, 1, 0, 0, 255);
        }
        X_SERIES = new ControlTable("ROBOTIS e-Manual, XL430-W250, Control Table", 662, x.items);

        XL320 = new ControlTable("ROBOTIS e-Manual, XL-320, Control Table", 53, new Builder()
                .r("Model Number", 0, 2, 350)
                .r("Firmware Version", 2, 1, DXL_FIRMWARE)
                .rw("ID", 3, 1, 1, 0, 252)
                .rw("Baud Rate", 4, 1, 3, 0, 3)
                .rw("Return Delay Time", 5, 1, 250, 0, 254)
                .rw("CW Angle Limit", 6, 2, 0, 0, 1023)
                .rw("CCW Angle Limit", 8, 2, 1023, 0, 1023)
                .rw("Control Mode", 11, 1, 2, 1, 2)
                .rw("Temperature Limit", 12, 1, 65, 0, 150)
                .rw("Min Voltage Limit", 13, 1, 60, 50, 250)
                .rw("Max Voltage Limit", 14, 1, 90, 50, 250)
                .rw("Max Torque", 15, 2, 1023, 0, 1023)
                .rw("Status Return Level", 17, 1, 2, 0, 2)
                .rw("Shutdown", 18, 1, 3, 0, 7)
                .ram()
                .rw("Torque Enable", 24, 1, 0, 0, 1)
                .rw("LED", 25, 1, 0, 0, 7)
                .rw("D Gain", 27, 1, 0, 0, 254)
                .rw("I Gain", 28, 1, 0, 0, 254)
                .rw("P Gain", 29, 1, 32, 0, 254)
                // Range: CW Angle Limit(6) ~ CCW Angle Limit(8), checked by the servo.
                .rw("Goal Position", 30, 2, 512, ANY, ANY)
                .rw("Moving Speed", 32, 2, 0, 0, 2047)
                .rw("Torque Limit", 35, 2, 1023, 0, 1023)
                .r("Present Position", 37, 2, 512)
                .r("Present Speed", 39, 2, 0)
                .r("Present Load", 41, 2, 0)
                .r("Present Voltage", 45, 1, 74)
                .r("Present Temperature", 46, 1, TEMPERATURE)
                .r("Registered Instruction", 47, 1, 0)
                .r("Moving", 49, 1, 0)
                .r("Hardware Error Status", 50, 1, 0)
                .rw("Punch", 51, 2, 32, 0, 1023).items);

        STS = feetech("Feetech STS/SMS memory table (LeRobot STS_SMS_SERIES_CONTROL_TABLE)", 777, 4095, 74, true);
        SCS = feetech("Feetech SCS memory table (LeRobot SCS_SERIES_CONTROL_TABLE)", 1284, 1023, 60, false);
    }

    private static ControlTable feetech(String source, int model, int maxPosition, int volts, boolean sts) {
        Builder b = new Builder()
                .r("Firmware Major Version", 0, 1, 3)
                .r("Firmware Minor Version", 1, 1, 10)
                .r("Model Number", 3, 2, model)
                .rw("ID", 5, 1, 1, 0, 253)
                .rw("Baud Rate", 6, 1, 0, 0, 7)
                .rw("Return Delay Time", 7, 1, 0, 0, 254)
                .rw("Response Status Level", 8, 1, 1, 0, 1)
                .rw("Min Position Limit", 9, 2, 0, 0, maxPosition)
                .rw("Max Position Limit", 11, 2, maxPosition, 0, maxPosition)
                .rw("Max Temperature Limit", 13, 1, 70, 0, 100)
                .rw("Max Voltage Limit", 14, 1, 80, 0, 254)
                .rw("Min Voltage Limit", 15, 1, 40, 0, 254)
                .rw("Max Torque Limit", 16, 2, 1000, 0, 1000)
                .rw("Phase", 18, 1, 0, 0, 255)
                .rw("Unloading Condition", 19, 1, 44, 0, 255)
                .rw("LED Alarm Condition", 20, 1, 47, 0, 255)
                .rw("P Coefficient", 21, 1, 32, 0, 255)
                .rw("D Coefficient", 22, 1, 32, 0, 255)
                .rw("I Coefficient", 23, 1, 0, 0, 255)
                .rw("Minimum Startup Force", 24, 2, 16, 0, 1000)
                .rw("CW Dead Zone", 26, 1, 1, 0, 255)
                .rw("CCW Dead Zone", 27, 1, 1, 0, 255);
        if (sts) {
            b.rw("Protection Current", 28, 2, 500, 0, 2047)
                    .rw("Angular Resolution", 30, 1, 1, 1, 100)
                    .rw("Homing Offset", 31, 2, 0, 0, 0xFFFF)
                    .rw("Operating Mode", 33, 1, 0, 0, 3)
                    .rw("Protective Torque", 34, 1, 20, 0, 100)
                    .rw("Protection Time", 35, 1, 200, 0, 254)
                    .rw("Overload Torque", 36, 1, 80, 0, 100)
                    .rw("Velocity closed loop P", 37, 1, 10, 0, 100)
                    .rw("Over Current Protection Time", 38, 1, 200, 0, 254)
                    .rw("Velocity closed loop I", 39, 1, 200, 0, 254);
        } else {
            b.rw("Protective Torque", 37, 1, 20, 0, 100)
                    .rw("Protection Time", 38, 1, 200, 0, 254);
        }
        b.ram()
                .rw("Torque Enable", 40, 1, 0, 0, 1)
                .rw("Acceleration", 41, 1, 0, 0, 254)
                // Range: Min Position Limit(9) ~ Max Position Limit(11).
                .rw("Goal Position", 42, 2, maxPosition / 2 + 1, ANY, ANY)
                .rw(sts ? "Goal Time" : "Running Time", 44, 2, 0, 0, 0xFFFF)
                .rw("Goal Velocity", 46, 2, 0, 0, 0xFFFF);
        if (sts) {
            b.rw("Torque Limit", 48, 2, 1000, 0, 1000).rw("Lock", 55, 1, 1, 0, 1);
        } else {
            b.rw("Lock", 48, 1, 1, 0, 1);
        }
        b.r("Present Position", 56, 2, maxPosition / 2 + 1)
                .r("Present Velocity", 58, 2, 0)
                .r("Present Load", 60, 2, 0)
                .r("Present Voltage", 62, 1, volts)
                .r("Present Temperature", 63, 1, TEMPERATURE);
        if (!sts) {
            b.r("Sync Write Flag", 64, 1, 0);
        }
        b.r("Status", 65, 1, 0).r("Moving", 66, 1, 0);
        if (sts) {
            b.r("Present Current", 69, 2, 0).r("Goal Position 2", 71, 2, 0);
        }
        return new ControlTable(source, 87, b.items);
    }
}
