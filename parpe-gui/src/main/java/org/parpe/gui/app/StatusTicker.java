package org.parpe.gui.app;

import org.parpe.gui.text.UiMsg;

/**
 * Renews, ten times a second, what the window says of the run and the robot: the status bar's
 * simulator, hardware and time fields, the red banner while the robot does not answer, and the
 * plots during a run. UI thread only; ends when the window closes.
 */
final class StatusTicker {
    private final IdeWindow ide;
    private final HardwareBridge hardware;

    private StatusTicker(IdeWindow ide, HardwareBridge hardware) {
        this.ide = ide;
        this.hardware = hardware;
    }

    /** Starts renewing {@code ide}'s status; {@code hardware} says whether the Hardware dialog holds the bus. */
    static void start(IdeWindow ide, HardwareBridge hardware) {
        new StatusTicker(ide, hardware).next();
    }

    private void next() {
        ide.shell.getDisplay().timerExec(100, () -> {
            if (!ide.shell.isDisposed()) {
                tick();
                next();
            }
        });
    }

    private void tick() {
        RunActions runs = ide.runs;
        boolean running = runs.running();
        var st = runs.controller().status();
        String simState = (!ide.toolbar.target().sim() ? UiMsg.SIM_OFF
                : running ? (runs.controller().paused() ? UiMsg.SIM_PAUSED : UiMsg.SIM_RUNNING)
                : UiMsg.SIM_IDLE).text();
        StatusBar status = ide.status;
        status.setSim(simState);
        String held = hardware.held();
        long since = runs.hardwareSilentSince();
        boolean silent = running && since >= 0;
        String state = held != null && !running ? held : runs.hardwareState();
        status.setHardware(state, silent ? UiMsg.ROBOT_SILENT_MESSAGE.text(RunActions.silentTime(since)) : null);
        ide.alarm.show(silent ? UiMsg.ROBOT_SILENT_BANNER.text(RunActions.silentTime(since)) : null);
        if (st != null) {
            status.setTime(st.time());
        }
        if (running) {
            ide.plots.refresh();
        }
    }
}
