package org.parpe.gui.app;

import org.parpe.gui.text.UiMsg;
import org.parpe.gui.prefs.Prefs;
import org.parpe.gui.run.CrashLog;

import org.parpe.gui.files.FileActions;
import org.parpe.gui.hardware.HardwareDialog;
import org.parpe.gui.hardware.HardwareHost;
import org.parpe.gui.view3d.ModuleCameraWindow;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.CTabFolder;
import org.eclipse.swt.custom.CTabItem;
import org.eclipse.swt.custom.SashForm;
import org.eclipse.swt.custom.StyledText;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Shell;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.load.LoadResult;
import org.parpe.core.model.Program;
import org.parpe.gui.diagram.DiagramPane;
import org.parpe.gui.editor.ParslEditor;
import org.parpe.gui.editor.ScriptDocument;
import org.parpe.gui.grid.GridPane;
import org.parpe.gui.panels.ControlPanel;
import org.parpe.gui.panels.OutlineView;
import org.parpe.gui.panels.PlotView;
import org.parpe.gui.panels.ProblemsView;
import org.parpe.gui.pose.PosePanel;
import org.parpe.gui.view3d.View3D;

/**
 * The IDE's main window: outline | editor over Problems and Run log | 3D view over controls and
 * plots, with the menu bar, the run tool bar and the status bar. Owns the wiring between them;
 * UI thread only (other threads use {@link #logLater}).
 */
public final class IdeWindow implements HardwareHost {
    private final Shell shell;
    /** Problems one run may add to the view; more are logged only. */
    static final int RUN_PROBLEM_LIMIT = 500;

    private static final String MAXIMISED = "window.maximised";
    private static final String FIRST_START = "tutorial.offered";
    /** The preference (Help > Open the Tutorial at Every Start) that opens the tutorial at each start, not only the first. */
    static final String TUTORIAL_AT_START = "tutorial.atStart";
    private final Prefs prefs;
    private final AlarmBanner alarm;
    private final MenuBar menus;
    private final RunChoices choices;
    private final ParslEditor editor;
    private final GridPane gaitGrid;
    private final DiagramPane diagram;
    private final CTabItem editorTab;
    private final ProblemsView problems;
    private final CTabFolder bottom;
    private final StyledText log;
    private String lastCrash;
    private String lastCrashFile;
    /** The problem counts the status bar says now (renewed when Problems changes), or null. */
    private String shownCounts;
    private final OutlineView outline;
    private final View3D view;
    private final ViewBar viewBar;
    private final ControlPanel controls;
    private final PlotView plots;
    private final StatusBar status;
    private final RunToolBar toolbar;
    private final ScriptDocument document;
    private final FileActions files;
    private final RunActions runs;
    private final PosePanel pose;
    private final org.parpe.gui.robot.RobotTab robotTab;
    private final CTabItem poseTab;
    private final SashForm editorSplit;
    private SashForm mainSash;
    private final TutorialDock tutorialDock;
    private HardwareDialog hardwareDialog;
    private volatile String hardwareHeld;
    private Program program;
    private int validations;
    private boolean wasRunning;
    private int zoom;

