package org.parpe.gui.app;

import java.nio.file.Path;
import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.CTabFolder;
import org.eclipse.swt.custom.CTabItem;
import org.eclipse.swt.custom.SashForm;
import org.eclipse.swt.custom.StyledText;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Shell;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.model.Program;
import org.parpe.gui.automation.BenchHost;
import org.parpe.gui.diagram.DiagramPane;
import org.parpe.gui.editor.ParslEditor;
import org.parpe.gui.editor.ScriptDocument;
import org.parpe.gui.files.Examples;
import org.parpe.gui.files.FileActions;
import org.parpe.gui.grid.GridPane;
import org.parpe.gui.panels.ChartView;
import org.parpe.gui.panels.ControlPanel;
import org.parpe.gui.panels.FileDialogs;
import org.parpe.gui.panels.OutlineView;
import org.parpe.gui.panels.PlotView;
import org.parpe.gui.panels.ProblemsView;
import org.parpe.gui.pose.PosePanel;
import org.parpe.gui.prefs.Prefs;
import org.parpe.gui.robot.RobotTab;
import org.parpe.gui.text.UiMsg;
import org.parpe.gui.view3d.ModuleCameraWindow;
import org.parpe.gui.view3d.View3D;
import org.parpe.sim.world.WorldReader;

/**
 * The IDE's main window: outline | editor over Problems and Run log | 3D view over controls and
 * plots, with the menu bar, the run tool bar and the status bar. Builds them and hands each
 * feature what it needs of the others: the open script's {@link ScriptDocument}, and a narrow host
 * (the bridges of this package) where a feature's package declares one. How the window shows a
 * check of the script is {@link CheckResults}, its keys {@link WindowKeys}, its columns
 * {@link ColumnWeights}, the tabs below the editor {@link BottomTabs}. UI thread only (other
 * threads use {@link #sayLater}).
 */
public final class IdeWindow {
    private static final String MAXIMISED = "window.maximised";
    private static final String FIRST_START = "tutorial.offered";
    /** The preference (Help > Open the Tutorial at Every Start) that opens the tutorial at each start, not only the first. */
    static final String TUTORIAL_AT_START = "tutorial.atStart";

    // The window's parts, read by the bridges and collaborators of this package (and by the tests
    // of other packages through IdeAccess); other packages' main code reaches them through hosts.
    final Shell shell;
    final Prefs prefs;
    /** The robot, world and target chosen for each file. */
    final RunChoices choices;
    /** How the window shows each check of the script. */
    final CheckResults checks = new CheckResults(this);
    /** The window as the Hardware dialog sees it. */
    final HardwareBridge hardware = new HardwareBridge(this);
    private final EventFailures crashes = new EventFailures(this);
    private final WindowKeys keys = new WindowKeys(this);
    final RunActions runs;
    final RunToolBar toolbar;
    /** The red banner under the tool bar while the robot does not answer. */
    final AlarmBanner alarm;
    /** The outline | editor | 3D view split. */
    final SashForm mainSash;
    final OutlineView outline;
    final TutorialDock tutorialDock;
    final ParslEditor editor;
    /** The gait-table grid beside the editor. */
    final GridPane grid;
    private final CTabItem editorTab;
    /** The tabs below the editor: Problems, the Run log, the Pose panel. */
    final BottomTabs bottom;
    final View3D view;
    final ViewBar viewBar;
    final ControlPanel controls;
    final PlotView plots;
    final StatusBar status;
    final FileActions files;
    /** The open script (the editor's text, loaded once per version). */
    final ScriptDocument document;
    /** The Diagram pane beside the 3D view. */
    final DiagramPane diagram;
    /** The Robot tab beside the 3D view. */
    final RobotTab robotTab;
    /** The menu bar's actions. */
    final MenuBar menus;
    /** The Pose panel. */
    final PosePanel pose;
    private boolean wasRunning;

