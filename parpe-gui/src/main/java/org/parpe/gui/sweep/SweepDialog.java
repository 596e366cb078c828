package org.parpe.gui.sweep;

import org.parpe.gui.panels.RobotChoice;
import java.nio.file.Path;
import java.util.List;
import org.eclipse.jface.text.DocumentEvent;
import org.eclipse.jface.text.IDocumentListener;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.ProgressBar;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.TabFolder;
import org.eclipse.swt.widgets.TabItem;
import org.parpe.core.io.OutputPlan;
import org.parpe.core.load.LoadResult;
import org.parpe.gui.editor.ScriptDocument;
import org.parpe.core.model.Parameter;
import org.parpe.gui.text.ToolMsg;
import org.parpe.sim.sweep.SweepRow;

/**
 * Run → Sweep / Optimise…: a window beside the IDE (not modal) on the editor's script, unsaved
 * edits included. Above, the robot, the world, the simulated seconds per run, the threads and
 * the objective; a Sweep tab and an Optimise tab; Start and Stop with a progress bar; the results
 * table and the plot filled as runs finish; "Apply best" and "Save CSV…" below. The engine
 * runs on worker threads ({@link SweepRunner}); this class runs on the UI thread only.
 */
public final class SweepDialog {
    private final SweepHost host;
    private final Shell shell;
    private final RunSettings settings;
    private final TabFolder tabs;
    private final SweepTab sweepTab;
    private final OptimiseTab optimiseTab;
    private final Button start;
    private final Button stop;
    private final ProgressBar progress;
    private final Label counts;
    private final Label message;
    private final ResultsPane pane;
    private final Button apply;
    private final Button save;
    private final IDocumentListener edits = new IDocumentListener() {
        @Override
        public void documentAboutToBeChanged(DocumentEvent event) {
        }

        @Override
        public void documentChanged(DocumentEvent event) {
            edited = true;
        }
    };
    private boolean edited;
    private List<Parameter> parameters = List.of();
    private Results results;
    private SweepRunner runner;
    private int total;
    private long startedAt;
    /** Counts the starts, so that news of an earlier one can never reach the later one's table. */
    private int generation;

