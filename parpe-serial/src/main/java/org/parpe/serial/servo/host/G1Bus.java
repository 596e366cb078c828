package org.parpe.serial.servo.host;

import java.io.IOException;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.bus.BusMaster;
import org.parpe.serial.bus.Reply;
import org.parpe.serial.bus.SafeMode;
import org.parpe.serial.link.ByteLink;
import org.parpe.serial.protocol.Protocol;
import org.parpe.serial.protocol.Command;
import org.parpe.serial.servo.ServoBus;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;

/**
 * The reconstructed G1 bus behind {@link ServoBus}: goals become one SETPOINTS frame, torque off
 * LIMP, torque on RESUME and HOLD, positions READ transactions, the watchdog CONFIG, the emergency
 * stop ESTOP. G1 ticks are hundredths of a degree (model {@code g1-segment}).
 */
public final class G1Bus implements ServoBus {
    private final BusMaster master;
    private final Reply reply = new Reply();
    private short[] wire = new short[1];
    private int seq;

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

    /** G1 modules have no register to read the torque state from; their RESUME and HOLD frames are sent twice. */
    @Override
    public int torqueState(int id, ServoModel model, int attempts) {
        return 1;
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
        master.sendSetpoints(seq++ & 0xFFFF, first, wire, last - first + 1);
    }

    @Override
    public int readPositions(int[] ids, ServoModel[] models, int n, double[] degrees, int[] errors) throws IOException {
        int answered = 0;
        for (int i = 0; i < n; i++) {
            if (master.read(ids[i], reply, 1)) {
                degrees[i] = reply.angle;
                errors[i] = reply.flags & (Protocol.Flag.ESTOP.bit() | Protocol.Flag.WATCHDOG.bit());
                answered++;
            } else {
                errors[i] = NO_REPLY;
            }
        }
        return answered;
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
            return "module watchdogs off; modules finish their move and hold";
        }
        master.sendConfig(ms, limp ? SafeMode.LIMP : SafeMode.HOLD, 0);
        master.send(Protocol.BROADCAST, Command.RESUME);
        return "modules " + (limp ? "go limp" : "hold") + " after " + ms + " ms without a frame (module watchdog)";
    }

    @Override
    public void emergencyStop(int[] ids, ServoModel[] models, int n, boolean limp) throws IOException {
        for (int pass = 0; pass < 3; pass++) {
            master.sendEmergencyStop(limp ? SafeMode.LIMP : SafeMode.HOLD);
        }
        master.drain(100);
    }

    @Override
    public int pendingOutput() {
        return master.pendingOutput();
    }

    @Override
    public Counters counters() {
        BusMaster.Counters c = master.counters();
        return new Counters(c.framesSent(), c.timeouts(), c.checksumErrors(), c.stray());
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
