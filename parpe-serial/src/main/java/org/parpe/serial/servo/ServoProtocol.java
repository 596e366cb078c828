package org.parpe.serial.servo;

import java.util.List;
import java.util.function.Supplier;
import org.parpe.serial.dynamixel.Dxl2Codec;
import org.parpe.serial.feetech.FeetechCodec;
import org.parpe.serial.servo.wire.PacketCodec;

/**
 * The servo bus protocols, with the name used on the command line and in hardware profiles and
 * the baud rates a scan tries when none is given (most common first). What differs between
 * them is data here (byte order, default model, what a device is called) or the family's
 * {@link PacketCodec} ({@link #codec}), never a comparison with one of the constants: a new
 * protocol is one more constant, and the compiler asks for what its codec must answer.
 */
public enum ServoProtocol {
    /** PARPE's reconstructed PolyBot G1 module bus (docs/hardware-protocol.md). */
    G1("g1", 254, false, List.of(115_200, 1_000_000, 57_600, 9_600), true, false, false, false,
            "g1-segment", null),
    /** Dynamixel Protocol 2.0 (X series: XL330, XL430, XM430, …). */
    DXL2("dxl2", 252, true, List.of(57_600, 1_000_000, 115_200, 2_000_000, 3_000_000, 4_000_000, 9_600), false,
            true, true, false, "xl430-w250", Dxl2Codec::new),
    /** Feetech STS series (STS3215, …): little-endian control table. */
    STS("sts", 253, true, List.of(1_000_000, 500_000, 115_200, 57_600, 250_000, 128_000, 76_800, 38_400), false,
            true, true, false, "sts3215", FeetechCodec::new),
    /**
     * Feetech SCS series (SCS15, SCS0009, …): big-endian control table, no Sync Read, no answer
     * to a broadcast Ping.
     */
    SCS("scs", 253, true, List.of(1_000_000, 500_000, 115_200, 57_600, 250_000, 128_000, 76_800, 38_400), false,
            false, false, true, "scs0009", FeetechCodec::new);

    private final String key;
    private final int maxId;
    private final boolean groupRead;
    private final List<Integer> scanBauds;
    private final boolean modules;
    private final boolean syncRead;
    private final boolean answersBroadcastPing;
    private final boolean bigEndian;
    private final String defaultModel;
    private final Supplier<PacketCodec> codec;

    ServoProtocol(String key, int maxId, boolean groupRead, List<Integer> scanBauds, boolean modules,
                  boolean syncRead, boolean answersBroadcastPing, boolean bigEndian, String defaultModel,
                  Supplier<PacketCodec> codec) {
        this.key = key;
        this.maxId = maxId;
        this.groupRead = groupRead;
        this.scanBauds = scanBauds;
        this.modules = modules;
        this.syncRead = syncRead;
        this.answersBroadcastPing = answersBroadcastPing;
        this.bigEndian = bigEndian;
        this.defaultModel = defaultModel;
        this.codec = codec;
    }

    /**
     * Whether the devices on this bus are PolyBot modules, whose bus ID is their PARSL module ID
     * (G1), rather than servos mapped to modules by a profile.
     */
    public boolean modules() {
        return modules;
    }

    /**
     * Whether the bus is a servo control table reached by packets of a {@link #codec} (Dynamixel
     * 2.0, Feetech), rather than G1's own frames ({@code org.parpe.serial.g1}).
     */
    public boolean controlTable() {
        return codec != null;
    }

    /**
     * A new codec of this control-table protocol's packets.
     *
     * @throws IllegalStateException for G1, which is no control-table protocol
     */
    public PacketCodec codec() {
        if (codec == null) {
            throw new IllegalStateException(key + " is not a control-table protocol");
        }
        return codec.get();
    }

    /**
     * Whether multi-byte control-table values are big-endian (Feetech SCS); little-endian on
     * Dynamixel 2.0 and Feetech STS.
     */
    public boolean bigEndian() {
        return bigEndian;
    }

    /**
     * Whether one Sync Read asks every servo: true but on Feetech SCS, whose servos are read by
     * READs queued in one write, and on G1, which reads one module at a time.
     */
    public boolean syncRead() {
        return syncRead;
    }

    /**
     * Whether every servo answers a broadcast Ping, in the order of its ID (Dynamixel 2.0 and
     * Feetech STS; not SCS, nor G1 modules, which never reply to the broadcast address).
     */
    public boolean answersBroadcastPing() {
        return answersBroadcastPing;
    }

    /** The name of the model a bus assumes when the servo's own is not known. */
    public String defaultModel() {
        return defaultModel;
    }

    /** The name on the command line and in profiles: g1, dxl2, sts, scs. */
    public String key() {
        return key;
    }

    /**
     * The highest servo ID: 252 on Dynamixel 2.0 (e-Manual, Protocol 2.0, Packet ID: 0–252; 253
     * and 255 would look like header bytes, 254 is broadcast), 253 on Feetech (254 is broadcast),
     * 254 on G1.
     */
    public int maxId() {
        return maxId;
    }

    /**
     * Whether a run reads every servo each read cycle, because one write asks them all (Sync Read
     * on Dynamixel 2.0 and Feetech STS, the SCS servos' READs queued in one write) and their
     * replies follow each other at once. G1 modules are read one READ transaction at a time,
     * each waiting for its reply: a run reads one module per read cycle, round robin, so that a
     * setpoint frame never waits for more than one read.
     */
    public boolean groupRead() {
        return groupRead;
    }

    /** Baud rates a scan tries, most common (the factory default) first. */
    public List<Integer> scanBauds() {
        return scanBauds;
    }

    /** The protocol named {@code key}, or null. */
    public static ServoProtocol of(String key) {
        for (ServoProtocol p : values()) {
            if (p.key.equals(key)) {
                return p;
            }
        }
        return null;
    }

    /** The names, for messages: {@code g1, dxl2, sts, scs}. */
    public static String keys() {
        return String.join(", ", java.util.Arrays.stream(values()).map(ServoProtocol::key).toList());
    }
}
