package org.parpe.serial.servo.host;

import org.parpe.serial.text.SerialMsg;
import java.io.IOException;
import org.parpe.serial.link.ByteLink;
import org.parpe.serial.servo.Registers;
import org.parpe.serial.servo.ServoBus;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.wire.Packet;
import org.parpe.serial.servo.wire.PacketCodec;

/**
 * The host end of a control-table servo bus (Dynamixel Protocol 2.0, Feetech STS or SCS). Goals
 * and torque go out as one Sync Write per register layout; positions come back by Sync Read
 * (Dynamixel, STS), Fast Sync Read (Dynamixel servos whose model and pinged firmware have it: one
 * status packet instead of one per servo), Bulk Read (Dynamixel servos with different layouts on
 * one bus) or one Read per servo (SCS, which has no Sync Read). Requests and replies go through a
 * {@link PacketPort}.
 */
public final class ControlTableBus implements ServoBus {
    /** Bus Watchdog after it tripped: −1 in one byte. */
    private static final int WATCHDOG_TRIPPED = 0xFF;
    /** Bytes of a Dynamixel 2.0 Ping status packet (header 4, ID, length 2, instruction, error, 3 parameters, CRC 2). */
    private static final int PING_STATUS_BYTES = 14;
    /**
     * A scan first waits for the line to be quiet this long (at most {@link #FLUSH_MAX_MS}): far
     * longer than servos take to finish answering requests already sent.
     */
    private static final long FLUSH_QUIET_MS = 50;
    private static final long FLUSH_MAX_MS = 500;
    /** Group reads every servo answers by Sync Read before a Fast Sync Read is tried again after one broke. */
    private static final int FAST_RETRY_READS = 100;

    private final ServoProtocol protocol;
    private final int baud;
    private final boolean bigEndian;
    private final PacketCodec codec;
    private final PacketPort port;
    private final byte[] params = new byte[Packet.MAX_PARAMS];
    private final int[] replyIds = new int[256];
    private final java.util.List<Registers> layouts = new java.util.ArrayList<>(2);
    /** Firmware version each ID's last Ping reply reported (Dynamixel), −1 before one. */
    private final int[] firmware = new int[256];
    /** Group reads by Sync Read still to go before Fast Sync Read is tried again (0: it is used). */
    private int fastPause;

    /** Starts talking {@code protocol} (not G1) over {@code link} running at {@code baud}. */
    public ControlTableBus(ServoProtocol protocol, ByteLink link, int baud, int timeoutMs) {
        if (!protocol.controlTable()) {
            throw new IllegalArgumentException(protocol.name() + " is not a control-table protocol; use G1Bus");
        }
        this.protocol = protocol;
        this.baud = baud;
        this.bigEndian = protocol.bigEndian();
        this.codec = protocol.codec();
        this.port = new PacketPort(link, codec, bigEndian, baud, timeoutMs);
        java.util.Arrays.fill(firmware, -1);
    }

    @Override
    public ServoProtocol protocol() {
        return protocol;
    }

    @Override
    public String name() {
        return port.name();
    }

    @Override
    public int ping(int id, int attempts) throws IOException {
        for (int a = 0; a < attempts; a++) {
            if (port.request(id, PacketCodec.PING, params, 0, id) && pingReply(id)) {
                if (codec.pingReplyParams() > 0) {
                    firmware[id] = port.value(id) >>> 16 & 0xFF;
                    return port.value(id) & 0xFFFF;
                }
                int model = read(id, Registers.FEETECH.model(), 2, attempts - a);
                return model == Integer.MIN_VALUE ? 0 : model;
            }
        }
        return -1;
    }

    /**
     * Whether servo {@code id}'s last status packet has the shape of a reply to Ping: on
     * Dynamixel 2.0 exactly model number (2 bytes) and firmware version (e-Manual, Protocol 2.0,
     * Ping: Parameters 1–3), on Feetech no parameter. Anything else is a late reply to another
     * request (an interrupted run's position read) and says nothing about the servo's model.
     */
    private boolean pingReply(int id) {
        return port.size(id) == codec.pingReplyParams();
    }

