package org.parpe.serial.servo.emu;

import java.util.Arrays;
import org.parpe.serial.dynamixel.Dxl2Codec;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.wire.Packet;
import org.parpe.serial.servo.wire.PacketCodec;

/**
 * Executes instruction packets on the emulated servos as the manuals describe: Ping, Read, Write,
 * Reg Write and Action, Sync Write, Sync Read (not on SCS, which has none), and on Dynamixel 2.0
 * Bulk Read, Bulk Write, Reboot and Fast Sync Read (one status packet from all, where the model
 * and firmware have it). Each status packet leaves after the servo's Return Delay Time
 * (e-Manual, X series, Return Delay Time(9)); servos answer Sync Read and Bulk Read one after the
 * other in the order of the request, each its Return Delay Time after the one before, and a
 * broadcast Ping in the order of their IDs, servo ID k in the k-th reply slot of {@link #SLOT_NANOS}
 * (e-Manual, Protocol 2.0, Ping: "All devices send their Status Packet according to their arranged
 * order"). Status Return Level is honoured; nothing answers a broadcast otherwise. Not
 * thread-safe: the emulator holds its lock.
 */
final class ServoResponder {
    /** Sends one status packet {@code wait} ns after the one before (or, when {@code fromRequest}, after the request). */
    @FunctionalInterface
    interface Sender {
        void send(byte[] packet, int len, long wait, boolean fromRequest);
    }

    /** Reply slot per ID after a broadcast Ping: the time ROBOTIS's DynamixelSDK allows each ID (3 ms). */
    static final long SLOT_NANOS = 3_000_000;

    private final PacketCodec codec;
    /** The Dynamixel codec, which builds the Fast Sync Read status; null on Feetech. */
    private final Dxl2Codec dxlCodec;
    /** Error, ID and data of each servo's block of a Fast Sync Read status. */
    private final byte[] blocks = new byte[Packet.MAX_PARAMS];
    private final EmulatedServo[] servos;
    private final EmulatedServo[] byId;
    private final Sender sender;
    private final EmulatorListener listener;
    private final ServoProtocol protocol;
    private final int addrBytes;
    private final byte[] out;
    private final byte[] data = new byte[Packet.MAX_PARAMS];
    private final double[] view;
    private int goalWrites;

    ServoResponder(ServoProtocol protocol, PacketCodec codec, EmulatedServo[] servos, Sender sender,
                   EmulatorListener listener) {
        this.codec = codec;
        this.dxlCodec = codec instanceof Dxl2Codec d ? d : null;
        this.servos = servos;
        this.byId = servos.clone();
        this.sender = sender;
        this.listener = listener;
        this.protocol = protocol;
        this.addrBytes = codec.addressBytes();
        this.out = new byte[codec.bufferSize()];
        this.view = new double[servos.length];
    }

    /** Executes one valid instruction packet received at {@code now}. */
    void execute(Packet p, long now) {
        if (codec.marksStatus() && p.code == PacketCodec.STATUS) {
            return;
        }
        boolean broadcast = p.id == PacketCodec.BROADCAST;
        EmulatedServo target = broadcast ? null : find(p.id);
        if (!broadcast && target == null) {
            return;
        }
        for (EmulatedServo s : servos) {
            if (broadcast || s == target) {
                s.heard(now);
            }
        }
        switch (p.code) {
            case PacketCodec.PING -> ping(target);
            case PacketCodec.READ -> {
                if (target != null && p.length >= 2 * addrBytes && target.answers(false, true)) {
                    readReply(target, p.le(0, addrBytes), p.le(addrBytes, addrBytes), true);
                }
            }
            case PacketCodec.WRITE, PacketCodec.REG_WRITE -> write(p, target, p.code == PacketCodec.REG_WRITE);
            case PacketCodec.ACTION -> action(target);
            case PacketCodec.SYNC_WRITE -> syncWrite(p);
            case PacketCodec.SYNC_READ -> {
                if (protocol.syncRead()) {
                    syncRead(p);
                }
            }
            case PacketCodec.BULK_READ -> bulkRead(p);
            case PacketCodec.FAST_SYNC_READ -> {
                if (codec.knows(PacketCodec.FAST_SYNC_READ)) {
                    fastSyncRead(p);
                }
            }
            case PacketCodec.BULK_WRITE -> bulkWrite(p);
            case PacketCodec.REBOOT -> reboot(target);
            default -> {
                if (target != null && codec.errorNumbers()) {
                    status(target, EmulatedServo.INSTRUCTION_ERROR, 0, target.returnDelayNanos(), true);
                }
            }
        }
    }

