package org.parpe.serial.servo.emu;

import java.io.IOException;
import java.util.Arrays;
import java.util.concurrent.locks.LockSupport;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.emu.EmulatorOptions;
import org.parpe.serial.emu.ServedLine;
import org.parpe.serial.link.ByteLink;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.wire.Packet;
import org.parpe.serial.servo.wire.PacketCodec;
import org.parpe.serial.servo.wire.PacketDecoder;
import org.parpe.serial.text.SerialMsg;

/**
 * Emulates a chain of Dynamixel 2.0 or Feetech servos on the far end of a serial link. Incoming
 * bytes pass a perfect decoder, then the fault injector ({@link EmulatorOptions}: lose a packet,
 * change one of its bytes, delay replies, pull the cable), then the servos' own decoder, so
 * corrupted packets are really rejected by CRC or checksum. {@link ServoResponder} executes the
 * instructions; a physics thread moves the motors every 2 ms and runs the Dynamixel Bus Watchdog.
 */
public final class ServoEmulator extends ServedLine {
    /**
     * Counters.
     *
     * @param packets        packets the servos accepted
     * @param dropped        packets lost on purpose, both directions
     * @param corrupted      packets given a wrong byte on purpose, both directions
     * @param checksumErrors packets the servos rejected by CRC or checksum
     * @param replies        status packets sent
     */
    public record Stats(long packets, long dropped, long corrupted, long checksumErrors, long replies) {
    }

    private final ServoProtocol protocol;
    private final EmulatedServo[] servos;
    private final PacketCodec codec;
    private final PacketDecoder wire;
    private final PacketDecoder servoRx;
    private final ServoResponder responder;
    /** Status packets of the request being answered, back to back; packet i ends at outEnds[i]. */
    private final byte[] outBuf = new byte[64 * 1024];
    private final int[] outEnds = new int[256];
    /** When packet i leaves: {@code outWait[i]} ns after the one before, or after the request when {@code outFromRequest[i]}. */
    private final long[] outWait = new long[256];
    private final boolean[] outFromRequest = new boolean[256];
    private int outCount;
    private long packets;
    private long replies;

    private ServoEmulator(LinkOpener opener, ByteLink first, ServoModel[] models, EmulatorOptions options,
                          EmulatorListener listener) {
        super(opener, first, options, listener, "servo-emulator");
        this.protocol = models[0].protocol();
        this.codec = protocol.codec();
        int[] ids = options.modules();
        servos = new EmulatedServo[ids.length];
        for (int i = 0; i < ids.length; i++) {
            servos[i] = new EmulatedServo(ids[i], models[i]);
        }
        Arrays.sort(servos, (a, b) -> Integer.compare(a.id(), b.id()));
        responder = new ServoResponder(protocol, codec, servos, this::reply, listener);
        wire = codec.decoder(this::onWirePacket);
        servoRx = codec.decoder(this::onServoPacket);
        decoders(wire, servoRx, codec.bufferSize() * 2);
    }

    /**
     * Opens the device through {@code opener} and serves servos of {@code model} (its protocol
     * must not be G1) with the IDs of {@code options}.
     */
    public static ServoEmulator start(LinkOpener opener, ServoModel model, EmulatorOptions options,
                                      EmulatorListener listener) throws IOException {
        ServoModel[] models = new ServoModel[options.modules().length];
        Arrays.fill(models, model);
        return start(opener, models, options, listener);
    }

    /**
     * Like {@link #start(LinkOpener, ServoModel, EmulatorOptions, EmulatorListener)} with a model
     * per servo: {@code models[i]} for {@code options.modules()[i]}, all of one protocol.
     */
    public static ServoEmulator start(LinkOpener opener, ServoModel[] models, EmulatorOptions options,
                                      EmulatorListener listener) throws IOException {
        if (models.length != options.modules().length || models.length == 0) {
            throw new IllegalArgumentException("one model per servo needed, got " + models.length + " for "
                    + options.modules().length + " servos");
        }
        for (ServoModel m : models) {
            if (!m.protocol().controlTable() || m.protocol() != models[0].protocol()) {
                throw new IllegalArgumentException("servos of one protocol other than G1 needed, got " + m.label());
            }
        }
        int maxId = models[0].protocol().maxId();
        for (int id : options.modules()) {
            if (id > maxId) {
                throw new IllegalArgumentException(SerialMsg.SERVO_IDS.text(models[0].protocol().key(), maxId, id));
            }
        }
        ServoEmulator e = new ServoEmulator(opener, opener.open(), models, options, listener);
        e.serve();
        return e;
    }

