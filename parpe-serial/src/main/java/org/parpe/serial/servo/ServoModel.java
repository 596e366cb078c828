package org.parpe.serial.servo;

import java.util.List;
import java.util.Locale;

/**
 * One servo model and its units: the only place where raw position ticks become degrees and
 * back. Degrees here are servo degrees, 0 at {@link #centre}; a hardware profile's zero offset and
 * direction turn them into joint angles.
 *
 * @param protocol   the bus it speaks
 * @param number     model number as the servo reports it
 * @param name       name for messages and profiles (lower case)
 * @param resolution ticks per {@code rangeDeg}
 * @param rangeDeg   degrees covered by {@code resolution} ticks
 * @param centre     tick of servo angle 0
 * @param minTick    lowest goal position the servo accepts
 * @param maxTick    highest goal position the servo accepts
 * @param signBit    bit that carries the sign of a position (sign and magnitude), or −1 for two's complement
 * @param registers  control table addresses
 * @param fastSyncReadFirmware the lowest firmware version that answers Dynamixel Fast Sync Read
 *                   (0x8A), or −1 when the model has none
 */
public record ServoModel(ServoProtocol protocol, int number, String name, int resolution, double rangeDeg, int centre,
                         int minTick, int maxTick, int signBit, Registers registers, int fastSyncReadFirmware) {

    /** The models PARPE knows, from the manufacturers' control tables. */
    public static final List<ServoModel> TABLE = List.of(
            // Fast Sync Read: X series from firmware v45, the XL330 from v46; the XL-320 has none
            // (DynamixelSDK's fast_sync_read example: "X series (except XL-320)"). Sources and the
            // choice: docs/decisions.md, "Vendor disagreements".
            dxlX(1060, "xl430-w250", 45),
            dxlX(1090, "2xl430-w250", 45),
            dxlX(1190, "xl330-m077", 46),
            dxlX(1200, "xl330-m288", 46),
            dxlX(1020, "xm430-w350", 45),
            dxlX(1030, "xm430-w210", 45),
            dxlX(1070, "xc430-w150", 45),
            new ServoModel(ServoProtocol.DXL2, 350, "xl-320", 1024, 300, 512, 0, 1023, -1, Registers.DXL_XL320, -1),
            new ServoModel(ServoProtocol.STS, 777, "sts3215", 4096, 360, 2048, 0, 4095, 15, Registers.FEETECH, -1),
            // Feetech rates the SCS0009 at 300° over 1024 steps (0.293°/step), like the XL-320.
            new ServoModel(ServoProtocol.SCS, 1284, "scs0009", 1024, 300, 512, 0, 1023, -1, Registers.FEETECH, -1),
            new ServoModel(ServoProtocol.G1, 1, "g1-segment", 100, 1, 0, -9000, 9000, -1, null, -1));

    private static ServoModel dxlX(int number, String name, int fastSyncReadFirmware) {
        return new ServoModel(ServoProtocol.DXL2, number, name, 4096, 360, 2048, 0, 4095, -1, Registers.DXL_X,
                fastSyncReadFirmware);
    }

    /** Whether a servo of this model running firmware version {@code firmware} answers Fast Sync Read. */
    public boolean fastSyncRead(int firmware) {
        return fastSyncReadFirmware >= 0 && firmware >= fastSyncReadFirmware;
    }

    /** The model with {@code number} on {@code protocol}, or null when PARPE does not know it. */
    public static ServoModel of(ServoProtocol protocol, int number) {
        for (ServoModel m : TABLE) {
            if (m.protocol == protocol && m.number == number) {
                return m;
            }
        }
        return null;
    }

    /** The model named {@code name} (case-insensitive), or null. */
    public static ServoModel named(String name) {
        for (ServoModel m : TABLE) {
            if (m.name.equalsIgnoreCase(name)) {
                return m;
            }
        }
        return null;
    }

    /** The names of the models of {@code protocol}, for messages. */
    public static String names(ServoProtocol protocol) {
        return String.join(", ", TABLE.stream().filter(m -> m.protocol == protocol).map(ServoModel::name).toList());
    }

    /** The model a bus assumes for {@code protocol} when the servo's own is not known. */
    public static ServoModel defaultFor(ServoProtocol protocol) {
        return named(protocol.defaultModel());
    }

    /** Degrees per tick. */
    public double degreesPerTick() {
        return rangeDeg / resolution;
    }

    /** Lowest servo angle, degrees. */
    public double minDegrees() {
        return (minTick - centre) * degreesPerTick();
    }

    /** Highest servo angle, degrees. */
    public double maxDegrees() {
        return (maxTick - centre) * degreesPerTick();
    }

    /** The servo angle of a position as read from the bus ({@code size} bytes, unsigned). */
    public double degrees(int raw, int size) {
        return (tick(raw, size) - centre) * degreesPerTick();
    }

    /**
     * The tick a position of {@code size} bytes read from the bus or a control table stands for:
     * sign and magnitude where the model uses it (Feetech STS: bit 15 is the sign, as the FTServo
     * SDK's {@code scs_tohost} reads it), two's complement otherwise.
     */
    public int tick(int raw, int size) {
        if (signBit >= 0) {
            int magnitude = raw & ((1 << signBit) - 1);
            return (raw & (1 << signBit)) != 0 ? -magnitude : magnitude;
        }
        return size >= 4 ? raw : (raw << (32 - 8 * size)) >> (32 - 8 * size);
    }

    /**
     * The goal position of servo angle {@code degrees}: rounded to the nearest tick and kept
     * within {@link #minTick}…{@link #maxTick} (never a goal the servo refuses), encoded for the
     * wire (sign and magnitude where the model uses it).
     */
    public int ticks(double degrees) {
        return encode(nearestTick(degrees));
    }

    /** The tick nearest to servo angle {@code degrees}, within {@link #minTick}…{@link #maxTick}, not encoded. */
    public int nearestTick(double degrees) {
        long t = Math.round(centre + degrees / degreesPerTick());
        return (int) Math.max(minTick, Math.min(maxTick, t));
    }

    /** The servo angle of tick {@code t} (not encoded). */
    public double tickDegrees(int t) {
        return (t - centre) * degreesPerTick();
    }

    /** Tick {@code t} (within {@link #minTick}…{@link #maxTick}) as the wire carries it. */
    public int encode(int t) {
        int v = Math.max(minTick, Math.min(maxTick, t));
        return signBit >= 0 && v < 0 ? (1 << signBit) | -v : v;
    }

    /** Model name and number, for messages: {@code xl430-w250 (1060)}. */
    public String label() {
        return String.format(Locale.ROOT, "%s (%d)", name, number);
    }
}