    public IdeWindow(Display display, Prefs prefs) {
        this.prefs = prefs;
        choices = new RunChoices(prefs);
        shell = new Shell(display, SWT.SHELL_TRIM);
        shell.setText("PARPE");
        shell.setImage(icon(display));
        shell.addDisposeListener(e -> shell.getImage().dispose());
        shell.setLayout(grid(1, 0));
        runs = new RunActions(this);
        toolbar = new RunToolBar(shell, runs, prefs);
        toolbar.control().setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        alarm = new AlarmBanner(shell);

        SashForm main = new SashForm(shell, SWT.HORIZONTAL);
        main.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        CTabFolder left = Panels.folder(main);
        outline = new OutlineView(left, this::reveal);
        Panels.tab(left, UiMsg.TAB_OUTLINE.text(), outline.control());

        SashForm middle = new SashForm(main, SWT.VERTICAL);
        editorSplit = middle;
        CTabFolder editorFolder = Panels.folder(middle);
        SashForm editorBox = new SashForm(editorFolder, SWT.HORIZONTAL);
        editor = new ParslEditor(editorBox);
        gaitGrid = new GridPane(editorBox, editor);
        editorTab = Panels.tab(editorFolder, "untitled.xml", editorBox);
        bottom = Panels.folder(middle);
        problems = new ProblemsView(bottom, d -> reveal(d.pos()), this::markProblems);
        Panels.tab(bottom, UiMsg.TAB_PROBLEMS.text(), problems.control());
        // Wrapped: a run's last lines (its score and parts) are read without scrolling sideways.
        log = new StyledText(bottom, SWT.READ_ONLY | SWT.V_SCROLL | SWT.MULTI | SWT.WRAP);
        log.setFont(org.eclipse.jface.resource.JFaceResources.getTextFont());
        Panels.tab(bottom, UiMsg.TAB_RUN_LOG.text(), log);
        middle.setWeights(72, 28);

        SashForm right = new SashForm(main, SWT.VERTICAL);
        CTabFolder viewFolder = Panels.folder(right);
        Composite viewBox = new Composite(viewFolder, SWT.NONE);
        viewBox.setLayout(grid(1, 0));
        viewBar = new ViewBar(viewBox, this, prefs);
        view = new View3D(viewBox);
        view.control().setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        viewBar.attach(view);
        Panels.tab(viewFolder, UiMsg.TAB_3D_VIEW.text(), viewBox);
        CTabFolder controlFolder = Panels.folder(right);
        controls = new ControlPanel(controlFolder, runs);
        Panels.tab(controlFolder, UiMsg.TAB_CONTROLS.text(), controls.control());
        CTabFolder plotFolder = Panels.folder(right);
        plots = new PlotView(plotFolder);
        org.parpe.gui.panels.ChartView.zoomAll(0); // a new window starts at the normal size, its plots too
        Panels.tab(plotFolder, UiMsg.TAB_JOINT_ANGLES.text(), plots.control());
        right.setWeights(54, 18, 28);
        main.setWeights(15, 43, 42);
        tutorialDock = new TutorialDock(left, main);
        // The grid beside the text widens the middle column, except while the Diagram tab is shown (the
        // diagram keeps its share, and nothing moves under the mouse when an edit there opens a table) or the
        // docked tutorial is in front (it keeps its column).
        gaitGrid.onShown(v -> {
            if (!diagramShown(viewFolder) && !tutorialDock.inFront()) {
                main.setWeights(v ? new int[] {11, 61, 28} : new int[] {15, 43, 42});
            }
        });
        // Sane minimums at 1366x768: the outline, the editor, the 3D view's tools, Problems and the plots stay usable.
        SashMinimum.keepMinimum(main, 120, 420, 300);
        SashMinimum.keepMinimum(middle, 160, 90);
        // the plots: 150 px, what the chart needs to draw its axes and legend (at 100 it was blank beside the Diagram tab)
        SashMinimum.keepMinimum(right, 150, 70, 150);
        this.mainSash = main;

        status = new StatusBar(shell);
        status.control().setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        files = new FileActions(shell, editor, prefs, this::documentChanged, this::fileSwitched, status::setMessage);
        document = new ScriptDocument(display, editor.document(), files::pathForLoading);
        document.addListener(l -> {
            if (l.names() != null) {
                editor.setNames(l.names());
            }
            showValidation(l.result());
        });
        org.parpe.gui.panels.FileDialogs.follow(files::file, org.parpe.gui.files.Examples.bundled());
        diagram = new DiagramPane(viewFolder, editor, document);
        diagram.sayPlacesWith(status::setMessage);
        Panels.tab(viewFolder, UiMsg.TAB_DIAGRAM.text(), diagram.control());
        robotTab = new org.parpe.gui.robot.RobotTab(viewFolder, new RobotBridge(this));
        Panels.tab(viewFolder, UiMsg.TAB_ROBOT.text(), robotTab.control());
        diagram.follow(runs.controller().live(), runs::running);
        diagram.breakpoints(runs.controller().breakpoints(), () -> runs.controller().setPaused(false), this::runStateChanged);
        viewFolder.addListener(SWT.Selection, e -> {
            boolean d = diagramShown(viewFolder);
            right.setWeights(d ? new int[] {84, 4, 12} : new int[] {54, 18, 28});
            if (!tutorialDock.inFront()) { // the docked tutorial keeps its column
                main.setWeights(d ? new int[] {10, 38, 52} : gaitGrid.visible() ? new int[] {11, 61, 28} : new int[] {15, 43, 42});
            }
        });
        menus = new MenuBar(this);
        menus.install();
        wire(display);
        // After wire(): the panel shows its posed robot in the 3D view, and the run's otherwise.
        pose = new PosePanel(bottom, new PoseBridge(this));
        poseTab = Panels.tab(bottom, UiMsg.TAB_POSE.text(), pose.control());
        diagram.usePoses(pose::selectedAngles);
        diagram.openTablesWith(gaitGrid::showTable);
        bottom.addListener(SWT.Selection, e -> fitBottom());
    }

