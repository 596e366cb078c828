package org.parpe.serial.servo.wire;

/**
 * The packet format of one servo protocol: encodes instruction and status packets into a
 * caller's buffer (at least {@link #bufferSize} bytes) and makes stream decoders. Instruction
 * codes are the same on both protocols for what PARPE uses.
 */
public interface PacketCodec {
    /** Broadcast ID: every servo executes, none replies (except to Sync Read and Bulk Read). */
    int BROADCAST = 0xFE;
    /** Ping: the servo replies (Dynamixel 2.0: model number and firmware version). */
    int PING = 0x01;
    /** Read {@code addr, len} from the control table. */
    int READ = 0x02;
    /** Write {@code addr, data…} to the control table. */
    int WRITE = 0x03;
    /** Reg Write: a Write kept until Action. */
    int REG_WRITE = 0x04;
    /** Action: carries out the kept Reg Write. */
    int ACTION = 0x05;
    /** Dynamixel 2.0 Reboot: restarts the servo, which clears a hardware error. */
    int REBOOT = 0x08;
    /** Sync Read: the same {@code addr, len} from several servos, each replies in turn. */
    int SYNC_READ = 0x82;
    /** Sync Write: the same {@code addr, len} to several servos, {@code id, data…} each; no reply. */
    int SYNC_WRITE = 0x83;
    /**
     * Dynamixel 2.0 Fast Sync Read: asked like Sync Read, answered by one status packet from the
     * broadcast ID that every servo adds its block to ({@link org.parpe.serial.dynamixel.Dxl2Codec#fastStatus}).
     */
    int FAST_SYNC_READ = 0x8A;
    /** Dynamixel 2.0 Bulk Read: {@code id, addr, len} per servo, each replies in turn. */
    int BULK_READ = 0x92;
    /** Dynamixel 2.0 Bulk Write: {@code id, addr, len, data…} per servo. */
    int BULK_WRITE = 0x93;
    /** Dynamixel 2.0: the instruction field of a status packet. */
    int STATUS = 0x55;

    /** Largest packet this codec builds, stuffing included. */
    default int bufferSize() {
        return 2 * Packet.MAX_PARAMS + 16;
    }

    /** Builds an instruction packet in {@code out}; returns its length. */
    int instruction(byte[] out, int id, int instruction, byte[] params, int len);

    /** Builds a status packet with error byte {@code error} in {@code out}; returns its length. */
    int status(byte[] out, int id, int error, byte[] params, int len);

    /** A new decoder handing packets to {@code handler}. */
    PacketDecoder decoder(PacketHandler handler);

    /** The error byte of a received status packet. */
    int statusError(Packet p);

    /** Bytes on the wire of a packet with {@code params} parameters (without stuffing). */
    int packetLength(int params);

    // What tells the families apart: each codec answers for its family, so that the host
    // driver and the emulator never compare protocols.

    /**
     * The facts of a family that are one value each.
     *
     * @param family in messages: {@code Dynamixel}, {@code Feetech}
     * @param addressBytes bytes of a control-table address, and of a length, in instruction parameters
     * @param pingReplyParams parameters of a reply to Ping: the model number (2 bytes) and firmware
     *     version on Dynamixel 2.0 (e-Manual, Protocol 2.0, Ping: Parameters 1–3); none on Feetech,
     *     whose model is read from the control table
     * @param marksStatus whether a status packet is told from an instruction by its instruction
     *     field ({@link #STATUS}, Dynamixel 2.0): the host then ignores other packets it hears (its
     *     own, echoed by a half-duplex adapter); on Feetech that field is the status packet's error byte
     * @param broadcastPing whether the servos answer a broadcast Ping one after another in ID order,
     *     so that a scan asks them all at once (Dynamixel 2.0); Feetech servos are pinged one by one
     * @param errorNumbers whether the error byte of a status packet numbers what was wrong with the
     *     instruction (Dynamixel 2.0: instruction, data range, access error …), so that a servo
     *     refuses a bad write with an error; Feetech servos ignore a write to a read-only address
     *     and keep a goal inside their limits instead
     * @param busWatchdog whether the servos stop on their own when the host falls silent (Dynamixel
     *     Bus Watchdog, e-Manual, X series, Bus Watchdog(98)); Feetech servos hold their last goal
     */
    record Traits(String family, int addressBytes, int pingReplyParams, boolean marksStatus,
            boolean broadcastPing, boolean errorNumbers, boolean busWatchdog) {
    }

    /** This codec's family facts. */
    Traits traits();

    /** {@link Traits#family}. */
    default String family() {
        return traits().family();
    }

    /** {@link Traits#addressBytes}. */
    default int addressBytes() {
        return traits().addressBytes();
    }

    /** {@link Traits#pingReplyParams}. */
    default int pingReplyParams() {
        return traits().pingReplyParams();
    }

    /** {@link Traits#marksStatus}. */
    default boolean marksStatus() {
        return traits().marksStatus();
    }

    /** {@link Traits#broadcastPing}. */
    default boolean broadcastPing() {
        return traits().broadcastPing();
    }

    /**
     * Whether the family's servos carry out {@code instruction}, one of the codes above: Reboot,
     * Fast Sync Read, Bulk Read and Bulk Write are Dynamixel 2.0's. (Sync Read also depends on
     * the series: {@code ServoProtocol.syncRead}.)
     */
    boolean knows(int instruction);

    /** {@link Traits#errorNumbers}. */
    default boolean errorNumbers() {
        return traits().errorNumbers();
    }

    /** The error byte of a status packet from a servo with these hardware error bits and error number. */
    int statusByte(int hardwareError, int errorNumber);

    /**
     * Whether a servo with status level {@code level} answers a Read ({@code read}) or another
     * instruction other than Ping, which is always answered: Dynamixel Status Return Level 0
     * answers Ping only, 1 also Read, 2 everything (e-Manual, X series, Status Return Level(68));
     * Feetech Response Status Level 0 answers Ping and Read only, 1 everything.
     */
    boolean answers(int level, boolean read);

    /** {@link Traits#busWatchdog}. */
    default boolean busWatchdog() {
        return traits().busWatchdog();
    }

    /**
     * Whether a non-zero status error byte reports a fault of the servo: on Dynamixel 2.0 only
     * with the alert bit (the low bits number an error of the packet); on Feetech every bit is one.
     */
    boolean faulty(int statusError);

    /** The error of a packet a status error byte names in words ({@code CRC error}), or null for none. */
    String packetError(int statusError);

    /** An unsigned little-endian value of {@code size} bytes of {@code b} at {@code off}. */
    static int le(byte[] b, int off, int size) {
        int v = 0;
        for (int i = size - 1; i >= 0; i--) {
            v = v << 8 | (b[off + i] & 0xFF);
        }
        return v;
    }

    /** Writes {@code v} as {@code size} little-endian bytes into {@code b} at {@code off}. */
    static void putLe(byte[] b, int off, int size, int v) {
        for (int i = 0; i < size; i++) {
            b[off + i] = (byte) (v >>> 8 * i);
        }
    }
}
