package org.parpe.serial.servo;

import java.util.List;

/**
 * The servo bus protocols, with the name used on the command line and in hardware profiles and
 * the baud rates a scan tries when none is given (most common first).
 */
public enum ServoProtocol {
    /** PARPE's reconstructed PolyBot G1 module bus (docs/hardware-protocol.md). */
    G1("g1", 254, false, List.of(115_200, 1_000_000, 57_600, 9_600)),
    /** Dynamixel Protocol 2.0 (X series: XL330, XL430, XM430, …). */
    DXL2("dxl2", 252, true, List.of(57_600, 1_000_000, 115_200, 2_000_000, 3_000_000, 4_000_000, 9_600)),
    /** Feetech STS series (STS3215, …): little-endian control table. */
    STS("sts", 253, true, List.of(1_000_000, 500_000, 115_200, 57_600, 250_000, 128_000, 76_800, 38_400)),
    /** Feetech SCS series (SCS15, SCS0009, …): big-endian control table. */
    SCS("scs", 253, true, List.of(1_000_000, 500_000, 115_200, 57_600, 250_000, 128_000, 76_800, 38_400));

    private final String key;
    private final int maxId;
    private final boolean groupRead;
    private final List<Integer> scanBauds;

    ServoProtocol(String key, int maxId, boolean groupRead, List<Integer> scanBauds) {
        this.key = key;
        this.maxId = maxId;
        this.groupRead = groupRead;
        this.scanBauds = scanBauds;
    }

    /**
     * What one device on this bus is called in messages: "module" for G1, whose devices are
     * PolyBot modules (their bus ID is their PARSL module ID), "servo" for the others.
     */
    public String unit() {
        return this == G1 ? "module" : "servo";
    }

    /** What one packet on this bus is called in messages: "frame" for G1, "packet" for the others. */
    public String packet() {
        return this == G1 ? "frame" : "packet";
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