    /** Whether {@code viewFolder} shows the Diagram tab or the Robot tab (both want the room). */
    private boolean diagramShown(CTabFolder viewFolder) {
        var shown = viewFolder.getSelection() == null ? null : viewFolder.getSelection().getControl();
        return shown != null && (diagram != null && shown == diagram.control() || robotTab != null && shown == robotTab.control());
    }

    /** The Pose panel needs more room than Problems and the Run log. */
    private void fitBottom() {
        editorSplit.setWeights(bottom.getSelection() == poseTab ? new int[] {40, 60} : new int[] {72, 28});
    }

    private static GridLayout grid(int columns, int margin) {
        GridLayout gl = new GridLayout(columns, false);
        gl.marginWidth = margin;
        gl.marginHeight = margin;
        gl.verticalSpacing = 0;
        return gl;
    }

    private void wire(Display display) {
        view.setSource(runs::snapshot);
        view.setHighlighted(runs::driven);
        view.setOverlay(() -> {
            var st = runs.controller().status();
            String entry = st == null || st.entry().isEmpty() || !runs.running() ? "" : UiMsg.OVERLAY_BEHAVIOR.text(st.entry());
            var snap = runs.snapshot();
            return String.format(java.util.Locale.ROOT, "t = %.2f s%s", snap == null ? 0 : snap.time(), entry)
                    + runs.scoreText();
        });
        view.startAnimation();
        editor.widget().addCaretListener(e -> {
            int line = editor.widget().getLineAtOffset(e.caretOffset);
            status.setCaret(line + 1, e.caretOffset - editor.widget().getOffsetAtLine(line) + 1);
        });
        Listener keys = new Listener();
        display.addFilter(SWT.KeyDown, keys);
        shell.addListener(SWT.Dispose, e -> display.removeFilter(SWT.KeyDown, keys));
        shell.addListener(SWT.Close, e -> e.doit = closeRequested());
        shell.addListener(SWT.Dispose, e -> {
            runs.dispose();
            document.close();
        });
        tickStatus();
        runStateChanged();
    }

    /**
     * Esc stops everything. During a run the keys bound to controls steer the robot wherever the
     * focus is in this window, the script editor and the gait table included (a steering key never
     * edits the script), except in a box that takes a typed value; the status bar says so.
     */
    private final class Listener implements org.eclipse.swt.widgets.Listener {
        @Override
        public void handleEvent(Event e) {
            if (shell.isDisposed()) {
                return;
            }
            if (e.keyCode == SWT.ESC) {
                if (runs.running()) {
                    runs.emergencyStop();
                }
                return;
            }
            var focus = e.display.getFocusControl();
            if ((e.stateMask & SWT.MOD1) != 0 && focus != null && focus.getShell() == shell && !tutorialDock.holds(focus)
                    && zoomKey(e)) { // the docked tutorial zooms its lesson itself
                e.doit = false;
                e.type = SWT.None;
                return;
            }
            if (focus == null || focus.getShell() != shell || !runs.running() || (e.stateMask & SWT.MODIFIER_MASK) != 0) {
                return;
            }
            boolean valueBox = (focus instanceof org.eclipse.swt.widgets.Text || focus instanceof org.eclipse.swt.widgets.Combo
                    || focus instanceof org.eclipse.swt.widgets.Spinner) && !gaitGrid.hasFocus();
            if (!valueBox && controls.key(e)) {
                // Neither the editor's nor the table's key handling sees it: the text stays as it was.
                e.doit = false;
                e.type = SWT.None;
            }
        }
    }

