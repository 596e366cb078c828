package org.parpe.gui.app;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import org.eclipse.jface.resource.JFaceResources;
import org.eclipse.swt.SWT;
import org.eclipse.swt.SWTException;
import org.eclipse.swt.custom.CTabFolder;
import org.eclipse.swt.custom.CTabItem;
import org.eclipse.swt.custom.SashForm;
import org.eclipse.swt.custom.StyledText;
import org.eclipse.swt.widgets.Control;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.gui.panels.ProblemsView;
import org.parpe.gui.text.UiMsg;

/**
 * The tabs below the editor: Problems, the Run log and the Pose panel, and which of them is in
 * front when. UI thread only, except the methods that say "any thread".
 */
final class BottomTabs {
    /** Problems one run may add to the view; more are logged only. */
    static final int RUN_PROBLEM_LIMIT = 500;

    private final SashForm split;
    private final CTabFolder folder;
    private final ProblemsView problems;
    private final StyledText log;
    private CTabItem poseTab;

    /**
     * The tabs under the editor in {@code split}; a double-click on a problem calls {@code reveal},
     * and {@code changed} runs whenever Problems changes.
     */
    BottomTabs(SashForm split, Consumer<Diagnostic> reveal, Runnable changed) {
        this.split = split;
        folder = Panels.folder(split);
        problems = new ProblemsView(folder, reveal, changed);
        Panels.tab(folder, UiMsg.TAB_PROBLEMS.text(), problems.control());
        // Wrapped: a run's last lines (its score and parts) are read without scrolling sideways.
        log = new StyledText(folder, SWT.READ_ONLY | SWT.V_SCROLL | SWT.MULTI | SWT.WRAP);
        log.setFont(JFaceResources.getTextFont());
        Panels.tab(folder, UiMsg.TAB_RUN_LOG.text(), log);
        split.setWeights(72, 28);
    }

    /** The folder (the Pose panel is made in it). */
    CTabFolder folder() {
        return folder;
    }

    /** Adds the Pose panel's tab; it takes more of the column while it is in front. */
    void addPose(Control pose) {
        poseTab = Panels.tab(folder, UiMsg.TAB_POSE.text(), pose);
        folder.addListener(SWT.Selection, e -> fit());
    }

    ProblemsView problems() {
        return problems;
    }

    /** The Run log. */
    StyledText log() {
        return log;
    }

    /** The Pose panel needs more room than Problems and the Run log. */
    private void fit() {
        split.setWeights(folder.getSelection() == poseTab ? new int[] {40, 60} : new int[] {72, 28});
    }

    /** Whether Problems is the tab in front. */
    boolean problemsInFront() {
        return folder.getSelectionIndex() == 0;
    }

    /** Brings Problems to the front (a refused Run: what to fix is there). */
    void showProblems() {
        folder.setSelection(0);
        if (split.getWeights()[1] < 150) {
            split.setWeights(72, 28);
        }
    }

    /** Brings the Pose panel to the front. */
    void showPose() {
        folder.setSelection(poseTab);
        fit();
    }

    /**
     * Brings the Run log to the front (a run's score is there), unless the Pose panel is: that is
     * the user's work, not a view of the run.
     */
    void showRunLog() {
        if (folder.getSelection() != poseTab) {
            folder.setSelection(1);
            log.setSelection(log.getCharCount());
        }
    }

    /** Whether the Run log is the tab in front. */
    boolean runLogInFront() {
        return folder.getSelection() != null && folder.getSelection().getControl() == log;
    }

    /** Appends a line to the Run log. */
    void log(String line) {
        if (!log.isDisposed()) {
            log.append(String.format(Locale.ROOT, "[%tT] %s%n", System.currentTimeMillis(), line));
            log.setSelection(log.getCharCount()); // in sight, however many screen lines the wrapped lines take
        }
    }

    /** {@link #log} from any thread. */
    void logLater(String line) {
        post(() -> log(line));
    }

    void clearLog() {
        log.setText("");
    }

    /**
     * Adds a problem reported by the run to Problems and the log; any thread. A run that reports
     * more than {@value #RUN_PROBLEM_LIMIT} problems (a bus fault repeating) shows the first ones
     * and logs the rest.
     */
    void runProblemLater(Diagnostic d) {
        post(() -> {
            List<Diagnostic> now = problems.runDiagnostics();
            if (now.size() < RUN_PROBLEM_LIMIT) {
                List<Diagnostic> all = new ArrayList<>(now);
                all.add(d);
                problems.setRunDiagnostics(all);
            }
            log(d.format());
            if (d.severity() == Severity.ERROR) {
                folder.setSelection(0);
            }
        });
    }

    /** Shows the diagnostics of a run in Problems, replacing the run's earlier ones; any thread. */
    void showRunDiagnostics(List<Diagnostic> diagnostics) {
        List<Diagnostic> copy = List.copyOf(diagnostics);
        post(() -> {
            problems.setRunDiagnostics(copy);
            if (!copy.isEmpty()) {
                folder.setSelection(0);
            }
        });
    }

    /** Runs {@code r} on the UI thread unless the window has closed (then nobody is left to tell); any thread. */
    void post(Runnable r) {
        if (folder.isDisposed()) {
            return;
        }
        try {
            folder.getDisplay().asyncExec(() -> {
                if (!folder.isDisposed()) {
                    r.run();
                }
            });
        } catch (SWTException e) {
            // The display was disposed between the check and the call.
        }
    }
}
