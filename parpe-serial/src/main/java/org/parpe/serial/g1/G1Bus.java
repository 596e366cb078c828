package org.parpe.serial.g1;

import org.parpe.serial.text.SerialMsg;
import java.io.IOException;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.bus.SafeMode;
import org.parpe.serial.link.ByteLink;
import org.parpe.serial.servo.ServoBus;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;

/**
 * The reconstructed G1 bus behind {@link ServoBus}: goals become one SETPOINTS frame, torque off
 * LIMP, torque on RESUME and HOLD, positions READ transactions, the watchdog CONFIG, the emergency
 * stop ESTOP. G1 ticks are hundredths of a degree (model {@code g1-segment}). A READ's STATUS
 * also carries the module's accelerometer and touch sensors, which {@link #sensors} hands on, and
 * how many frames the module rejected, which the counters report. The modules stop on their own
 * watchdog in the configured safe mode, so a silent bus needs no frame from the host.
 */
public final class G1Bus implements ServoBus {
    private final BusMaster master;
    private final Reply reply = new Reply();
    private static final int SENSORS = 5;
    private short[] wire = new short[1];
    private int seq;
    /** The accelerometer and touch sensors of each module's last STATUS, by ID. */
    private final double[] sensors = new double[(Protocol.MAX_MODULE_ID + 1) * SENSORS];
    private final boolean[] sensed = new boolean[Protocol.MAX_MODULE_ID + 1];
    private volatile long rejected;

    /** Starts talking G1 over {@code link}. */
    public G1Bus(ByteLink link, BusConfig config) {
        this.master = new BusMaster(link, config);
    }

    @Override
    public ServoProtocol protocol() {
        return ServoProtocol.G1;
    }

    @Override
    public String name() {
        return master.name();
    }

    @Override
    public int ping(int id, int attempts) throws IOException {
        return id <= Protocol.MAX_MODULE_ID && master.ping(id, reply, attempts)
                ? ServoModel.defaultFor(ServoProtocol.G1).number() : -1;
    }

    @Override
    public void torque(int[] ids, ServoModel[] models, int n, boolean on) throws IOException {
        for (int pass = 0; pass < 2; pass++) {
            // Twice: these frames have no reply.
            for (int i = 0; i < n; i++) {
                if (on) {
                    master.send(ids[i], Command.RESUME);
                    master.sendHold(ids[i], false);
                } else {
                    master.send(ids[i], Command.LIMP);
                }
            }
        }
    }

    /** RESUME and HOLD at the current angle: a G1 module holds where it is without goals of its own. */
    @Override
    public void holdAt(int[] ids, ServoModel[] models, int[] ticks, int n) throws IOException {
        torque(ids, models, n, true);
    }

    /** G1 modules have no register to read the torque state from; their RESUME and HOLD frames are sent twice. */
    @Override
    public int torqueState(int id, ServoModel model, int attempts) {
        return 1;
    }

    @Override
    public void goalSequence(int s) {
        seq = s;
    }

    @Override
    public void writeGoals(int[] ids, ServoModel[] models, int[] ticks, int n) throws IOException {
        if (n == 0) {
            return;
        }
        int first = Integer.MAX_VALUE;
        int last = -1;
        for (int i = 0; i < n; i++) {
            first = Math.min(first, ids[i]);
            last = Math.max(last, ids[i]);
        }
        if (wire.length < last - first + 1) {
            wire = new short[last - first + 1];
        }
        java.util.Arrays.fill(wire, Protocol.NO_CHANGE);
        for (int i = 0; i < n; i++) {
            wire[ids[i] - first] = (short) ticks[i];
        }
        master.sendSetpoints(seq & 0xFFFF, first, wire, last - first + 1);
    }

    @Override
    public int readPositions(int[] ids, ServoModel[] models, int n, double[] degrees, int[] errors) throws IOException {
        int answered = 0;
        for (int i = 0; i < n; i++) {
            if (master.read(ids[i], reply, 1)) {
                degrees[i] = reply.angle;
                errors[i] = reply.flags & (Protocol.Flag.ESTOP.bit() | Protocol.Flag.WATCHDOG.bit());
                answered++;
                keepSensors(ids[i]);
            } else {
                errors[i] = NO_REPLY;
            }
        }
        return answered;
    }