    public IdeWindow(Display display, Prefs prefs) {
        this.prefs = prefs;
        choices = new RunChoices(prefs);
        shell = new Shell(display, SWT.SHELL_TRIM);
        shell.setText("PARPE");
        shell.setImage(Panels.icon(display));
        shell.addDisposeListener(e -> shell.getImage().dispose());
        shell.setLayout(gridLayout(1, 0));
        runs = new RunActions(this);
        toolbar = new RunToolBar(shell, runs, prefs);
        toolbar.control().setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        alarm = new AlarmBanner(shell);
        mainSash = new SashForm(shell, SWT.HORIZONTAL);
        mainSash.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        CTabFolder left = Panels.folder(mainSash);
        outline = new OutlineView(left, this::reveal);
        Panels.tab(left, UiMsg.TAB_OUTLINE.text(), outline.control());
        EditorColumn middle = middleColumn();
        editor = middle.editor();
        grid = middle.grid();
        editorTab = middle.tab();
        bottom = middle.bottom();
        ViewColumn right = rightColumn();
        viewBar = right.bar();
        view = right.view();
        controls = right.controls();
        plots = right.plots();
        CTabFolder viewFolder = right.folder();
        tutorialDock = new TutorialDock(left, mainSash);
        ColumnWeights columns = new ColumnWeights(mainSash, (SashForm) viewFolder.getParent(), viewFolder, grid, tutorialDock);
        status = new StatusBar(shell);
        status.control().setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        files = new FileActions(shell, editor, prefs, this::documentChanged, this::fileSwitched, status::setMessage);
        document = new ScriptDocument(display, editor.document(), files::pathForLoading);
        document.addListener(this::checked);
        FileDialogs.follow(files::file, Examples.bundled());
        diagram = new DiagramPane(viewFolder, editor, document);
        diagram.sayPlacesWith(status::setMessage);
        columns.wide(Panels.tab(viewFolder, UiMsg.TAB_DIAGRAM.text(), diagram.control()).getControl());
        robotTab = new RobotTab(viewFolder, new RobotBridge(this));
        columns.wide(Panels.tab(viewFolder, UiMsg.TAB_ROBOT.text(), robotTab.control()).getControl());
        diagram.follow(runs.controller().live(), runs::running);
        diagram.breakpoints(runs.controller().breakpoints(), () -> runs.controller().setPaused(false), this::runStateChanged);
        menus = new MenuBar(this);
        menus.install();
        wire(display);
        // After wire(): the panel shows its posed robot in the 3D view, and the run's otherwise.
        pose = new PosePanel(bottom.folder(), new PoseBridge(this));
        bottom.addPose(pose.control());
        diagram.usePoses(pose::selectedAngles);
        diagram.openTablesWith(grid::showTable);
    }

    /** The middle column's parts. */
    private record EditorColumn(ParslEditor editor, GridPane grid, CTabItem tab, BottomTabs bottom) {
    }

    /** The right column's parts: the views' folder (3D view, later Diagram and Robot), its bar, the controls, the plots. */
    private record ViewColumn(CTabFolder folder, ViewBar bar, View3D view, ControlPanel controls, PlotView plots) {
    }

    /** The editor with the gait table beside it, over Problems and the Run log. */
    private EditorColumn middleColumn() {
        SashForm middle = new SashForm(mainSash, SWT.VERTICAL);
        CTabFolder editorFolder = Panels.folder(middle);
        SashForm editorBox = new SashForm(editorFolder, SWT.HORIZONTAL);
        ParslEditor text = new ParslEditor(editorBox);
        GridPane table = new GridPane(editorBox, text);
        CTabItem tab = Panels.tab(editorFolder, "untitled.xml", editorBox);
        BottomTabs below = new BottomTabs(middle, d -> reveal(d.pos()), checks::problemsChanged);
        SashMinimum.keepMinimum(middle, 160, 90);
        return new EditorColumn(text, table, tab, below);
    }

    /** The 3D view (and later the Diagram and Robot tabs) over the controls and the plots. */
    private ViewColumn rightColumn() {
        SashForm right = new SashForm(mainSash, SWT.VERTICAL);
        CTabFolder viewFolder = Panels.folder(right);
        Composite viewBox = new Composite(viewFolder, SWT.NONE);
        viewBox.setLayout(gridLayout(1, 0));
        ViewBar bar = new ViewBar(viewBox, this, prefs);
        View3D view3d = new View3D(viewBox);
        view3d.control().setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        bar.attach(view3d);
        Panels.tab(viewFolder, UiMsg.TAB_3D_VIEW.text(), viewBox);
        CTabFolder controlFolder = Panels.folder(right);
        ControlPanel panel = new ControlPanel(controlFolder, runs);
        Panels.tab(controlFolder, UiMsg.TAB_CONTROLS.text(), panel.control());
        CTabFolder plotFolder = Panels.folder(right);
        PlotView plotView = new PlotView(plotFolder);
        ChartView.zoomAll(0); // a new window starts at the normal size, its plots too
        Panels.tab(plotFolder, UiMsg.TAB_JOINT_ANGLES.text(), plotView.control());
        return new ViewColumn(viewFolder, bar, view3d, panel, plotView);
    }

    private static GridLayout gridLayout(int columns, int margin) {
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
        display.addFilter(SWT.KeyDown, keys);
        shell.addListener(SWT.Dispose, e -> display.removeFilter(SWT.KeyDown, keys));
        shell.addListener(SWT.Close, e -> e.doit = closeRequested());
        shell.addListener(SWT.Dispose, e -> {
            runs.dispose();
            document.close();
        });
        StatusTicker.start(this, hardware);
        runStateChanged();
    }