    /**
     * Input is flushed first (an interrupted run's replies must not read as servos). On
     * Dynamixel 2.0 a broadcast Ping, which every servo answers in the order of its ID after its
     * Return Delay Time (e-Manual, Protocol 2.0, Ping), listened to for as long as ROBOTIS's SDK
     * does ({@link #broadcastPingNanos}), twice (a reply lost to noise is not a missing servo),
     * merging the answers. Feetech servos are pinged one by one.
     */
    @Override
    public int[] scan(int[] ids) throws IOException {
        port.flushInput(FLUSH_QUIET_MS, FLUSH_MAX_MS);
        if (!codec.broadcastPing()) {
            return ServoBus.super.scan(ids);
        }
        int[] models = new int[ids.length];
        java.util.Arrays.fill(models, -1);
        int highest = 0;
        for (int id : ids) {
            highest = Math.max(highest, id);
        }
        long listen = broadcastPingNanos(baud, ids.length, highest);
        for (int pass = 0; pass < 2; pass++) {
            port.requestAll(PacketCodec.BROADCAST, PacketCodec.PING, params, 0, ids, ids.length, listen);
            for (int i = 0; i < ids.length; i++) {
                if (port.got(ids[i]) && pingReply(ids[i]) && models[i] < 0) {
                    models[i] = port.value(ids[i]) & 0xFFFF;
                    firmware[ids[i]] = port.value(ids[i]) >>> 16 & 0xFF;
                }
            }
        }
        return models;
    }

    /**
     * How long to listen after a broadcast Ping for {@code n} servos up to ID {@code highest}:
     * every Ping status (14 bytes) on the wire, plus one reply slot per ID up to the highest
     * (the servos answer in ID order), plus 16 ms, as ROBOTIS's DynamixelSDK does
     * (protocol2_packet_handler broadcastPing: 3 ms per ID). A slot is 3 ms or, on slow lines,
     * the longest Return Delay Time (508 µs) plus one status packet, whichever is longer.
     */
    static long broadcastPingNanos(int baud, int n, int highest) {
        long perByte = 10_000_000_000L / baud;
        long slot = Math.max(3_000_000L, 508_000L + PING_STATUS_BYTES * perByte);
        return PING_STATUS_BYTES * perByte * n + slot * (highest + 1) + 16_000_000L;
    }

    /** Reads {@code size} bytes at {@code addr} of servo {@code id}: the value, or {@link Integer#MIN_VALUE}. */
    public int read(int id, int addr, int size, int attempts) throws IOException {
        for (int a = 0; a < attempts; a++) {
            int n = putAddress(0, addr, size);
            // Exactly the bytes asked for: a late reply to another request (a position read that
            // timed out) must not pass for this one.
            if (port.request(id, PacketCodec.READ, params, n, id) && port.size(id) == size) {
                return port.value(id);
            }
        }
        return Integer.MIN_VALUE;
    }

    /**
     * Writes {@code v} ({@code size} bytes) at {@code addr} of servo {@code id} with up to
     * {@code attempts} tries; true when it acknowledged without error.
     */
    public boolean write(int id, int addr, int size, int v, int attempts) throws IOException {
        for (int a = 0; a < attempts; a++) {
            int n = putAddress(0, addr, -1);
            n = put(n, v, size);
            if (port.request(id, PacketCodec.WRITE, params, n, id)) {
                return port.error(id) == 0;
            }
        }
        return false;
    }

    @Override
    public void torque(int[] ids, ServoModel[] models, int n, boolean on) throws IOException {
        for (Registers r : layouts(models, n)) {
            syncWrite(r.torque(), 1, ids, models, null, on ? 1 : 0, n, r, false);
        }
    }

    @Override
    public int torqueState(int id, ServoModel model, int attempts) throws IOException {
        int v = read(id, model.registers().torque(), 1, attempts);
        return v == Integer.MIN_VALUE ? NO_REPLY : v == 0 ? 0 : 1;
    }

    /**
     * The goals, torque on, and the goals again: a servo that takes its present position as its
     * goal when its torque comes on (as the emulator's X series do) still ends at the goal given,
     * inside its limits.
     */
    @Override
    public void holdAt(int[] ids, ServoModel[] models, int[] ticks, int n) throws IOException {
        writeGoals(ids, models, ticks, n);
        torque(ids, models, n, true);
        writeGoals(ids, models, ticks, n);
    }

