package org.parpe.serial.servo.emu;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
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

    /** PARPE's choice where the tables give no value: a room-temperature servo, firmware as Ping reports it. */
    static final int TEMPERATURE = 28;
    /** Dynamixel firmware version PARPE's emulated servos report (Ping and Firmware Version). */
    static final int DXL_FIRMWARE = 46;
    /** The transcribed tables, one file of rows read once (its head says the format). */
    private static final String TABLES = "control-tables.txt";

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
        Map<String, ControlTable> tables = read();
        X_SERIES = tables.get("X_SERIES");
        XL320 = tables.get("XL320");
        STS = tables.get("STS");
        SCS = tables.get("SCS");
    }

    /** The tables of {@link #TABLES}, by name; a malformed row is a mistake in PARPE and fails loudly. */
    private static Map<String, ControlTable> read() {
        List<String> lines;
        try (InputStream in = ControlTable.class.getResourceAsStream(TABLES)) {
            if (in == null) {
                throw new IllegalStateException("missing resource " + TABLES);
            }
            lines = new String(in.readAllBytes(), StandardCharsets.UTF_8).lines().toList();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        Map<String, ControlTable> tables = new HashMap<>();
        String name = null;
        String source = null;
        int length = 0;
        List<Item> items = new ArrayList<>();
        boolean eeprom = true;
        for (int n = 0; n <= lines.size(); n++) {
            String line = n < lines.size() ? lines.get(n).strip() : "table";
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            if (line.startsWith("table")) {
                if (name != null) {
                    if (name.equals("X_SERIES")) {
                        addIndirect(items);
                    }
                    tables.put(name, new ControlTable(source, length, items));
                }
                if (n < lines.size()) {
                    String[] head = line.split(" ", 4);
                    name = head[1];
                    length = Integer.parseInt(head[2]);
                    source = head[3];
                    items = new ArrayList<>();
                    eeprom = true;
                }
            } else if (line.equals("ram")) {
                eeprom = false;
            } else {
                items.add(item(line.split("\\s*\\|\\s*"), eeprom, TABLES + ":" + (n + 1)));
            }
        }
        return tables;
    }

    private static Item item(String[] f, boolean eeprom, String where) {
        boolean writable = f[0].equals("RW");
        if (f.length != (writable ? 7 : 5) || !(writable || f[0].equals("R"))) {
            throw new IllegalStateException(where + ": not an item row");
        }
        return new Item(f[1], Integer.parseInt(f[2]), Integer.parseInt(f[3]), writable, eeprom, value(f[4]),
                writable ? value(f[5]) : ANY, writable ? value(f[6]) : ANY);
    }

    private static long value(String v) {
        switch (v) {
            case "*": return ANY;
            case "$firmware": return DXL_FIRMWARE;
            case "$temperature": return TEMPERATURE;
            default: return Long.parseLong(v);
        }
    }

    /** The X series' Indirect Address 1–56 and Indirect Data 1–56 items, in address order. */
    private static void addIndirect(List<Item> items) {
        for (int half = 0; half < 2; half++) {
            int addrBase = half == 0 ? 168 : 578;
            int dataBase = half == 0 ? 224 : 634;
            for (int k = 0; k < 28; k++) {
                items.add(new Item("Indirect Address " + (28 * half + k + 1), addrBase + 2 * k, 2, true, false,
                        dataBase + k, 64, 661));
            }
            for (int k = 0; k < 28; k++) {
                items.add(new Item(INDIRECT_DATA + (28 * half + k + 1), dataBase + k, 1, true, false, 0, 0, 255));
            }
        }
    }
}
