package org.parpe.gui.automation;

import org.parpe.gui.text.UiMsg;

import java.io.IOException;
import org.eclipse.swt.widgets.Display;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.run.Speed;

/**
 * What {@code --run-for}, {@code --screenshot} and {@code --exit} do once the window is up:
 * wait for the script to be validated, run it in the simulator (as fast as possible) for the
 * given simulated time, let the views catch up, save the picture, close. Every wait is bounded.
 * Driven by UI-thread timers, so the window stays live throughout. With the system property
 * {@value #MENUS} set to a file, the texts of the menu bar are written there too (one a line,
 * without the mnemonic's {@code &}): the .deb's install test reads in them which language the
 * IDE speaks ({@code JAVA_TOOL_OPTIONS=-Dparpe.menus=/tmp/menus.txt parpe-ide ... --exit}).
 */
public final class Automation {
    private static final int POLL_MS = 100;
    private static final int LOAD_TIMEOUT_MS = 15_000;
    private static final int SETTLE_MS = 600;
    /** The system property naming the file for the menu bar's texts. */
    public static final String MENUS = "parpe.menus";

    private final AutomationHost ide;
    private final LaunchOptions options;
    private final Display display;
    private int exitCode;
    private boolean done;
    private boolean posePanelShown;

    private Automation(AutomationHost ide, LaunchOptions options) {
        this.ide = ide;
        this.options = options;
        this.display = ide.display();
    }

    /** Starts the automation for {@code ide}. */
    public static Automation start(AutomationHost ide, LaunchOptions options) {
        Automation a = new Automation(ide, options);
        a.waitForLoad(0);
        return a;
    }

    /** The process exit code: 0, 1 when the script failed, 2 when the picture could not be saved. */
    public int exitCode() {
        return exitCode;
    }

    /** Records a failure (internal error in the UI). */
    public void fail(String message) {
        System.err.println("parpe gui: " + message);
        exitCode = Math.max(exitCode, 1);
    }

    private void later(int ms, Runnable r) {
        display.timerExec(ms, () -> {
            if (!ide.closed()) {
                r.run();
            }
        });
    }

    private void waitForLoad(int waited) {
        if (ide.validations() == 0 && waited < LOAD_TIMEOUT_MS) {
            later(POLL_MS, () -> waitForLoad(waited + POLL_MS));
            return;
        }
        if (options.posePanel() && !posePanelShown) {
            showPosePanel(0);
            return;
        }
        if (options.grid() != null) {
            showGrid(options.grid());
        }
        if (options.runFor() >= 0) {
            if (!ide.runnable()) {
                for (Diagnostic d : ide.problems()) {
                    System.err.println(d.format());
                }
                fail(UiMsg.AUTO_SCRIPT_ERRORS.text());
                later(SETTLE_MS, this::shoot);
                return;
            }
            ide.runInSimulator(Speed.MAX, options.runFor(), this::ran);
            watchdog();
        } else {
            later(SETTLE_MS * 2, this::shoot);
        }
    }

    /**
     * {@code --pose-panel}: brings the Pose panel to the front with the poses the script plays,
     * waits (bounded) until the posed robot stands in the first of them, then carries on.
     */
    private void showPosePanel(int waited) {
        if (waited == 0) {
            if (!ide.showScriptPoses()) {
                System.err.println("parpe gui: " + ide.statusMessage());
            }
        }
        if (!ide.posingReady() && waited < LOAD_TIMEOUT_MS) {
            later(POLL_MS, () -> showPosePanel(waited + POLL_MS));
            return;
        }
        posePanelShown = true;
        // The joints take a moment to reach the pose; then the camera goes close to the posed group.
        later(SETTLE_MS * 3, () -> {
            ide.focusOnPosedModules();
            later(SETTLE_MS, () -> waitForLoad(LOAD_TIMEOUT_MS));
        });
    }

    /** {@code --grid NAME}: the grid editor on gait table NAME, every module cell selected. */
    private void showGrid(String name) {
        if (!ide.selectGaitTable(name)) {
            String shown = ide.gaitTableShown();
            fail(UiMsg.AUTO_NO_GAIT_TABLE.text(name, ide.fileName(),
                    shown == null ? UiMsg.AUTO_HAS_NONE.text() : UiMsg.AUTO_FIRST_IS.text(shown)));
        }
    }

    /** Stops a run that takes far longer than it should (a stuck plant) so that --exit always exits. */
    private void watchdog() {
        int limitMs = (int) Math.min(Integer.MAX_VALUE, 120_000 + options.runFor() * 10_000);
        later(limitMs, () -> {
            if (!done && ide.running()) {
                fail(UiMsg.AUTO_RUN_TOO_LONG.text(limitMs / 1000));
                ide.stop();
            }
        });
    }

    private void ran(RunOutcome outcome) {
        if (outcome.status() == RunOutcome.Status.ERROR) {
            fail(UiMsg.AUTO_RUN_FAILED.text(outcome.message()));
        } else {
            System.out.println("parpe gui: " + UiMsg.AUTO_RAN.text(ide.fileName(),
                    String.format(java.util.Locale.ROOT, "%.2f", outcome.time())));
        }
        later(SETTLE_MS, this::shoot);
    }

    private void shoot() {
        if (done) {
            return;
        }
        done = true;
        if (options.screenshot() != null) {
            try {
                ide.screenshot(options.screenshot());
                System.out.println("parpe gui: " + UiMsg.AUTO_SCREENSHOT_SAVED.text(options.screenshot()));
            } catch (IOException e) {
                System.err.println("parpe gui: error: " + e.getMessage());
                exitCode = 2;
            }
        }
        String menus = System.getProperty(MENUS);
        if (menus != null) {
            writeMenus(java.nio.file.Path.of(menus));
        }
        if (options.exit()) {
            ide.close();
        }
    }

    /** The menu bar's texts, one a line, to {@code file} (the install test's view of the IDE's language). */
    private void writeMenus(java.nio.file.Path file) {
        StringBuilder texts = new StringBuilder();
        for (String title : ide.menuTitles()) {
            texts.append(title.replace("&", "")).append('\n');
        }
        try {
            java.nio.file.Files.writeString(file, texts, java.nio.charset.StandardCharsets.UTF_8);
        } catch (IOException e) {
            System.err.println("parpe gui: error: " + e.getMessage());
            exitCode = 2;
        }
    }
}