    @Override
    public void writeGoals(int[] ids, ServoModel[] models, int[] ticks, int n) throws IOException {
        for (Registers r : layouts(models, n)) {
            syncWrite(r.goal(), r.goalSize(), ids, models, ticks, 0, n, r, false);
        }
    }

    /** The Sync Writes of the goals are held back and leave in one write with the first read request. */
    @Override
    public int writeGoalsAndRead(int[] ids, ServoModel[] models, int[] ticks, int n, double[] degrees, int[] errors)
            throws IOException {
        for (Registers r : layouts(models, n)) {
            syncWrite(r.goal(), r.goalSize(), ids, models, ticks, 0, n, r, true);
        }
        return readPositions(ids, models, n, degrees, errors);
    }

    @Override
    public int readPositions(int[] ids, ServoModel[] models, int n, double[] degrees, int[] errors) throws IOException {
        java.util.List<Registers> layouts = layouts(models, n);
        int expected = 0;
        if (!protocol.syncRead()) {
            for (Registers r : layouts) {
                int k = putAddress(0, r.present(), r.presentSize());
                expected = 0;
                for (int i = 0; i < n; i++) {
                    if (models[i].registers() == r) {
                        replyIds[expected++] = ids[i];
                    }
                }
                port.requestEach(PacketCodec.READ, params, k, replyIds, expected);
            }
        } else if (layouts.size() == 1 || !codec.knows(PacketCodec.BULK_READ)) {
            for (Registers r : layouts) {
                int k = putAddress(0, r.present(), r.presentSize());
                expected = 0;
                boolean fast = codec.knows(PacketCodec.FAST_SYNC_READ);
                for (int i = 0; i < n; i++) {
                    if (models[i].registers() == r) {
                        params[k++] = (byte) ids[i];
                        replyIds[expected++] = ids[i];
                        fast &= models[i].fastSyncRead(firmware[ids[i]]);
                    }
                }
                syncRead(k, r.presentSize(), expected, fast);
            }
        } else {
            int k = 0;
            for (int i = 0; i < n; i++) {
                Registers r = models[i].registers();
                params[k++] = (byte) ids[i];
                k = putAddress(k, r.present(), r.presentSize());
            }
            port.requestAll(PacketCodec.BROADCAST, PacketCodec.BULK_READ, params, k, ids, n);
        }
        int answered = 0;
        for (int i = 0; i < n; i++) {
            int id = ids[i];
            int size = models[i].registers().presentSize();
            if (!port.got(id) || port.size(id) != size) {
                errors[i] = NO_REPLY;
            } else {
                degrees[i] = models[i].degrees(port.value(id), size);
                errors[i] = port.error(id);
                answered++;
            }
        }
        return answered;
    }

    /**
     * Reads servos {@code replyIds[0…n)}, whose Sync Read parameters ({@code k} bytes) are ready:
     * by Fast Sync Read when {@code fast} (each has it) and more than one is read (for one it
     * costs a byte more), else by Sync Read. A Fast Sync Read left unfinished is followed at once
     * by a Sync Read of the same servos, so that the positions of those that answer are not lost
     * (holding where they are needs them). When one of them is silent too, it would break every
     * Fast Sync Read's chain of blocks: the next group reads are Sync Reads until
     * {@value #FAST_RETRY_READS} of them were answered by all.
     */
    private void syncRead(int k, int size, int n, boolean fast) throws IOException {
        if (fast && n > 1 && fastPause == 0) {
            port.requestFast(params, k, size, replyIds, n);
            if (allGot(n)) {
                return;
            }
            port.requestAll(PacketCodec.BROADCAST, PacketCodec.SYNC_READ, params, k, replyIds, n);
            fastPause = allGot(n) ? 0 : FAST_RETRY_READS;
            return;
        }
        port.requestAll(PacketCodec.BROADCAST, PacketCodec.SYNC_READ, params, k, replyIds, n);
        if (fastPause > 0 && allGot(n)) {
            fastPause--;
        }
    }

    private boolean allGot(int n) {
        for (int i = 0; i < n; i++) {
            if (!port.got(replyIds[i])) {
                return false;
            }
        }
        return true;
    }

    @Override
    public boolean faulty(int statusError) {
        if (statusError <= 0) {
            return false;
        }
        return codec.faulty(statusError);
    }