    /** Opens the window; then {@code file} if given, else recovers or starts a new script. */
    public void open(Path file, boolean automated) {
        Rectangle screen = shell.getDisplay().getPrimaryMonitor().getClientArea();
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
        viewBar.world().show(choices.world(WorldReader.declaredBy(files.pathForLoading(), editor.document().get())));
        if (!runs.running()) {
            toolbar.setTarget(choices.target());
        }
        runs.invalidatePreview();
        checks.forget();
        plots.setRecorder(null);
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

    /** A version of the script was checked: completion learns its names, and the window shows the result. */
    private void checked(ScriptDocument.Loaded loaded) {
        if (loaded.names() != null) {
            editor.setNames(loaded.names());
        }
        checks.show(loaded.result());
    }

    /** Jumps the editor to {@code pos} (if it is in this file). */
    void reveal(SourcePos pos) {
        if (pos != null && pos.line() > 0 && CheckResults.sameFile(pos, files.pathForLoading().toAbsolutePath().normalize())) {
            editor.reveal(pos);
        }
    }

    void runStateChanged() {
        boolean running = runs.running();
        if (running && !wasRunning) {
            problems().clearRunDiagnostics();
        }
        wasRunning = running;
        toolbar.update(running, running && runs.controller().paused());
        Program p = program();
        String steer = running ? steeringKeys(runs.controller().engine() == null ? p : runs.controller().engine().program()) : "";
        status.setKeys(steer.isEmpty() ? "" : UiMsg.STATUS_STEER.text(steer));
        plots.refresh();
        if (!running && p != null) {
            controls.show(p);
        }
    }

    /** The keys the program binds to its controls, as the status bar names them during a run. */
    private static String steeringKeys(Program p) {
        return p == null ? "" : String.join(" ", p.controls().stream().flatMap(c -> c.keys().stream()).distinct().toList());
    }

    /** One question before quitting: unsaved text and unsaved poses are asked about together. */
    boolean closeRequested() {
        return files.dirty() ? files.confirmDiscard(pose.lossSentence()) : pose.confirmClose();
    }

    /**
     * A failure of PARPE itself while handling an event ({@link EventFailures}): a run going on is
     * stopped if it is an Error, and the crash file is written and named. Returns the crash file.
     */
    public String internalError(Throwable e) {
        return crashes.report(e);
    }

    /** Says {@code message} in the status bar and the Run log, from any thread. */
    void sayLater(String message) {
        bottom.post(() -> {
            bottom.log(message);
            status.setMessage(message);
        });
    }

    /**
     * Shows the diagnostics of a run (run-time errors, overlap warnings, parameter and control
     * errors, robot configuration and bus faults) in Problems beside the load diagnostics,
     * replacing the run's earlier ones; they stay until the next run starts or another file is
     * opened. Any thread: the update is posted to the UI thread.
     */
    void showRunDiagnostics(List<Diagnostic> diagnostics) {
        bottom.showRunDiagnostics(diagnostics);
    }

    /** Opens a module camera window on the run, looking from the script's last module. */
    ModuleCameraWindow openModuleCamera() {
        Program p = program();
        return ModuleCameraWindow.open(shell, runs::snapshot, p != null ? p.moduleIds() : new int[0]);
    }

    /** Whether the window has closed (the event loop of {@code Main} runs until it has). */
    public boolean closed() {
        return shell.isDisposed();
    }

    /** The window as the command line's automation and the IDE benchmark drive it. */
    public BenchHost automated() {
        return new AutomationBridge(this);
    }

    /** The Problems view below the editor. */
    ProblemsView problems() {
        return bottom.problems();
    }

    /** The last program that loaded, or null. */
    Program program() {
        return checks.program();
    }

    /** How many validation results have been shown (automation waits for the first). */
    int validations() {
        return checks.validations();
    }

    /** The robot picked in the 3D view's bar. */
    String robotChoice() {
        return viewBar.robot();
    }

    /** The user picked {@code robot} for the file in the editor. */
    void robotChosen(String robot) {
        choices.robotChosen(robot);
        robotTab.robotChosen();
    }

    /** View → Zoom In (1) / Zoom Out (−1) / Reset Zoom (0) ({@link WindowKeys#zoom(int)}). */
    void zoom(int step) {
        keys.zoom(step);
    }

    /** How many steps of 2 points the text is zoomed in (negative: out). */
    int zoom() {
        return keys.zoom();
    }

    /** The Run log's text. */
    StyledText runLog() {
        return bottom.log();
    }
}
