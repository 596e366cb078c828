package org.parpe.serial.servo;

import org.parpe.serial.text.SerialMsg;
import java.io.IOException;

/**
 * One open servo bus, whatever its protocol: ping, torque on and off, goal positions of many
 * servos in one packet, present positions, error status, emergency stop. Positions cross this
 * interface as ticks ({@link ServoModel#ticks}) going out and servo degrees coming back. Requests
 * that expect a reply must come from one thread at a time; {@link #emergencyStop} may be called
 * from any thread.
 */
public interface ServoBus extends AutoCloseable {
    /** Status error value of a servo that did not reply. */
    int NO_REPLY = -1;

    /** The protocol spoken. */
    ServoProtocol protocol();

    /** The device's name. */
    String name();

    /**
     * Pings servo {@code id} with up to {@code attempts} tries: its model number, 0 when it
     * answers but its model cannot be read, or −1 when it does not answer.
     */
    int ping(int id, int attempts) throws IOException;

    /**
     * Looks for servos {@code ids}: the model number of each (as {@link #ping}), −1 for those that
     * do not answer. Every ID is pinged twice.
     */
    default int[] scan(int[] ids) throws IOException {
        int[] models = new int[ids.length];
        for (int i = 0; i < ids.length; i++) {
            models[i] = ping(ids[i], 2);
        }
        return models;
    }

    /** Turns the torque of servos {@code ids[0…n)} on (holding) or off (limp, back-drivable). */
    void torque(int[] ids, ServoModel[] models, int n, boolean on) throws IOException;

    /**
     * Reads back whether servo {@code id}'s torque is on: 1 on, 0 off (limp), {@link #NO_REPLY}
     * when it did not answer in {@code attempts} tries. A bus without a register to read it from
     * answers 1.
     */
    int torqueState(int id, ServoModel model, int attempts) throws IOException;

    /**
     * The run's tick of the goals that follow, for protocols whose goal packets carry a sequence
     * number (G1's SETPOINTS: tick mod 2¹⁶); the others ignore it.
     */
    default void goalSequence(int seq) {
    }

    /** Sends goal positions ({@code ticks[i]} for {@code ids[i]}) to servos {@code 0…n) at once. */
    void writeGoals(int[] ids, ServoModel[] models, int[] ticks, int n) throws IOException;

    /**
     * Reads the present positions of servos {@code 0…n)}: servo degrees into {@code degrees[i]}
     * (unchanged for a servo that did not reply) and the status error byte into
     * {@code errors[i]} (0 when all is well, {@link #NO_REPLY} when it did not reply). Returns the
     * number of servos that replied.
     */
    int readPositions(int[] ids, ServoModel[] models, int n, double[] degrees, int[] errors) throws IOException;

    /**
     * One full cycle: {@link #writeGoals} then {@link #readPositions}, with the same arguments and
     * result. A bus may put both requests on the line in one write (one system call and one USB
     * transfer instead of two); the servos see the same packets in the same order.
     */
    default int writeGoalsAndRead(int[] ids, ServoModel[] models, int[] ticks, int n, double[] degrees, int[] errors)
            throws IOException {
        writeGoals(ids, models, ticks, n);
        return readPositions(ids, models, n, degrees, errors);
    }

    /**
     * The sensors other than the angle of device {@code id}, from its last position read, into
     * {@code out} (accelerometer x, y, z in −100…100, touch left and right as 0 or 1): true where
     * the devices have them (G1 modules), false otherwise.
     */
    default boolean sensors(int id, double[] out) {
        return false;
    }

    /** Whether a status error byte reports a fault of the servo (rather than of the request). */
    boolean faulty(int statusError);

    /**
     * What servo {@code id} reports as wrong, in words (for example {@code overload,
     * overheating}), reading its error register where the protocol has one; null when it does not
     * answer.
     */
    String describeFault(int id, ServoModel model, int statusError) throws IOException;

    /**
     * Sets the servos' own watchdog: stop after {@code ms} without a packet ({@code limp} or
     * holding), where the protocol and model have one; 0 turns it off. Returns what the servos
     * will do when the host falls silent, for the user.
     */
    String watchdog(int[] ids, ServoModel[] models, int n, int ms, boolean limp) throws IOException;

    /**
     * Whether servo {@code id} had stopped on its own watchdog (its last status error was
     * {@code statusError}); if so it is re-armed with {@code ms} and obeys goals again.
     */
    boolean resumeIfTripped(int id, ServoModel model, int statusError, int ms) throws IOException;

    /**
     * Emergency stop of servos {@code 0…n)}: torque off ({@code limp}), or stop where they are
     * and hold. Several packets, so that one lost packet does not matter. Returns what the
     * devices now do, for the user ("servos limp (torque off)").
     */
    String emergencyStop(int[] ids, ServoModel[] models, int n, boolean limp) throws IOException;