    /** Ctrl + / Ctrl − / Ctrl 0 ({@link #zoom(int)}), wherever the focus is in this window. */
    private boolean zoomKey(Event e) {
        int step = org.parpe.gui.panels.Zoom.step(e);
        if (step == org.parpe.gui.panels.Zoom.NONE) {
            return false;
        }
        zoom(step);
        return true;
    }

    /**
     * Larger ({@code step} 1), smaller (−1) or normal (0) text in every view that zooms: the
     * editor, the log, the gait table, the plots and the diagram (a projector). View → Zoom In /
     * Zoom Out / Reset Zoom and their keys come here.
     */
    void zoom(int step) {
        zoom = org.parpe.gui.panels.Zoom.next(zoom, step);
        org.parpe.gui.panels.Zoom.apply(editor.widget(), org.eclipse.jface.resource.JFaceResources.getTextFont(), zoom);
        org.parpe.gui.panels.Zoom.apply(log, org.eclipse.jface.resource.JFaceResources.getTextFont(), zoom);
        gaitGrid.zoom(zoom);
        org.parpe.gui.panels.ChartView.zoomAll(zoom);
        diagram.zoom(zoom);
        robotTab.zoom(zoom);
        status.setMessage(zoom == 0 ? UiMsg.ZOOM_NORMAL.text() : UiMsg.ZOOM_POINTS.text((zoom > 0 ? "+" : "") + zoom * 2));
    }

    /** How many steps of 2 points the text is zoomed in (negative: out). */
    int zoom() {
        return zoom;
    }

    /** The keys the program binds to its controls, as the status bar names them during a run. */
    private static String steeringKeys(Program p) {
        return p == null ? "" : String.join(" ", p.controls().stream().flatMap(c -> c.keys().stream()).distinct().toList());
    }

    private void tickStatus() {
        shell.getDisplay().timerExec(100, () -> {
            if (shell.isDisposed()) {
                return;
            }
            boolean running = runs.running();
            var st = runs.controller().status();
            String simState = (!toolbar.target().sim() ? UiMsg.SIM_OFF
                    : running ? (runs.controller().paused() ? UiMsg.SIM_PAUSED : UiMsg.SIM_RUNNING)
                    : UiMsg.SIM_IDLE).text();
            status.setSim(simState);
            String held = hardwareHeld;
            long since = runs.hardwareSilentSince();
            boolean silent = running && since >= 0;
            String hardware = held != null && !running ? held : runs.hardwareState();
            status.setHardware(hardware, silent ? UiMsg.ROBOT_SILENT_MESSAGE.text(RunActions.silentTime(since)) : null);
            alarm.show(silent ? UiMsg.ROBOT_SILENT_BANNER.text(RunActions.silentTime(since)) : null);
            if (st != null) {
                status.setTime(st.time());
            }
            if (running) {
                plots.refresh();
            }
            tickStatus();
        });
    }

    /** The red banner under the tool bar while the robot does not answer (tests). */
    AlarmBanner alarm() {
        return alarm;
    }