    private SweepDialog(SweepHost host) {
        this.host = host;
        shell = new Shell(host.shell(), SWT.SHELL_TRIM | SWT.MODELESS);
        shell.setLayout(new GridLayout(1, false));
        settings = new RunSettings(org.parpe.gui.panels.WrapRow.of(shell), host.robot().get(), host.world().get());
        tabs = new TabFolder(shell, SWT.TOP);
        tabs.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, false));
        sweepTab = new SweepTab(tabs);
        tab(ToolMsg.SWEEP_TAB_SWEEP.text(), sweepTab.control());
        optimiseTab = new OptimiseTab(tabs);
        tab(ToolMsg.SWEEP_TAB_OPTIMISE.text(), optimiseTab.control());
        ((GridData) tabs.getLayoutData()).heightHint = 270;

        Composite bar = row(shell, 4);
        start = button(bar, ToolMsg.SWEEP_START.text(), this::start);
        stop = button(bar, ToolMsg.SWEEP_STOP.text(), this::stop);
        progress = new ProgressBar(bar, SWT.HORIZONTAL);
        progress.setMaximum(1000);
        progress.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        counts = new Label(bar, SWT.NONE);
        counts.setLayoutData(new GridData(280, SWT.DEFAULT));
        message = new Label(shell, SWT.WRAP);
        GridData wrap = new GridData(SWT.FILL, SWT.CENTER, true, false);
        wrap.widthHint = 300;
        message.setLayoutData(wrap);

        pane = new ResultsPane(shell);
        Composite bottom = row(shell, 3);
        apply = button(bottom, ToolMsg.SWEEP_APPLY_BEST.text(), this::applyBest);
        apply.setToolTipText(ToolMsg.SWEEP_APPLY_BEST_TIP.text());
        save = button(bottom, ToolMsg.SWEEP_SAVE_CSV.text(), this::saveCsv);
        button(bottom, ToolMsg.SWEEP_CLOSE.text(), shell::close);
        shell.setDefaultButton(start);
        wire();
    }

    private static Composite row(Composite parent, int columns) {
        Composite c = new Composite(parent, SWT.NONE);
        GridLayout gl = new GridLayout(columns, false);
        gl.marginHeight = 2;
        c.setLayout(gl);
        c.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        return c;
    }

    private void tab(String text, org.eclipse.swt.widgets.Control control) {
        TabItem item = new TabItem(tabs, SWT.NONE);
        item.setText(text);
        item.setControl(control);
    }

    private static Button button(Composite parent, String text, Runnable action) {
        Button b = new Button(parent, SWT.PUSH);
        b.setText(text);
        b.addListener(SWT.Selection, e -> action.run());
        return b;
    }

    private void wire() {
        host.editor().document().addDocumentListener(edits);
        shell.addListener(SWT.Activate, e -> reloadIfEdited());
        shell.addListener(SWT.Close, e -> {
            if (runner != null) {
                runner.stop();
            }
        });
        shell.addListener(SWT.Dispose, e -> {
            // The IDE window closing disposes this one without a Close event.
            if (runner != null) {
                runner.stop();
            }
            host.editor().document().removeDocumentListener(edits);
            if (results != null) {
                results.discard();
            }
        });
        setRunning(false);
    }

    /** Opens the dialog on {@code host}'s editor. */
    public static SweepDialog open(SweepHost host) {
        SweepDialog d = new SweepDialog(host);
        d.reload();
        // 1200x900 where the screen has room; on a 1366x768 laptop no taller than the screen (it scrolled off its bottom)
        org.eclipse.swt.graphics.Rectangle screen = host.shell().getMonitor().getClientArea();
        d.shell.setSize(Math.min(1200, screen.width), Math.min(900, screen.height));
        d.shell.open();
        return d;
    }

    /** The dialog's window. */
    public Shell shell() {
        return shell;
    }

    /** Brings the dialog to the front and reads the script's parameters again if it was edited. */
    public void activate() {
        shell.setActive();
        reloadIfEdited();
    }

    private void reloadIfEdited() {
        if (edited && (runner == null || !runner.running())) {
            reload();
        }
    }

    /** Reads the editor's script and shows its parameters; returns its parameters, or null when it does not load. */
    private List<Parameter> reload() {
        edited = false;
        ScriptDocument.Loaded loaded = host.document().loaded();
        Path file = loaded.file();
        shell.setText(ToolMsg.SWEEP_TITLE.text(file.getFileName()));
        LoadResult r = loaded.result();
        if (r.program() == null) {
            String first = r.errors().isEmpty() ? ToolMsg.SWEEP_DOES_NOT_LOAD.text(file) : r.errors().get(0).format();
            error(r.errors().size() > 1 ? ToolMsg.SWEEP_AND_MORE.text(first, r.errors().size() - 1) : first);
            return null;
        }
        List<Parameter> now = r.program().parameters();
        if (!now.equals(parameters)) {
            parameters = now;
            sweepTab.setParameters(now);
        }
        return now;
    }

    private void start() {
        if (runner != null && runner.running()) {
            return;
        }
        List<Parameter> now = reload();
        if (now == null) {
            return;
        }
        try {
            StartRequest req = new StartRequest(host.document().file(), host.document().text(), settings.robot().robot(),
                    settings.world().world(), settings.duration(), settings.jobs(), settings.objective());
            boolean sweeping = tabs.getSelectionIndex() == 0;
            SweepRunner.Events events = new Events(++generation);
            StartRequest.Started s = sweeping ? req.sweep(now, sweepTab, shell.getDisplay(), events)
                    : req.optimise(now, optimiseTab, shell.getDisplay(), events);
            if (results != null) {
                results.discard();
            }
            results = s.results();
            runner = s.runner();
            total = s.total();
        } catch (org.parpe.sim.sweep.SweepException e) {
            error(StartRequest.inDialogWords(e.text()).toString());
            return;
        }
        pane.show(results);
        progress.setSelection(0);
        counts.setText(ToolMsg.SWEEP_COUNTS.text(0, total, ""));
        startedAt = System.nanoTime();
        info(ToolMsg.SWEEP_RUNNING.text(total, settings.duration().trim(), settings.jobs()));
        setRunning(true);
    }

    /** Receives the runner's news on the UI thread; ignores a runner that is no longer the current one. */
    private final class Events implements SweepRunner.Events {
        private final int start;

        Events(int start) {
            this.start = start;
        }

        private boolean stale() {
            return shell.isDisposed() || start != generation;
        }

        @Override
        public void rows(List<SweepRow> rows, int done, int of) {
            if (stale()) {
                return;
            }
            rows.forEach(results::add);
            pane.refresh();
            progress.setSelection(of == 0 ? 0 : (int) (1000L * done / of));
            counts.setText(ToolMsg.SWEEP_COUNTS.text(done, of, timeLeft(done, of)));
            apply.setEnabled(results.best() != null);
        }

        @Override
        public void finished(List<SweepRow> all, boolean cancelled, String error) {
            if (stale()) {
                return;
            }
            setRunning(false);
            if (error != null) {
                error(error);
                return;
            }
            // An optimisation's final list is the engine's (its order); a sweep's rows all came through rows()
            // in order. Stopped: the dialog keeps every run that finished, so Stop never throws finished work away.
            if (all != null && (!cancelled || all.size() >= results.count())) {
                results.replace(all);
            }
            int kept = results.count();
            pane.refresh();
            counts.setText(ToolMsg.SWEEP_COUNTS.text(kept, total, ""));
            if (!cancelled) {
                progress.setSelection(1000);
            }
            SweepRow best = results.best();
            String head = cancelled ? ToolMsg.SWEEP_STOPPED_AFTER.text(kept, total) : ToolMsg.SWEEP_FINISHED.text(kept);
            String said = head + " " + (best == null ? noBest() : results.bestSentence(best));
            info(results.complete() ? said : ToolMsg.SWEEP_SHOWN_FIRST.text(said, results.rows().size(), kept));
            apply.setEnabled(best != null);
        }

        @Override
        public void problems(List<org.parpe.core.diag.Diagnostic> problems) {
            if (!stale()) {
                host.problems().accept(problems);
            }
        }
    }

    /** ", about 1 min 20 s left" from the pace so far, or empty before the first run is done. */
    private String timeLeft(int done, int of) {
        if (done <= 0 || done >= of) {
            return "";
        }
        double left = (System.nanoTime() - startedAt) / 1e9 / done * (of - done);
        long s = Math.round(left);
        return ToolMsg.SWEEP_TIME_LEFT.text(s >= 3600 ? s / 3600 + " h " + s % 3600 / 60 + " min"
                : s >= 60 ? s / 60 + " min " + s % 60 + " s" : s + " s");
    }

    /** Why no run can be the best, with the counts the table's columns show. */
    private String noBest() {
        if (results.count() == 0) {
            return ToolMsg.SWEEP_NO_RUN_FINISHED.text();
        }
        int failed = results.failed();
        int fell = results.fell();
        return results.mode() == Results.Mode.SWEEP
                ? ToolMsg.SWEEP_NO_BEST.text(fell, failed)
                : ToolMsg.SWEEP_NO_RUN_MET.text();
    }

    private void stop() {
        if (runner != null && runner.running()) {
            runner.stop();
            stop.setEnabled(false);
            info(ToolMsg.SWEEP_STOPPING.text());
        }
    }

    private void setRunning(boolean running) {
        start.setEnabled(!running);
        stop.setEnabled(running);
        save.setEnabled(!running && results != null && results.count() > 0);
        apply.setEnabled(results != null && results.best() != null);
        tabs.setEnabled(!running);
        settings.setEnabled(!running);
    }

    private void applyBest() {
        if (results == null) {
            return;
        }
        Path now = host.document().file();
        if (!now.equals(results.script())) {
            error(ToolMsg.SWEEP_OTHER_SCRIPT.text(results.script().getFileName(), now.getFileName()));
            return;
        }
        try {
            String what = ApplyBest.apply(host.editor(), host.document().loaded(), results.bestValues());
            info(ToolMsg.SWEEP_APPLIED.text(what));
        } catch (org.parpe.sim.sweep.SweepException e) {
            error(e.getMessage());
        }
    }

    private void saveCsv() {
        String name = host.document().file().getFileName().toString().replaceFirst("\\.xml$", "");
        Path p = org.parpe.gui.panels.FileDialogs.ask(shell, SWT.SAVE, ToolMsg.SWEEP_SAVE_CSV_TITLE.text(), "*.csv",
                name + (results.mode() == Results.Mode.SWEEP ? "-sweep.csv" : "-optimise.csv"), null);
        if (p != null) {
            saveCsv(p);
        }
    }

    /** Writes the rows to {@code file} off the UI thread and says when it is done. */
    void saveCsv(Path file) {
        if (OutputPlan.sameFile(host.document().file(), file)) {
            error(ToolMsg.SWEEP_SAVE_OVER_SCRIPT.text(file.getFileName()));
            return;
        }
        CsvExport.inBackground(shell.getDisplay(), file, results, total, (ok, said) -> {
            if (shell.isDisposed()) {
                return;
            }
            if (ok) {
                info(said);
            } else {
                error(said);
            }
        });
    }

    private void info(String text) {
        message.setForeground(null);
        message.setText(text);
        shell.layout(true, true);
    }

    private void error(String text) {
        message.setForeground(shell.getDisplay().getSystemColor(SWT.COLOR_RED));
        message.setText(text);
        shell.layout(true, true);
    }

    // Accessors for the tests of this package.

    String message() {
        return message.getText();
    }

    SweepTab sweepTab() {
        return sweepTab;
    }

    OptimiseTab optimiseTab() {
        return optimiseTab;
    }

    ResultsTable table() {
        return pane.table();
    }

    Results results() {
        return results;
    }

    boolean running() {
        return runner != null && runner.running();
    }

    void setDuration(String seconds) {
        settings.setDuration(seconds);
    }

    void setJobs(int n) {
        settings.setJobs(n);
    }

    void selectTab(int index) {
        tabs.setSelection(index);
    }

    RobotChoice robot() {
        return settings.robot();
    }

    WorldChoice world() {
        return settings.world();
    }

    void selectObjective(org.parpe.sim.sweep.Objective o) {
        settings.selectObjective(o);
    }

    Button startButton() {
        return start;
    }

    Button stopButton() {
        return stop;
    }

    Button applyButton() {
        return apply;
    }
}
