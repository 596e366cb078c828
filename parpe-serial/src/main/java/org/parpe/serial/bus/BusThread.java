package org.parpe.serial.bus;

import java.io.IOException;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.text.Message;
import org.parpe.serial.text.SerialMsg;

/**
 * The thread that owns the wire of a host driver, the same for G1 modules and for Dynamixel or
 * Feetech servos: while connected it runs the driver's cycle; when every module falls silent it
 * looks for them until one answers; when the device goes away it closes it and keeps reopening it
 * every reconnect interval. It also keeps, once for every protocol, what the user is told: since
 * when the robot has not answered (the IDE's alarm), the silence, a module resumed after its own
 * watchdog stopped it, and the emergency stop, which into a silent bus is reported as not
 * confirmed; after an emergency stop the run ends without final setpoints. Subclasses speak the
 * protocol.
 */
public abstract class BusThread implements HostPlant, AutoCloseable {
    /** Where the bus is. */
    protected enum State { CONNECTED, SILENT, LINK_LOST }

    /** Timeouts, retries, reconnect interval. */
    protected final BusConfig config;
    /** Where user messages go, from any thread. */
    protected final BusReport report;
    /** Whether the addressable units on this bus are modules (G1), not servos: the word in messages. */
    private final boolean modules;
    private long lastAnswerNanos = System.nanoTime();
    /** Wall-clock time of the last answer, for messages and the IDE's alarm. */
    private volatile long lastAnswerMillis = System.currentTimeMillis();
    private volatile Thread thread;
    private volatile boolean running;
    private volatile boolean estopped;
    private volatile State state = State.CONNECTED;
    private long silentSince;
    private long disconnects;

    /**
     * A driver with {@code config} reporting to {@code report}; {@code modules} says whether messages
     * call one device a module (G1) or a servo.
     */
    protected BusThread(BusConfig config, BusReport report, boolean modules) {
        this.config = config;
        this.report = report;
        this.modules = modules;
    }

    /** One cycle while connected: setpoints out, readings in. */
    protected abstract void cycle() throws IOException, InterruptedException;

    /** The device's name, for messages. */
    public abstract String name();

    /** One line of counters for the end of a run. */
    public abstract String summary();

    /** Why the link failed, or null while it works. */
    protected abstract IOException linkError();

    /**
     * The end of a run: the last setpoints, several times where frames get no reply, and every
     * device left holding with its watchdog off.
     */
    protected abstract void sendFinalHold() throws IOException;

    /**
     * Ends the run: unless the bus is lost or an emergency stop was sent, the devices get the last
     * setpoints and hold there; then the counters are reported.
     */
    @Override
    public final void finish(RunOutcome outcome) {
        stopThread();
        if (connected() && linkError() == null) {
            try {
                sendFinalHold();
            } catch (IOException e) {
                report.problem("bus: " + SerialMsg.FINAL_HOLD_FAILED.text(e.getMessage()));
            }
        }
        report.note(summary());
    }

    /** How many devices the bus looks for while silent. */
    protected abstract int lookCount();

    /** Whether device {@code i} (of {@link #lookCount}) answers one ping now. */
    protected abstract boolean answers(int i) throws IOException;

    /**
     * A device answers again: the protocol's set-up after a silence (rediscovery, watchdog,
     * resume); returns what to add to the "back" note, e.g. {@code 5 of 5 answer}.
     */
    protected abstract Message setUpAgain() throws IOException;

    /** Opens the device again after it went away. */
    protected abstract void reopenDevice() throws IOException;

    /** Closes the device. */
    protected abstract void closeDevice();

    /** What the modules do while the host has lost the device, for the user. */
    protected abstract String whileLost();

    /**
     * Sends the protocol's emergency stop (several times where frames get no reply); returns what
     * the devices now do, for the user ("servos limp (torque off)").
     */
    protected abstract String sendEmergencyStop() throws IOException;

    /**
     * Emergency stop: every driven device stops in the safe mode. Into a silent bus it is reported
     * as not confirmed, with the time of the last answer, since nothing says the robot got it.
     * Safe from any thread.
     */
    public final void emergencyStop() {
        // Stopping the bus thread also keeps a port closed at shutdown from being reported as an
        // unplugged device.
        emergencyStopping();
        long since = notAnsweringSince();
        Message silence = since >= 0 ? Message.of(SerialMsg.NONE_ANSWERED_SINCE, unit(), clock(since)) : null;
        try {
            String done = sendEmergencyStop();
            if (silence != null) {
                report.problem("bus: " + SerialMsg.ESTOP_NOT_CONFIRMED.text(silence));
            } else {
                report.note("bus: " + SerialMsg.ESTOP_SENT.text(done));
            }
        } catch (IOException e) {
            report.problem("bus: " + (silence != null ? SerialMsg.ESTOP_NOT_SENT_SILENT.text(e.getMessage(), silence)
                    : SerialMsg.ESTOP_NOT_SENT.text(e.getMessage(), whileLost())));
        }
    }

    /** A device answered: the robot responds. */
    protected final void answeredNow() {
        answeredAt(System.nanoTime());
    }

    /** A device answered at {@code nanos} ({@link System#nanoTime()}), if that is later than the last answer known. */
    protected final void answeredAt(long nanos) {
        if (nanos - lastAnswerNanos > 0) {
            lastAnswerNanos = nanos;
            lastAnswerMillis = System.currentTimeMillis() - (System.nanoTime() - nanos) / 1_000_000;
        }
    }