    /** Opens the window; then {@code file} if given, else recovers or starts a new script. */
    public void open(Path file, boolean automated) {
        org.eclipse.swt.graphics.Rectangle screen = shell.getDisplay().getPrimaryMonitor().getClientArea();
        int w = Math.min(1480, screen.width);
        int h = Math.min(920, screen.height);
        shell.setBounds(screen.x + (screen.width - w) / 2, screen.y + (screen.height - h) / 2, w, h);
        // A window the user maximised opens maximised again (a 1366x768 laptop needs every pixel).
        shell.setMaximized(Boolean.parseBoolean(prefs.get(MAXIMISED, "false")));
        shell.addListener(SWT.Close, e -> prefs.put(MAXIMISED, Boolean.toString(shell.getMaximized())));
        shell.open();
        boolean recovered = !automated && files.offerRecovery();
        if (!recovered) {
            if (file != null) {
                files.openPath(file);
            } else {
                files.newFile();
            }
        } else if (file != null && !file.toAbsolutePath().normalize().equals(files.file())) {
            // The recovered text stays in the editor until it is saved or set aside.
            status.setMessage(UiMsg.RECOVERED_NOT_OPENED.text(file.getFileName()));
        }
        editor.widget().setFocus();
        if (!automated && (prefs.get(FIRST_START, null) == null || tutorialAtStart(prefs))) {
            // Someone who has never used PARPE (a student who has never programmed) meets the tutorial first;
            // a class that starts with a lesson every time can ask for it at each start.
            prefs.put(FIRST_START, "done");
            menus.openTutorial();
        }
    }

    /** Whether the tutorial opens at every start (Help > Open the Tutorial at Every Start). */
    static boolean tutorialAtStart(Prefs prefs) {
        return "yes".equals(prefs.get(TUTORIAL_AT_START, "no"));
    }

    /** A different file is in the editor: forget what belonged to the previous one. */
    void fileSwitched() {
        if (pose != null) {
            pose.documentSwitched(files.file());
        }
        diagram.documentSwitched(files.file());
        choices.switchTo(files.pathForLoading());
        viewBar.show(choices.robot());
        viewBar.world().show(choices.world(org.parpe.sim.world.WorldReader.declaredBy(files.pathForLoading(),
                editor.document().get())));
        if (!runs.running()) {
            toolbar.setTarget(choices.target());
        }
        runs.invalidatePreview();
        program = null;
        gaitGrid.setProgram(null);
        outline.show(null);
        controls.show(null);
        plots.setRecorder(null);
        problems.setLoadDiagnostics(List.of());
        problems.clearRunDiagnostics();
        runs.forgetPreview();
        view.clear();
        robotTab.documentSwitched();
    }

    private void documentChanged() {
        if (pose != null && files.file() != null) {
            pose.documentRenamed(files.file()); // Save As: the poses stay with the document
        }
        if (files.file() != null) {
            diagram.documentRenamed(files.file()); // Save As: the diagram's node places go beside the new file
        }
        String mark = files.dirty() ? "*" : "";
        editorTab.setText(mark + files.name());
        shell.setText(mark + files.name() + " \u2014 PARPE");
        document.check();
    }

    /** Shows a load result: markers, Problems, outline, controls, plots and the robot preview. */
    void showValidation(LoadResult r) {
        validations++;
        if (robotTab.documentChecked(r.program())) { // a robot configuration: its own problems
            problems.setLoadDiagnostics(robotTab.problems());
            showProblemCounts("");
            return;
        }
        if (emptyScript()) {
            showEmpty();
            return;
        }
        problems.setLoadDiagnostics(r.diagnostics());
        if (r.program() != null) {
            program = r.program();
            gaitGrid.setProgram(program);
            outline.show(program);
            if (!runs.running()) {
                controls.show(program);
            }
            plots.setModules(program.moduleIds());
            runs.updatePreview(program);
        }
        if (!runs.running()) {
            showProblemCounts(editor.plain() ? UiMsg.NO_COLOURING.text(ParslEditor.COLOUR_LIMIT / 1_000_000) : "");
        }
    }

    /** Whether the editor holds no script yet (nothing, white space, or a declaration and comments): the Diagram's "Start a robot". */
    boolean emptyScript() {
        return org.parpe.core.edit.SectionEdits.blank(editor.document().get());
    }

    /**
     * An empty file is a beginning, not a mistake: no problem listed, and nothing left of the
     * script shown before (outline, table, controls, robot); the status bar says how to begin.
     */
    private void showEmpty() {
        problems.setLoadDiagnostics(List.of());
        program = null;
        gaitGrid.setProgram(null);
        outline.show(null);
        if (!runs.running()) {
            controls.show(null);
            runs.forgetPreview();
            view.clear();
            status.setMessage(empty());
        }
    }