    private EmulatedServo find(int id) {
        for (EmulatedServo s : servos) {
            if (s.id() == id) {
                return s;
            }
        }
        return null;
    }

    /**
     * A Ping: the servo named answers; to a broadcast Ping every Dynamixel and STS servo answers,
     * in the order of their IDs, each in its reply slot.
     */
    private void ping(EmulatedServo target) {
        if (target != null) {
            pingReply(target, target.returnDelayNanos());
            return;
        }
        if (!protocol.answersBroadcastPing()) {
            return;
        }
        java.util.Arrays.sort(byId, (a, b) -> Integer.compare(a.id(), b.id()));
        for (EmulatedServo s : byId) {
            pingReply(s, s.returnDelayNanos() + s.id() * SLOT_NANOS);
        }
    }

    private void pingReply(EmulatedServo s, long at) {
        if (codec.pingReplyParams() > 0) {
            // Model number (2 bytes) and firmware version, read from the servo's own table.
            s.read(0, 2, data);
            data[2] = s.table[s.ct.named("Firmware Version").addr()];
            status(s, 0, 3, at, true);
        } else {
            status(s, 0, 0, at, true);
        }
    }

    private void write(Packet p, EmulatedServo target, boolean registered) {
        if (p.length <= addrBytes) {
            return;
        }
        int addr = p.le(0, addrBytes);
        int len = p.length - addrBytes;
        for (EmulatedServo s : servos) {
            if (target == null || s == target) {
                int e = registered ? s.register(addr, p.params, addrBytes, len) : s.write(addr, p.params, addrBytes, len);
                if (target != null && s.answers(false, false)) {
                    status(s, e, 0, s.returnDelayNanos(), true);
                }
            }
        }
    }

    private void action(EmulatedServo target) {
        for (EmulatedServo s : servos) {
            if (target == null || s == target) {
                boolean done = s.action();
                if (target != null && s.answers(false, false)) {
                    status(s, done ? 0 : EmulatedServo.INSTRUCTION_ERROR, 0, s.returnDelayNanos(), true);
                }
            }
        }
    }

    private void reboot(EmulatedServo target) {
        if (!codec.knows(PacketCodec.REBOOT)) {
            return;
        }
        for (EmulatedServo s : servos) {
            if (target == null || s == target) {
                if (target != null) {
                    status(s, 0, 0, s.returnDelayNanos(), true);
                }
                s.reboot();
            }
        }
    }

    /**
     * Sync Write: {@code addr, len}, then {@code id, data…} per servo. The listener hears the
     * goals (read back from each servo's table, so in its own byte order) when the written range
     * holds the goal position, whatever address it starts at.
     */
    private void syncWrite(Packet p) {
        if (p.length < 2 * addrBytes) {
            return;
        }
        int addr = p.le(0, addrBytes);
        int len = p.le(addrBytes, addrBytes);
        boolean goal = false;
        java.util.Arrays.fill(view, Double.NaN);
        for (int off = 2 * addrBytes; off + 1 + len <= p.length; off += 1 + len) {
            int id = p.params[off] & 0xFF;
            for (int i = 0; i < servos.length; i++) {
                EmulatedServo s = servos[i];
                if (s.id() == id) {
                    s.heard(System.nanoTime());
                    if (s.write(addr, p.params, off + 1, len) == EmulatedServo.OK && s.setsGoal(addr, len)) {
                        view[i] = s.goalDegrees();
                        goal = true;
                    }
                }
            }
        }
        if (goal) {
            listener.onSetpoints(goalWrites++ & 0xFFFF, view);
        }
    }