    private void keepSensors(int id) {
        int b = id * SENSORS;
        for (int a = 0; a < 3; a++) {
            sensors[b + a] = reply.accel[a];
        }
        sensors[b + 3] = (reply.touch & Protocol.Touch.LEFT.bit()) != 0 ? 1 : 0;
        sensors[b + 4] = (reply.touch & Protocol.Touch.RIGHT.bit()) != 0 ? 1 : 0;
        sensed[id] = true;
        rejected = Math.max(rejected, reply.rxErrors);
    }

    @Override
    public boolean sensors(int id, double[] out) {
        if (id > Protocol.MAX_MODULE_ID || !sensed[id]) {
            return false;
        }
        System.arraycopy(sensors, id * SENSORS, out, 0, SENSORS);
        return true;
    }

    /** G1 modules report no faults of their own: their flags are the host's latches (watchdog, emergency stop). */
    @Override
    public boolean faulty(int statusError) {
        return false;
    }

    @Override
    public String describeFault(int id, ServoModel model, int statusError) {
        return "flags " + statusError;
    }

    @Override
    public boolean resumeIfTripped(int id, ServoModel model, int statusError, int ms) throws IOException {
        if (statusError < 0 || (statusError & Protocol.Flag.WATCHDOG.bit()) == 0) {
            return false;
        }
        master.send(id, Command.RESUME);
        return true;
    }

    @Override
    public String watchdog(int[] ids, ServoModel[] models, int n, int ms, boolean limp) throws IOException {
        if (ms <= 0) {
            // HOLD disarms the watchdogs; mode 1 lets a module finish its move to the last setpoint.
            for (int pass = 0; pass < 3; pass++) {
                master.sendHold(Protocol.BROADCAST, true);
            }
            return SerialMsg.G1_WATCHDOGS_OFF.text();
        }
        master.sendConfig(ms, limp ? SafeMode.LIMP : SafeMode.HOLD, 0);
        master.send(Protocol.BROADCAST, Command.RESUME);
        return (limp ? SerialMsg.G1_WATCHDOG_LIMP : SerialMsg.G1_WATCHDOG_HOLD).text(ms);
    }

    /** ESTOP broadcast three times; every module latches it until the next run's RESUME. */
    @Override
    public String emergencyStop(int[] ids, ServoModel[] models, int n, boolean limp) throws IOException {
        SafeMode mode = limp ? SafeMode.LIMP : SafeMode.HOLD;
        for (int pass = 0; pass < 3; pass++) {
            master.sendEmergencyStop(mode);
        }
        master.drain(100);
        return (limp ? SerialMsg.G1_STOPPED_LIMP : SerialMsg.G1_STOPPED_HOLD).text();
    }

    /**
     * The last setpoints and a broadcast HOLD that lets each module finish its move and disarms
     * its watchdog, three times: these frames get no reply, and a lost HOLD would let the
     * watchdogs trip.
     */
    @Override
    public void finalHold(int[] ids, ServoModel[] models, int[] ticks, int n) throws IOException {
        for (int pass = 0; pass < 3; pass++) {
            if (ticks != null) {
                writeGoals(ids, models, ticks, n);
            }
            master.sendHold(Protocol.BROADCAST, true);
        }
    }

    /** Nothing to send: the modules stop on their own watchdog, in the safe mode CONFIG gave them. */
    @Override
    public String silenced(int[] ids, ServoModel[] models, int n, int watchdogMs, boolean limp) {
        return whileLost(watchdogMs, limp);
    }

    @Override
    public String whileLost(int watchdogMs, boolean limp) {
        return (limp ? SerialMsg.G1_WHILE_LOST_LIMP : SerialMsg.G1_WHILE_LOST_HOLD).text(watchdogMs);
    }

    @Override
    public int pendingOutput() {
        return master.pendingOutput();
    }

    @Override
    public Counters counters() {
        BusMaster.Counters c = master.counters();
        return new Counters(c.framesSent(), c.timeouts(), c.checksumErrors(), c.stray(), rejected);
    }

    @Override
    public IOException linkError() {
        return master.linkError();
    }

    @Override
    public void close() {
        master.close();
    }
}
