package org.parpe.serial.bus;

import java.io.IOException;

/**
 * The thread that owns the wire of a host driver, the same for G1 modules and for Dynamixel or
 * Feetech servos: while connected it runs the driver's cycle; when every module falls silent it
 * looks for them until one answers; when the device goes away it closes it and keeps reopening it
 * every reconnect interval. Also the emergency stop's bookkeeping: after one, the run ends
 * without final setpoints. Subclasses speak the protocol.
 */
public abstract class BusThread implements HostPlant, AutoCloseable {
    /** Where the bus is. */
    protected enum State { CONNECTED, SILENT, LINK_LOST }

    /** Timeouts, retries, reconnect interval. */
    protected final BusConfig config;
    /** Where user messages go, from any thread. */
    protected final BusReport report;
    private volatile Thread thread;
    private volatile boolean running;
    private volatile boolean estopped;
    private volatile State state = State.CONNECTED;
    private long silentSince;
    private long disconnects;

    /** A driver with {@code config} reporting to {@code report}. */
    protected BusThread(BusConfig config, BusReport report) {
        this.config = config;
        this.report = report;
    }

    /** One cycle while connected: setpoints out, readings in. */
    protected abstract void cycle() throws IOException, InterruptedException;

    /** While silent: pings; calls {@link #resumed} when a module answers. */
    protected abstract void lookFor() throws IOException, InterruptedException;

    /** Opens the device again after it went away. */
    protected abstract void reopenDevice() throws IOException;

    /** Closes the device. */
    protected abstract void closeDevice();

    /** What the modules do while the host has lost the device, for the user. */
    protected abstract String whileLost();

    /** Stops every module at once, in the safe mode; safe from any thread. */
    public abstract void emergencyStop();

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

    /** All modules fell silent: {@code problem} is reported and the thread looks for them. */
    protected final void silent(String problem) {
        state = State.SILENT;
        silentSince = System.nanoTime();
        disconnects++;
        report.problem(problem);
    }

    /** Modules answer again: back to cycles. Returns the seconds the bus was silent or lost. */
    protected final double resumed() {
        state = State.CONNECTED;
        return (System.nanoTime() - silentSince) / 1e9;
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
        report.problem("bus: " + e.getMessage() + "; " + whileLost() + "; waiting for the device to return");
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