    /** Whether no device has answered for the configured dead-bus time. */
    protected final boolean deadFor() {
        return System.nanoTime() - lastAnswerNanos > java.util.concurrent.TimeUnit.MILLISECONDS.toNanos(config.deadAfterMs());
    }

    /**
     * Since when (wall-clock milliseconds) no device has answered, while the bus is silent or the
     * device gone; −1 while they answer. The IDE shows it as an alarm.
     */
    public final long notAnsweringSince() {
        return lost() ? lastAnswerMillis : -1;
    }

    /** A wall-clock time of day, for messages: {@code 21:27:41}. */
    public static String clock(long millis) {
        return java.time.LocalTime.ofInstant(java.time.Instant.ofEpochMilli(millis), java.time.ZoneId.systemDefault())
                .withNano(0).toString();
    }

    /**
     * Every device fell silent for the dead-bus time: says so, with the time of the last answer
     * and {@code whatTheyDo}, and the thread looks for them.
     */
    protected final void silent(String device, String whatTheyDo) {
        silent("bus: " + SerialMsg.NO_REPLY.text(unit(), device, config.deadAfterMs(), clock(lastAnswerMillis), whatTheyDo));
    }

    /** Device {@code id} had stopped on its own watchdog (a read said so) and is being resumed: says so. */
    protected final void watchdogResumed(int id, int watchdogMs) {
        report.problem("bus: " + SerialMsg.WATCHDOG_STOPPED.text(unit(), id, watchdogMs));
    }

    /** Starts the bus thread, named {@code name}. */
    protected final void startThread(String name) {
        running = true;
        Thread t = new Thread(this::loop, name);
        t.setDaemon(true);
        thread = t;
        t.start();
    }

    /** Stops the bus thread and waits for it (up to 2 s). */
    protected final void stopThread() {
        running = false;
        Thread t = thread;
        if (t != null) {
            t.interrupt();
            try {
                t.join(2000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            thread = null;
        }
    }

    /** Marks the emergency stop and stops the bus thread, which has nothing more to send. */
    protected final void emergencyStopping() {
        estopped = true;
        stopThread();
    }

    /** Whether the run can end with final setpoints: connected and not emergency-stopped. */
    protected final boolean connected() {
        return !estopped && state == State.CONNECTED;
    }

    /** Whether the modules are silent or the device is gone (the thread is looking for them). */
    protected final boolean lost() {
        return state != State.CONNECTED;
    }

    /** What one device on this bus is called: module or servo, in the user's language. */
    private String unit() {
        return (modules ? SerialMsg.UNIT_MODULE : SerialMsg.UNIT_SERVO).text();
    }

    /** All modules fell silent: {@code problem} is reported and the thread looks for them. */
    private void silent(String problem) {
        state = State.SILENT;
        silentSince = System.nanoTime();
        disconnects++;
        report.problem(problem);
    }

    /**
     * While silent: pings one device per interval (the reconnect interval spread over them); when
     * one answers, sets up again, says how long they were away, and goes back to cycles.
     */
    private void lookFor() throws IOException, InterruptedException {
        int n = lookCount();
        for (int i = 0; i < n; i++) {
            if (answers(i)) {
                Message detail = setUpAgain();
                answeredNow();
                state = State.CONNECTED;
                double away = (System.nanoTime() - silentSince) / 1e9;
                report.note("bus: " + SerialMsg.BACK.text(modules ? SerialMsg.UNITS_MODULE.text() : SerialMsg.UNITS_SERVO.text(),
                        name(), String.format(java.util.Locale.ROOT, "%.2f", away), detail));
                return;
            }
            Thread.sleep(Math.max(1, config.reconnectMs() / n));
        }
        if (n == 0) {
            Thread.sleep(config.reconnectMs());
        }
    }

    /** How often the modules fell silent or the device went away. */
    protected final long disconnects() {
        return disconnects;
    }

    @Override
    public final void emergencyStopIfRunning() {
        if (thread != null && !estopped) {
            emergencyStop();
        }
    }

    /** Whether an emergency stop was sent. */
    public final boolean emergencyStopped() {
        return estopped;
    }

    /** Stops the bus thread and closes the device. */
    @Override
    public final void close() {
        stopThread();
        closeDevice();
    }

    private void loop() {
        while (running) {
            try {
                switch (state) {
                    case CONNECTED -> cycle();
                    case SILENT -> lookFor();
                    case LINK_LOST -> reopen();
                    default -> throw new IllegalStateException(state.name());
                }
            } catch (IOException e) {
                if (running) {
                    linkLost(e);
                }
            } catch (InterruptedException e) {
                return;
            }
        }
    }

    private void linkLost(IOException e) {
        state = State.LINK_LOST;
        silentSince = System.nanoTime();
        disconnects++;
        closeDevice();
        report.problem("bus: " + SerialMsg.LINK_LOST.text(e.getMessage(), whileLost()));
    }

    private void reopen() throws InterruptedException {
        Thread.sleep(config.reconnectMs());
        try {
            reopenDevice();
            state = State.SILENT;
        } catch (IOException e) {
            // Still gone: try again after the next interval.
        }
    }
}