    /** Dynamixel Bulk Write: {@code id, addr (2), len (2), data…} per servo. */
    private void bulkWrite(Packet p) {
        if (!codec.knows(PacketCodec.BULK_WRITE)) {
            return;
        }
        for (int off = 0; off + 5 <= p.length; ) {
            int len = p.le(off + 3, 2);
            if (off + 5 + len > p.length) {
                return;
            }
            EmulatedServo s = find(p.params[off] & 0xFF);
            if (s != null) {
                s.heard(System.nanoTime());
                s.write(p.le(off + 1, 2), p.params, off + 5, len);
            }
            off += 5 + len;
        }
    }

    private void syncRead(Packet p) {
        if (p.length < 2 * addrBytes) {
            return;
        }
        int addr = p.le(0, addrBytes);
        int len = p.le(addrBytes, addrBytes);
        boolean first = true;
        for (int off = 2 * addrBytes; off < p.length; off++) {
            EmulatedServo s = find(p.params[off] & 0xFF);
            if (s != null && s.answers(false, true)) {
                readReply(s, addr, len, first);
                first = false;
            }
        }
    }

    /**
     * Fast Sync Read: {@code addr, len} and IDs as Sync Read, answered by one status packet from
     * the broadcast ID to which each servo named adds its block in the order of the request
     * (e-Manual, Protocol 2.0, Fast Sync Read). The packet leaves after the first servo's Return
     * Delay Time. A servo named that is absent or does not answer reads breaks the chain: the
     * packet stops before its block and never completes. A servo without Fast Sync Read (XL-320,
     * older firmware) takes it for an unknown instruction and answers on its own with an
     * Instruction Error.
     */
    private void fastSyncRead(Packet p) {
        if (p.length < 4) {
            return;
        }
        int addr = p.le(0, 2);
        int len = p.le(2, 2);
        int n = p.length - 4;
        if ((long) n * (len + 4) + 16 > out.length || (long) n * (len + 2) > blocks.length) {
            return;
        }
        int sent = 0;
        boolean broken = false;
        long wait = 0;
        for (int k = 0; k < n; k++) {
            EmulatedServo s = find(p.params[4 + k] & 0xFF);
            if (s != null && !s.fastSyncRead()) {
                status(s, EmulatedServo.INSTRUCTION_ERROR, 0, s.returnDelayNanos(), true);
            }
            broken |= s == null || !s.fastSyncRead() || !s.answers(false, true);
            if (!broken) {
                int at = sent * (len + 2);
                int e = s.read(addr, len, data);
                if (e != EmulatedServo.OK) {
                    java.util.Arrays.fill(data, 0, len, (byte) 0);
                }
                blocks[at] = (byte) ((s.hardwareError() != 0 ? Dxl2Codec.ERROR_ALERT : 0) | e);
                blocks[at + 1] = (byte) s.id();
                System.arraycopy(data, 0, blocks, at + 2, len);
                wait = sent++ == 0 ? s.returnDelayNanos() : wait;
            }
        }
        if (sent > 0) {
            sender.send(out, dxlCodec.fastStatus(out, blocks, len, n, sent), wait, true);
        }
    }

    private void bulkRead(Packet p) {
        if (!codec.knows(PacketCodec.BULK_READ)) {
            return;
        }
        boolean first = true;
        for (int off = 0; off + 5 <= p.length; off += 5) {
            EmulatedServo s = find(p.params[off] & 0xFF);
            if (s != null && s.answers(false, true)) {
                readReply(s, p.le(off + 1, 2), p.le(off + 3, 2), first);
                first = false;
            }
        }
    }

    private void readReply(EmulatedServo s, int addr, int len, boolean first) {
        int e = len <= data.length ? s.read(addr, len, data) : EmulatedServo.ACCESS_ERROR;
        if (e != EmulatedServo.OK) {
            status(s, e, 0, s.returnDelayNanos(), first);
            return;
        }
        status(s, 0, len, s.returnDelayNanos(), first);
    }

    /** A status packet from {@code s} with {@code errorNumber} (Dynamixel) and {@code data[0…len)}. */
    private void status(EmulatedServo s, int errorNumber, int len, long wait, boolean fromRequest) {
        int error = codec.statusByte(s.hardwareError(), errorNumber);
        int n = codec.status(out, s.id(), error, data, len);
        sender.send(out, n, wait, fromRequest);
    }
}