    /** What the status bar says of an empty file. */
    static String empty() {
        return UiMsg.FILE_EMPTY.text();
    }

    /**
     * What Problems holds, in words: "No problems" only when it is empty. The status bar says this
     * after each check of the text and whenever Problems changes, so the two never disagree.
     */
    String problemCounts() {
        long errors = problems.errorCount();
        long warnings = problems.shown().size() - errors;
        if (errors == 0 && warnings == 0) {
            return UiMsg.NO_PROBLEMS.text();
        }
        String e = errors == 1 ? UiMsg.ERRORS_ONE.text() : UiMsg.ERRORS_N.text(errors);
        String w = warnings == 1 ? UiMsg.WARNINGS_ONE.text() : UiMsg.WARNINGS_N.text(warnings);
        return UiMsg.SEE_PROBLEMS.text(warnings == 0 ? e : errors == 0 ? w : UiMsg.ERRORS_AND_WARNINGS.text(e, w));
    }

    /** Says {@link #problemCounts()} in the status bar, then {@code more}; {@link #markProblems} renews it. */
    private void showProblemCounts(String more) {
        shownCounts = problemCounts() + more;
        status.setMessage(shownCounts);
    }

    /** Where the tutorial docks: a tab beside Outline. */
    TutorialDock tutorialDock() {
        return tutorialDock;
    }

    /** The outline | editor | 3D view split (tests). */
    SashForm mainSash() {
        return mainSash;
    }

    /** Whether Problems is the tab in front below the editor (tests). */
    boolean problemsInFront() {
        return bottom.getSelectionIndex() == 0;
    }

    /** Brings Problems to the front (a refused Run: what to fix is there). */
    void showProblems() {
        bottom.setSelection(0);
        if (editorSplit.getWeights()[1] < 150) {
            editorSplit.setWeights(72, 28);
        }
    }

    /** The Problems view changed: mark this file's problems in the editor. */
    private void markProblems() {
        String now = status.message();
        if (now.equals(shownCounts)) {
            showProblemCounts("");
        }
        status.setProblems(problems.errorCount(), problems.shown().size() - problems.errorCount());
        Path mine = files.pathForLoading().toAbsolutePath().normalize();
        List<Diagnostic> mineOnly = problems.shown().stream().filter(d -> sameFile(d.pos(), mine))
                .limit(ParslEditor.MARKER_LIMIT).toList();
        editor.setDiagnostics(mineOnly);
        gaitGrid.setDiagnostics(mineOnly);
    }

    private static boolean sameFile(SourcePos p, Path mine) {
        try {
            Path f = Path.of(p.file());
            return f.toAbsolutePath().normalize().equals(mine) || !f.isAbsolute() && mine.endsWith(f);
        } catch (RuntimeException e) {
            return false;
        }
    }

    /** Forgets the problems of the previous run (a new run is being prepared); UI thread. */
    void clearRunProblems() {
        problems.clearRunDiagnostics();
    }

    /**
     * Adds a problem reported by the run (a run-time error or warning of the script, a control
     * or parameter value refused, a robot configuration or bus problem) to Problems and the log.
     * Any thread: the update is posted to the UI thread. A run that reports more than
     * {@value #RUN_PROBLEM_LIMIT} problems (a bus fault repeating) shows the first ones and
     * logs the rest.
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
                bottom.setSelection(0);
            }
        });
    }

    /**
     * Shows the diagnostics of a run (run-time errors, overlap warnings, parameter and control
     * errors, robot configuration and bus faults) in Problems beside the load diagnostics,
     * replacing the run's earlier ones; they stay until the next run starts or another file is
     * opened. Any thread: the update is posted to the UI thread.
     */
    public void showRunDiagnostics(List<Diagnostic> diagnostics) {
        List<Diagnostic> copy = List.copyOf(diagnostics);
        post(() -> {
            problems.setRunDiagnostics(copy);
            if (!copy.isEmpty()) {
                bottom.setSelection(0);
            }
        });
    }

