package org.parpe.serial.servo.emu;

import java.util.Arrays;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.wire.Dxl2Codec;
import org.parpe.serial.servo.wire.Packet;
import org.parpe.serial.servo.wire.PacketCodec;

/**
 * Executes instruction packets on the emulated servos as the manuals describe: Ping, Read, Write,
 * Sync Write, Sync Read, and on Dynamixel 2.0 Bulk Read and Reboot. Servos answer Sync Read and
 * Bulk Read one after the other in the order of the request; nothing answers a broadcast
 * otherwise (except a Dynamixel broadcast Ping). Not thread-safe: the emulator holds its lock.
 */
final class ServoResponder {
    /** Sends one status packet. */
    @FunctionalInterface
    interface Sender {
        void send(byte[] packet, int len);
    }

    /** Dynamixel firmware version reported by Ping. */
    private static final int FIRMWARE = 46;

    private final PacketCodec codec;
    private final EmulatedServo[] servos;
    private final Sender sender;
    private final EmulatorListener listener;
    private final boolean dxl;
    private final int addrBytes;
    private final byte[] out;
    private final byte[] data = new byte[Packet.MAX_PARAMS];
    private final double[] view;
    private int goalWrites;

    ServoResponder(ServoProtocol protocol, PacketCodec codec, EmulatedServo[] servos, Sender sender,
                   EmulatorListener listener) {
        this.codec = codec;
        this.servos = servos;
        this.sender = sender;
        this.listener = listener;
        this.dxl = protocol == ServoProtocol.DXL2;
        this.addrBytes = dxl ? 2 : 1;
        this.out = new byte[codec.bufferSize()];
        this.view = new double[servos.length];
    }

    /** Executes one valid instruction packet received at {@code now}. */
    void execute(Packet p, long now) {
        if (dxl && p.code == PacketCodec.STATUS) {
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
            case PacketCodec.PING -> ping(target, broadcast);
            case PacketCodec.READ -> {
                if (target != null && p.length >= 2 * addrBytes) {
                    readReply(target, p.le(0, addrBytes), p.le(addrBytes, addrBytes));
                }
            }
            case PacketCodec.WRITE -> write(p, target, broadcast);
            case PacketCodec.SYNC_WRITE -> syncWrite(p);
            case PacketCodec.SYNC_READ -> syncRead(p);
            case PacketCodec.BULK_READ -> bulkRead(p);
            case PacketCodec.REBOOT -> {
                if (dxl) {
                    for (EmulatedServo s : servos) {
                        if (broadcast || s == target) {
                            if (!broadcast) {
                                status(s, 0, 0);
                            }
                            s.reboot();
                        }
                    }
                }
            }
            default -> {
                if (target != null && dxl) {
                    status(target, Dxl2Codec.ERROR_INSTRUCTION, 0);
                }
            }
        }
    }

    private EmulatedServo find(int id) {
        for (EmulatedServo s : servos) {
            if (s.id == id) {
                return s;
            }
        }
        return null;
    }

    private void ping(EmulatedServo target, boolean broadcast) {
        for (EmulatedServo s : servos) {
            if (s == target || broadcast && dxl) {
                if (dxl) {
                    PacketCodec.putLe(data, 0, 2, s.model.number());
                    data[2] = (byte) FIRMWARE;
                    status(s, 0, 3);
                } else {
                    status(s, 0, 0);
                }
            }
        }
    }

    private void write(Packet p, EmulatedServo target, boolean broadcast) {
        if (p.length <= addrBytes) {
            return;
        }
        int addr = p.le(0, addrBytes);
        for (EmulatedServo s : servos) {
            if (broadcast || s == target) {
                boolean ok = s.write(addr, p.params, addrBytes, p.length - addrBytes);
                if (!broadcast) {
                    status(s, ok ? 0 : Dxl2Codec.ERROR_ACCESS, 0);
                }
            }
        }
    }

    private void syncWrite(Packet p) {
        if (p.length < 2 * addrBytes) {
            return;
        }
        int addr = p.le(0, addrBytes);
        int len = p.le(addrBytes, addrBytes);
        boolean goal = servos.length > 0 && addr == servos[0].model.registers().goal();
        Arrays.fill(view, Double.NaN);
        for (int off = 2 * addrBytes; off + 1 + len <= p.length; off += 1 + len) {
            int id = p.params[off] & 0xFF;
            for (int i = 0; i < servos.length; i++) {
                EmulatedServo s = servos[i];
                if (s.id == id) {
                    s.heard(System.nanoTime());
                    if (s.write(addr, p.params, off + 1, len) && goal) {
                        view[i] = s.model.degrees(p.le(off + 1, len), len);
                    }
                }
            }
        }
        if (goal) {
            listener.onSetpoints(goalWrites++ & 0xFFFF, view);
        }
    }

    private void syncRead(Packet p) {
        if (p.length < 2 * addrBytes) {
            return;
        }
        int addr = p.le(0, addrBytes);
        int len = p.le(addrBytes, addrBytes);
        for (int off = 2 * addrBytes; off < p.length; off++) {
            EmulatedServo s = find(p.params[off] & 0xFF);
            if (s != null) {
                readReply(s, addr, len);
            }
        }
    }

    private void bulkRead(Packet p) {
        if (!dxl) {
            return;
        }
        for (int off = 0; off + 5 <= p.length; off += 5) {
            EmulatedServo s = find(p.params[off] & 0xFF);
            if (s != null) {
                readReply(s, p.le(off + 1, 2), p.le(off + 3, 2));
            }
        }
    }

    private void readReply(EmulatedServo s, int addr, int len) {
        if (addr < 0 || len < 0 || addr + len > s.table.length) {
            status(s, dxl ? Dxl2Codec.ERROR_ACCESS : 0, 0);
            return;
        }
        System.arraycopy(s.table, addr, data, 0, len);
        status(s, 0, len);
    }

    /** A status packet from {@code s} with {@code errorNumber} (Dynamixel) and {@code data[0…len)}. */
    private void status(EmulatedServo s, int errorNumber, int len) {
        int error = dxl ? (s.hardwareError() != 0 ? Dxl2Codec.ERROR_ALERT : 0) | errorNumber : s.hardwareError();
        int n = codec.status(out, s.id, error, data, len);
        sender.send(out, n);
    }
}