    @Override
    public String describeFault(int id, ServoModel model, int statusError) throws IOException {
        int bits = read(id, model.registers().error(), 1, 2);
        return bits == Integer.MIN_VALUE ? null : Faults.describe(model, statusError, bits);
    }

    @Override
    public String watchdog(int[] ids, ServoModel[] models, int n, int ms, boolean limp) throws IOException {
        if (!codec.busWatchdog()) {
            return SerialMsg.NO_WATCHDOG.text(codec.family());
        }
        // Units of 20 ms; writing 0 first also clears an earlier Bus Watchdog error.
        int units = watchdogUnits(ms);
        int covered = 0;
        for (int i = 0; i < n; i++) {
            int addr = models[i].registers().watchdog();
            if (addr >= 0 && write(ids[i], addr, 1, 0, 3) && (units == 0 || write(ids[i], addr, 1, units, 3))) {
                covered++;
            }
        }
        String armed = SerialMsg.WATCHDOG_ARMED.text(covered, n, units * 20);
        return limp ? SerialMsg.CANNOT_GO_LIMP.text(armed, codec.family()) : armed;
    }

    @Override
    public boolean resumeIfTripped(int id, ServoModel model, int statusError, int ms) throws IOException {
        int addr = model.registers().watchdog();
        if (addr < 0 || ms <= 0 || read(id, addr, 1, 3) != WATCHDOG_TRIPPED) {
            return false;
        }
        return write(id, addr, 1, 0, 3) && write(id, addr, 1, watchdogUnits(ms), 3);
    }

    @Override
    public String emergencyStop(int[] ids, ServoModel[] models, int n, boolean limp) throws IOException {
        if (limp) {
            for (int pass = 0; pass < 3; pass++) {
                torque(ids, models, n, false);
            }
            return SerialMsg.ESTOP_LIMP.text();
        }
        holdHere(ids, models, n);
        return SerialMsg.ESTOP_HOLD.text();
    }

    @Override
    public int pendingOutput() {
        return port.pendingOutput();
    }

    @Override
    public Counters counters() {
        long[] c = port.receiveCounters();
        return new Counters(port.packetsSent(), c[0], c[1], c[2], -1);
    }

    @Override
    public IOException linkError() {
        return port.linkError();
    }

    @Override
    public void close() {
        port.close();
    }

    /** Bus Watchdog units (20 ms) of {@code ms}, 0 for off. */
    private static int watchdogUnits(int ms) {
        return ms <= 0 ? 0 : Math.max(1, Math.min(127, (ms + 19) / 20));
    }

    /** The distinct register layouts of models {@code 0…n)}, in order of first use (a reused list). */
    private java.util.List<Registers> layouts(ServoModel[] models, int n) {
        layouts.clear();
        for (int i = 0; i < n; i++) {
            if (!layouts.contains(models[i].registers())) {
                layouts.add(models[i].registers());
            }
        }
        return layouts;
    }

    /**
     * One Sync Write of {@code size} bytes at {@code addr} to the servos of layout {@code r}; when
     * {@code held}, it leaves with the next packet sent (the caller sends one at once).
     */
    private void syncWrite(int addr, int size, int[] ids, ServoModel[] models, int[] values, int constant, int n,
                           Registers r, boolean held) throws IOException {
        synchronized (params) {
            int k = putAddress(0, addr, size);
            for (int i = 0; i < n; i++) {
                if (models[i].registers() == r) {
                    params[k++] = (byte) ids[i];
                    k = put(k, values == null ? constant : values[i], size);
                }
            }
            if (held) {
                port.hold(PacketCodec.BROADCAST, PacketCodec.SYNC_WRITE, params, k);
            } else {
                port.send(PacketCodec.BROADCAST, PacketCodec.SYNC_WRITE, params, k);
            }
        }
    }

    /** Address (and length unless {@code size} < 0) as the protocol encodes them, from {@code k}. */
    private int putAddress(int k, int addr, int size) {
        int n = codec.addressBytes();
        PacketCodec.putLe(params, k, n, addr);
        k += n;
        if (size >= 0) {
            PacketCodec.putLe(params, k, n, size);
            k += n;
        }
        return k;
    }

    private int put(int k, int v, int size) {
        for (int i = 0; i < size; i++) {
            params[k + i] = (byte) (v >>> 8 * (bigEndian ? size - 1 - i : i));
        }
        return k + size;
    }
}