    /** Runs {@code r} on the UI thread unless the window has closed (then nobody is left to tell). */
    private void post(Runnable r) {
        if (shell.isDisposed()) {
            return;
        }
        try {
            shell.getDisplay().asyncExec(() -> {
                if (!shell.isDisposed()) {
                    r.run();
                }
            });
        } catch (org.eclipse.swt.SWTException e) {
            // The display was disposed between the check and the call.
        }
    }

    /** Jumps the editor to {@code pos} (if it is in this file). */
    void reveal(SourcePos pos) {
        if (pos != null && pos.line() > 0 && sameFile(pos, files.pathForLoading().toAbsolutePath().normalize())) {
            editor.reveal(pos);
        }
    }

    void runStateChanged() {
        boolean running = runs.running();
        if (running && !wasRunning) {
            problems.clearRunDiagnostics();
        }
        wasRunning = running;
        toolbar.update(running, running && runs.controller().paused());
        String keys = running ? steeringKeys(runs.controller().engine() == null ? program : runs.controller().engine().program()) : "";
        status.setKeys(keys.isEmpty() ? "" : UiMsg.STATUS_STEER.text(keys));
        plots.refresh();
        if (!running && program != null) {
            controls.show(program);
        }
    }

    /** One question before quitting: unsaved text and unsaved poses are asked about together. */
    boolean closeRequested() {
        return files.dirty() ? files.confirmDiscard(pose.lossSentence()) : pose.confirmClose();
    }

    /** Appends a line to the Run log. */
    void log(String line) {
        if (!log.isDisposed()) {
            log.append(String.format(java.util.Locale.ROOT, "[%tT] %s%n", System.currentTimeMillis(), line));
            log.setSelection(log.getCharCount()); // in sight, however many screen lines the wrapped lines take
        }
    }

    /**
     * A failure of PARPE itself while handling an event: a run going on is stopped first if it is
     * an Error (the window's state is unknown after one; Esc's stop, so that modules on the bus
     * stop at once and a run never goes on unwatched), then the crash file is written and named in
     * the Run log and the status bar. The same failure again (a listener failing on each paint)
     * names the file written for it the first time. Returns the crash file.
     */
    public String internalError(Throwable e) {
        // asyncExec hands on a runnable's Error wrapped in an SWTException
        if (e instanceof Error || e instanceof org.eclipse.swt.SWTException s && s.throwable instanceof Error) {
            try {
                runs.emergencyStop();
            } catch (RuntimeException | Error stopFailed) {
                e.addSuppressed(stopFailed);
            }
        }
        StackTraceElement[] at = e.getStackTrace();
        String what = e + (at.length > 0 ? " at " + at[0] : "");
        if (!what.equals(lastCrash)) {
            lastCrash = what;
            lastCrashFile = CrashLog.write("handling a UI event", e);
        }
        try {
            String message = UiMsg.INTERNAL_ERROR_UI.text(e, lastCrashFile);
            log(message);
            status.setMessage(message);
        } catch (RuntimeException | Error notShown) {
            // The file is written; the window cannot say so.
        }
        return lastCrashFile;
    }

    /** The menu bar's actions (tests). */
    MenuBar menus() {
        return menus;
    }

    /** The Run log's text (tests). */
    StyledText runLog() {
        return log;
    }

    /**
     * Brings the Run log to the front (a run's score is there), unless the Pose panel is: that is
     * the user's work, not a view of the run.
     */
    void showRunLog() {
        if (bottom.getSelection() != poseTab) {
            bottom.setSelection(1);
            log.setSelection(log.getCharCount());
        }
    }

    /** Whether the Run log is the tab in front below the editor. */
    boolean runLogInFront() {
        return bottom.getSelection() != null && bottom.getSelection().getControl() == log;
    }

    void clearLog() {
        log.setText("");
    }

    /** Says {@code message} in the status bar and the Run log, from any thread. */
    void sayLater(String message) {
        post(() -> {
            log(message);
            status.setMessage(message);
        });
    }