    /** The emulated servo IDs, ascending. */
    public int[] servoIds() {
        return Arrays.stream(servos).mapToInt(EmulatedServo::id).toArray();
    }

    /** The servo angle of servo {@code id}, degrees (0 at the model's centre tick). */
    public double angle(int id) {
        synchronized (lock) {
            return servo(id).angle();
        }
    }

    /** Whether the torque of servo {@code id} is off. */
    public boolean isLimp(int id) {
        synchronized (lock) {
            return !servo(id).torqueOn();
        }
    }

    /** Whether servo {@code id} has stopped on its Bus Watchdog. */
    public boolean watchdogTripped(int id) {
        synchronized (lock) {
            return servo(id).watchdogTripped();
        }
    }

    /** The hardware error bits of servo {@code id}. */
    public int hardwareError(int id) {
        synchronized (lock) {
            return servo(id).hardwareError();
        }
    }

    /** Raises hardware error bits on servo {@code id} (0 clears them); a fault turns the torque off. */
    public void fault(int id, int bits) {
        synchronized (lock) {
            servo(id).fault(bits);
        }
    }

    /**
     * Sets every servo's Return Delay Time to {@code micros} (rounded to its 2 µs units), as a
     * user does with the maker's tool for a fast bus; the factory setting of Dynamixel servos is
     * 500 µs.
     */
    public void returnDelay(int micros) {
        synchronized (lock) {
            for (EmulatedServo s : servos) {
                s.table[s.ct.named("Return Delay Time").addr()] = (byte) Math.max(0, Math.min(254, micros / 2));
            }
        }
    }

    /** Moves a limp servo by hand (posing); false, and nothing moves, when its torque is on. */
    public boolean backDrive(int id, double degrees) {
        synchronized (lock) {
            return servo(id).backDrive(degrees);
        }
    }

    /** The counters so far. */
    public Stats stats() {
        synchronized (lock) {
            return new Stats(packets, dropped(), corrupted(), servoRx.checksumErrors(), replies);
        }
    }


    private EmulatedServo servo(int id) {
        for (EmulatedServo s : servos) {
            if (s.id() == id) {
                return s;
            }
        }
        throw new IllegalArgumentException(SerialMsg.NOT_EMULATED.text(SerialMsg.WHO_SERVO_ID.text(id)));
    }


    /** Packets as they were sent; the fault injector decides what the servos get. */
    private void onWirePacket(Packet p) {
        relay(p.raw, 0, p.rawLength);
    }

    private void onServoPacket(Packet p) {
        long received = System.nanoTime();
        synchronized (lock) {
            packets++;
            outCount = 0;
            responder.execute(p, received);
        }
        // Replies leave outside the lock, each at its time (Return Delay Time, reply slot): a
        // reply's wait must not stall the motors.
        long last = received;
        for (int i = 0; i < outCount; i++) {
            long due = (outFromRequest[i] ? received : last) + outWait[i] + (long) (options.latencyMs() * 1e6);
            for (long left; (left = due - System.nanoTime()) > 0; ) {
                LockSupport.parkNanos(left);
            }
            int from = i == 0 ? 0 : outEnds[i - 1];
            send(outBuf, from, outEnds[i] - from);
            last = System.nanoTime();
        }
    }

    /** Queues a status packet (called by the responder with {@link #lock} held); faults apply here. */
    private void reply(byte[] packet, int len, long wait, boolean fromRequest) {
        if (lose()) {
            return;
        }
        int from = outCount == 0 ? 0 : outEnds[outCount - 1];
        if (outCount == outEnds.length || from + len > outBuf.length) {
            return;
        }
        System.arraycopy(packet, 0, outBuf, from, len);
        maybeCorrupt(outBuf, from, len);
        outWait[outCount] = wait;
        outFromRequest[outCount] = fromRequest;
        outEnds[outCount++] = from + len;
        replies++;
    }

    @Override
    protected void physics(long now, double dt) {
        synchronized (lock) {
            for (EmulatedServo s : servos) {
                if (s.step(now, dt, options.speedDegPerS())) {
                    listener.onSafeStop(s.id(), now, "bus watchdog");
                }
            }
        }
    }
}