    /**
     * The end of a run: the devices {@code 0…n)} keep holding with their watchdog off, at goals
     * {@code ticks} (null: where they are). Packets without a reply go out several times. By
     * default the watchdog goes off first (writing 0 also clears a Dynamixel Bus Watchdog
     * error, which would refuse the goals), then the goals, three times.
     */
    default void finalHold(int[] ids, ServoModel[] models, int[] ticks, int n) throws IOException {
        watchdog(ids, models, n, 0, false);
        for (int i = 0; i < 3 && ticks != null; i++) {
            writeGoals(ids, models, ticks, n);
        }
    }

    /**
     * Every device fell silent for the dead-bus time: does what the host can (a torque-off for
     * {@code limp}, where the servos would otherwise keep their goal) and says what the devices
     * do, for the user.
     */
    default String silenced(int[] ids, ServoModel[] models, int n, int watchdogMs, boolean limp) {
        if (!limp) {
            return SerialMsg.HOLD_LAST_GOAL.text();
        }
        try {
            torque(ids, models, n, false);
        } catch (IOException e) {
            return SerialMsg.KEEP_LAST_GOAL.text();
        }
        return SerialMsg.TORQUE_OFF_SENT.text();
    }

    /** What the devices do while the host has lost the device, for the user. */
    default String whileLost(int watchdogMs, boolean limp) {
        return (watchdogMs > 0 ? SerialMsg.HOLD_OR_WATCHDOG : SerialMsg.HOLD_LAST_GOAL).text();
    }

    /**
     * Makes servos {@code 0…n)} hold where they are: their present positions become their goals,
     * then torque on (a servo whose torque comes on must not jump to an old goal). Returns how
     * many answered.
     */
    default int holdHere(int[] ids, ServoModel[] models, int n) throws IOException {
        double[] deg = new double[n];
        int[] err = new int[n];
        readPositions(ids, models, n, deg, err);
        retrySilent(ids, models, n, deg, err);
        int[] held = new int[n];
        ServoModel[] heldModels = new ServoModel[n];
        int[] ticks = new int[n];
        int m = 0;
        for (int i = 0; i < n; i++) {
            if (err[i] != NO_REPLY) {
                held[m] = ids[i];
                heldModels[m] = models[i];
                ticks[m++] = models[i].ticks(deg[i]);
            }
        }
        if (m > 0) {
            holdAt(held, heldModels, ticks, m);
        }
        return m;
    }

    /**
     * Reads once more the positions of the servos that did not answer the first read (a reply
     * lost on a busy line): a servo is held only where it is known to be.
     */
    private void retrySilent(int[] ids, ServoModel[] models, int n, double[] deg, int[] err) throws IOException {
        int silent = 0;
        for (int i = 0; i < n; i++) {
            silent += err[i] == NO_REPLY ? 1 : 0;
        }
        if (silent == 0) {
            return;
        }
        int[] again = new int[silent];
        ServoModel[] againModels = new ServoModel[silent];
        int[] at = new int[silent];
        for (int i = 0, k = 0; i < n; i++) {
            if (err[i] == NO_REPLY) {
                again[k] = ids[i];
                againModels[k] = models[i];
                at[k++] = i;
            }
        }
        double[] d = new double[silent];
        int[] e = new int[silent];
        readPositions(again, againModels, silent, d, e);
        for (int k = 0; k < silent; k++) {
            deg[at[k]] = d[k];
            err[at[k]] = e[k];
        }
    }

    /**
     * Makes servos {@code 0…n)} hold at goals {@code ticks}: the goals first, then torque on, so
     * that no servo jumps to an old goal when its torque comes on.
     */
    default void holdAt(int[] ids, ServoModel[] models, int[] ticks, int n) throws IOException {
        writeGoals(ids, models, ticks, n);
        torque(ids, models, n, true);
    }

    /** Bytes queued but not yet on the wire. */
    int pendingOutput();

    /**
     * Counters.
     *
     * @param packetsSent    packets written
     * @param timeouts       replies that did not come in time
     * @param checksumErrors received packets with a bad CRC or checksum
     * @param stray          valid packets nobody waited for
     * @param rejected       packets the devices say they rejected (G1 modules count them), −1
     *                       where the devices do not say
     */
    record Counters(long packetsSent, long timeouts, long checksumErrors, long stray, long rejected) {
    }

    /** A snapshot of the counters. */
    Counters counters();

    /** The error that ended the link, or null while it works. */
    IOException linkError();

    /** Lets queued bytes leave, then closes the device. */
    @Override
    void close();
}