    /** {@link #log} from any thread. */
    void logLater(String line) {
        post(() -> log(line));
    }

    @Override
    public Shell shell() {
        return shell;
    }

    Prefs prefs() {
        return prefs;
    }

    public ParslEditor editor() {
        return editor;
    }

    /** The Diagram pane beside the 3D view. */
    public DiagramPane diagram() {
        return diagram;
    }

    /** The gait-table grid beside the editor. */
    public GridPane grid() {
        return gaitGrid;
    }

    public FileActions files() {
        return files;
    }

    public RunActions runs() {
        return runs;
    }

    @Override
    public String port() {
        return toolbar().port();
    }

    @Override
    public void setPort(String port) {
        toolbar().setPort(port);
    }

    @Override
    public String hardwareProfile() {
        return toolbar().hardwareProfile();
    }

    @Override
    public void setHardwareProfile(String file) {
        toolbar().setHardwareProfile(file);
    }

    @Override
    public void hardwareGone() {
        pose().hardwareGone();
    }

    @Override
    public org.eclipse.swt.widgets.Control posePanel() {
        return pose().control();
    }

    @Override
    public java.util.List<java.nio.file.Path> openFiles() {
        return files().openFiles();
    }

    @Override
    public HardwareDialog hardwareDialog() {
        return hardwareDialog;
    }

    @Override
    public void setHardwareDialog(HardwareDialog d) {
        hardwareDialog = d;
    }

    /** What the status bar says while the Hardware dialog holds a bus, or null. */
    String hardwareHeld() {
        return hardwareHeld;
    }

    @Override
    public void setHardwareHeld(String state) {
        hardwareHeld = state;
    }

    public StatusBar status() {
        return status;
    }

    public RunToolBar toolbar() {
        return toolbar;
    }

    public ControlPanel controls() {
        return controls;
    }

    OutlineView outline() {
        return outline;
    }

    public ProblemsView problems() {
        return problems;
    }

    PlotView plots() {
        return plots;
    }

    public View3D view() {
        return view;
    }

    String robotChoice() {
        return viewBar.robot();
    }

    /** The user picked {@code robot} for the file in the editor. */
    void robotChosen(String robot) {
        choices.robotChosen(robot);
        robotTab.robotChosen();
    }

    /** The Robot tab beside the 3D view. */
    public org.parpe.gui.robot.RobotTab robotTab() {
        return robotTab;
    }

    /** The user picked {@code world} ({@link WorldPicker#FLAT} or a world file) for the file in the editor. */
    void worldChosen(String world) {
        choices.worldChosen(world);
    }

    /** The user picked {@code target} for the file in the editor. */
    void targetChosen(org.parpe.gui.run.RunOn target) {
        choices.targetChosen(target);
    }

    public ViewBar viewBar() {
        return viewBar;
    }

    /** The Pose panel. */
    public PosePanel pose() {
        return pose;
    }

    /** Brings the Pose panel to the front. */
    public void showPosePanel() {
        bottom.setSelection(poseTab);
        fitBottom();
    }

    /** How many validation results have been shown (automation waits for the first). */
    public int validations() {
        return validations;
    }

    /** The last program that loaded, or null. */
    /** Opens a module camera window on the run, looking from the script's last module. */
    public ModuleCameraWindow openModuleCamera() {
        return ModuleCameraWindow.open(shell(), runs::snapshot, program != null ? program.moduleIds() : new int[0]);
    }

    /** The open script (the editor's text, loaded once per version). */
    ScriptDocument document() {
        return document;
    }

    public Program program() {
        return program;
    }

    /** PARPE's icon (the one the desktop menu shows), for the window's title bar and task bar. */
    static org.eclipse.swt.graphics.Image icon(Display display) {
        try (java.io.InputStream in = IdeWindow.class.getResourceAsStream("/org/parpe/gui/parpe.png")) {
            if (in == null) {
                throw new IllegalStateException("parpe.png is missing from the build of parpe-gui");
            }
            return new org.eclipse.swt.graphics.Image(display, in);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
