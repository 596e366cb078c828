package org.parpe.gui.diagram;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Supplier;
import org.eclipse.jface.text.BadLocationException;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.layout.RowData;
import org.eclipse.swt.layout.RowLayout;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Text;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.diag.SourceSpan;
import org.parpe.core.edit.TextEdit;
import org.parpe.gui.diagram.Projection.View;
import org.parpe.gui.editor.AfterChange;
import org.parpe.gui.editor.ParslEditor;
import org.parpe.gui.editor.ScriptDocument;
import org.parpe.gui.text.PanelMsg;

/**
 * The Diagram pane: one view of the open document (program lane, swimlanes, automaton ring,
 * phase wheel, gait diagram) drawn from the text, never stored anywhere else. It is made again
 * a moment after the text changes ({@link AfterChange}, as the grid editor) (off the UI thread: the script is loaded, and for the gait
 * the engine run, on a worker), only while the pane is shown. Clicking a node selects its
 * element in the editor; the caret in the text selects the node whose element holds it; a text
 * island opens the text at its line. The selected node's values (a state's duration, an
 * instance's phase and offset, an entry's time) are fields: Enter writes the value through
 * {@link org.parpe.core.diagram.DiagramEdits} as one replacement of the document, so Edit →
 * Undo takes it back in one step. UI thread only.
 */
public final class DiagramPane {

    private final ParslEditor editor;
    private final ScriptDocument document;
    private final Composite box;
    private final Combo viewChoice;
    private final Combo subjectChoice;
    private final Composite fields;
    private final Label message;
    private final int twoRows;
    private final SceneCanvas canvas;
    private final LiveBar liveBar;
    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "parpe-diagram");
        t.setDaemon(true);
        return t;
    });
    private final AtomicLong generation = new AtomicLong();
    private View view = View.PROGRAM;
    private String subject;
    private Projection shown;
    private SourcePos selected;
    private boolean following;
    private Point dragFrom;
    private Projection.Target dragged;
    private Projection.Target offered;
    private Supplier<String> pose;
    private java.util.function.Predicate<String> tables;
    private Runnable written;
    private String told;
    private int fitWidth = -1;
    private final Palette palette;
    private final PlacesBeside places = new PlacesBeside(this::say);
    private final FreeNodes freeNodes;

    /** The pane in {@code parent}, showing {@code document}, the text of {@code editor}. */
    public DiagramPane(Composite parent, ParslEditor editor, ScriptDocument document) {
        this.editor = editor;
        this.document = document;
        box = new Composite(parent, SWT.NONE);
        GridLayout gl = new GridLayout(1, false);
        gl.marginWidth = 2;
        gl.marginHeight = 2;
        gl.verticalSpacing = 2;
        box.setLayout(gl);
        // few rows above the drawing (issue 24): at 1366×768 the drawing keeps at least half the tab
        Composite bar = new Composite(box, SWT.NONE);
        bar.setLayout(row());
        bar.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        Label viewLabel = new Label(bar, SWT.NONE);
        viewLabel.setText(PanelMsg.DIAGRAM_VIEW.text());
        // on the label, not the choosers: a tool tip over a chooser covered its open list (issue 31)
        viewLabel.setToolTipText(PanelMsg.DIAGRAM_VIEW_TIP.text());
        viewChoice = new Combo(bar, SWT.READ_ONLY);
        for (View v : View.values()) {
            viewChoice.add(v.label.text());
        }
        viewChoice.select(0);
        viewChoice.addListener(SWT.Selection, e -> setView(View.values()[viewChoice.getSelectionIndex()]));
        subjectChoice = new Combo(bar, SWT.READ_ONLY);
        subjectChoice.setLayoutData(new RowData(170, SWT.DEFAULT));
        subjectChoice.addListener(SWT.Selection, e -> {
            subject = subjectChoice.getText();
            relayout();
        });
        palette = new Palette(bar, this);
        fields = new Composite(box, SWT.NONE);
        fields.setLayout(row());
        GridData fd = new GridData(SWT.FILL, SWT.CENTER, true, false);
        // as tall with fields as without, so that the drawing does not move when a node is selected;
        // two rows: a palette item or a state has more fields than one row of a narrow tab holds
        Text probe = new Text(fields, SWT.BORDER | SWT.SINGLE);
        twoRows = 2 * probe.computeSize(SWT.DEFAULT, SWT.DEFAULT).y + 4;
        fd.heightHint = twoRows;
        probe.dispose();
        fields.setLayoutData(fd);
        message = new Label(box, SWT.WRAP);
        // two lines, always there, whatever it says: a message after an edit does not move the drawing
        // under the mouse (issue 31); a wider text wraps at the tab's width instead of widening it
        GridData md = new GridData(SWT.FILL, SWT.TOP, true, false);
        md.heightHint = 2 * lineHeight(message);
        md.widthHint = 100;
        message.setLayoutData(md);
        liveBar = new LiveBar(box, this);
        canvas = new SceneCanvas(box, this::clicked);
        canvas.control().setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        showFields();
        freeNodes = new FreeNodes(this, canvas, places);
        canvas.control().addListener(SWT.Resize, e -> laidOutAgain());
        canvas.control().addListener(SWT.MouseDown, e -> {
            dragged = e.button == 1 ? movable(e.x, e.y) : null;
            dragFrom = e.button == 1 && (wheel() != null || dragged != null) ? new Point(e.x, e.y) : null;
        });
        canvas.control().addListener(SWT.MouseMove, e -> {
            if (dragFrom != null && dragged(e.x, e.y)) {
                if (wheel() != null) {
                    previewPhase(phaseAt(e.x, e.y));
                } else {
                    message.setText(PanelMsg.DIAGRAM_RELEASE_ENTRY.text());
                }
            }
        });
        canvas.control().addListener(SWT.MouseUp, e -> {
            if (dragFrom != null && dragged(e.x, e.y)) {
                if (wheel() != null) {
                    dropPhase(e.x, e.y);
                } else {
                    dropEntry(dragged, movable(e.x, e.y));
                }
            }
            dragFrom = null;
            if (!dragMarks.isEmpty()) {
                dragMarks = List.of();
                repaintOverlay();
            }
        });
        editor.widget().addCaretListener(e -> caretAt(e.caretOffset));
        AfterChange soon = new AfterChange(box, editor.document(), this::relayout);
        box.addListener(SWT.Show, e -> soon.schedule());
        box.addListener(SWT.Resize, e -> fitFields());
        box.addListener(SWT.Dispose, e -> {
            generation.incrementAndGet();
            worker.shutdownNow();
        });
    }

    /** A row of controls that wraps only when the tab is too narrow, with little margin. */
    static RowLayout row() {
        return org.parpe.gui.panels.WrapRow.layout();
    }

    
    /** The height of a line of text in {@code c}'s font. */
    static int lineHeight(Control c) {
        org.eclipse.swt.graphics.GC gc = new org.eclipse.swt.graphics.GC(c);
        try {
            return gc.getFontMetrics().getHeight();
        } finally {
            gc.dispose();
        }
    }

    /** Sets the message line (its row keeps its height; a text longer than it shows whole as its tool tip). */
    void say(String text) {
        message.setText(text);
        message.setToolTipText(text.isEmpty() ? null : text);
        box.layout(true, true);
    }

    /**
     * The edit row's height: two rows of fields, or as many as its fields need at the tab's width,
     * so that no Add button is hidden under the message line. The same node after an edit needs the
     * same height: nothing moves.
     */
    private void fitFields() {
        GridData fd = (GridData) fields.getLayoutData();
        int width = box.getClientArea().width - 4;
        int need = width > 0 ? fields.computeSize(width, SWT.DEFAULT).y : 0;
        // at the same width the row never shrinks: what an Add switches to does not pull the drawing up
        int h = Math.max(width == fitWidth ? fd.heightHint : twoRows, need);
        fitWidth = width;
        if (fd.heightHint != h) {
            fd.heightHint = h;
            box.layout(true, true);
        }
    }

    /** Shows {@code c} in its row of the pane, or takes the row away. */
    private static void show(Control c, boolean shown) {
        c.setVisible(shown);
        ((GridData) c.getLayoutData()).exclude = !shown;
    }

    /** The pane's control (the host puts it in a tab). */
    public Control control() {
        return box;
    }

    /** Shows view {@code v} of the document. */
    public void setView(View v) {
        view = v;
        viewChoice.select(v.ordinal());
        subject = null;
        selected = null;
        relayout();
    }

    /** Shows view {@code v} on {@code label} (a behavior, automaton or instance as the subject chooser names it). */
    public void setView(View v, String label) {
        setView(v);
        subject = label;
        relayout();
    }

    /** Projects the current text on the worker if the pane is shown; the newest request wins. */
    void relayout() {
        if (box.isDisposed() || !box.isVisible()) {
            return;
        }
        long gen = generation.incrementAndGet();
        document.whenLoaded(loaded -> {
            if (gen != generation.get() || box.isDisposed()) {
                return;
            }
            View v = view;
            String s = subject;
            org.parpe.core.diagram.NodePlaces at = places.places();
            var display = box.getDisplay();
            worker.execute(() -> {
                if (gen != generation.get()) {
                    return;
                }
                Projection p = Projection.of(loaded, v, s, at);
                if (!display.isDisposed()) {
                    display.asyncExec(() -> {
                        if (gen == generation.get() && !box.isDisposed()) {
                            show(p);
                        }
                    });
                }
            });
        });
    }

    private void show(Projection p) {
        p = readable(p);
        shown = p;
        // a text that does not load for a moment (an Undo in two steps, typing) keeps the subject chosen
        if (p.subject() != null) {
            subject = p.subject();
        }
        List<String> items = p.subjects();
        if (!items.equals(List.of(subjectChoice.getItems()))) {
            subjectChoice.setItems(items.toArray(String[]::new));
        }
        subjectChoice.setEnabled(!items.isEmpty());
        if (p.subject() != null) {
            subjectChoice.select(items.indexOf(p.subject()));
        }
        if (p.view() == View.PHASE && p.targets().size() == 1) {
            selected = p.targets().keySet().iterator().next();
        } else if (selected != null && !p.targets().containsKey(selected) && canvas.centre(selected) == null) {
            selected = null;
        }
        canvas.show(p.scene() == null ? new org.parpe.core.diagram.Scene(1, 1) : p.scene());
        liveMarks = List.of();
        liveCounts = null;
        liveLabels = null;
        liveProgress = null;
        liveBar.shown();
        canvas.select(selected);
        message.setText(!p.message().isEmpty() ? p.message() : told != null ? told : !p.targets().isEmpty() ? PanelMsg.DIAGRAM_HINT.text() : "");
        told = null;
        showFields();
        box.layout(true, true);
    }

    /** The text scale the ring or the wheel shown is laid out with ({@link #readable}). */
    private double textScale = 1;

    /**
     * {@code p} with its ring or wheel laid out with text large enough to read on the canvas as
     * it is now: the canvas would otherwise make small text larger where it lies, and labels laid
     * out apart would meet. A few rounds, as larger text makes the drawing larger.
     */
    private Projection readable(Projection p) {
        textScale = 1;
        if (p.scene() == null || p.ring() == null && p.wheel() == null) {
            return p;
        }
        Projection out = p;
        for (int round = 0; round < 8; round++) {
            double need = canvas.textScale(out.scene(), org.parpe.core.diagram.Layouts.RING_TEXT);
            if (need <= textScale * 1.001) {
                break;
            }
            textScale = need;
            out = p.withTextScale(textScale);
        }
        return out;
    }

    /**
     * The drawing's smallest text is {@code steps} × 2 points larger than normal (the window's
     * zoom, {@link org.parpe.gui.panels.Zoom}): other text grows to it, and the ring and the wheel
     * are laid out again so that their labels stay apart.
     */
    public void zoom(int steps) {
        canvas.zoom(org.parpe.gui.panels.Zoom.factor(box.getDisplay().getSystemFont(), steps));
        laidOutAgain();
    }

    /** The canvas changed size or the zoom: the ring or the wheel is laid out again for it. */
    private void laidOutAgain() {
        if (shown != null && (shown.ring() != null || shown.wheel() != null) && shown.scene() != null) {
            double before = textScale;
            Projection p = readable(shown.withTextScale(1));
            if (textScale != before) {
                shown = p;
                canvas.show(p.scene());
                canvas.select(selected);
                repaintOverlay();
            }
        }
    }

    /**
     * Another document is shown ({@code file}, or {@code null} when untitled): the free nodes
     * take the places kept beside it ({@link PlacesBeside}).
     */
    public void documentSwitched(Path file) {
        // a palette item's inputs belong to the file they were opened on
        offered = null;
        places.documentSwitched(file);
        relayout();
    }

    /** The document was saved as {@code file}: its free nodes' places go beside it. */
    public void documentRenamed(Path file) {
        places.documentRenamed(file);
    }

    /** What the places beside the script cannot be read or written is said with {@code status} (once each). */
    public void sayPlacesWith(java.util.function.Consumer<String> status) {
        places.sayWith(status);
    }

    /** The places of the free nodes now (what is, or will be, beside the script). */
    public org.parpe.core.diagram.NodePlaces places() {
        return places.places();
    }

    /** Where on the canvas the middle of free node {@code name} is drawn, or {@code null}. */
    public Point whereFree(String name) {
        org.parpe.core.diagram.Workbench.Placed n = freeNodes.node(name);
        return n == null ? null : canvas.toCanvas(n.sceneX() + n.w() / 2, n.sceneY() + n.h() / 2);
    }

    /** Where free node {@code name} is on its workbench ({@code x, y}), or {@code null} when it is not drawn. */
    public double[] freeAt(String name) {
        org.parpe.core.diagram.Workbench.Placed n = freeNodes.node(name);
        return n == null ? null : new double[] {n.x(), n.y()};
    }

    /** The projection shown, or {@code null} before the first. */
    public Projection shown() {
        return shown;
    }

    /** Whether the diagram shows the editor's current text. */
    public boolean current() {
        return shown != null && shown.text().equals(editor.document().get());
    }

    /** The node selected, or {@code null}. */
    public SourcePos selected() {
        return selected;
    }

    /** The canvas, for tests that click on it. */
    public org.eclipse.swt.widgets.Canvas canvas() {
        return canvas.control();
    }

    /** The drawing's texts as last painted: each one's extent on the canvas (pixels) and its text. */
    public List<java.util.Map.Entry<org.eclipse.swt.graphics.Rectangle, String>> drawnTexts() {
        return canvas.drawnTexts();
    }

    /** Where on the canvas {@code node} is drawn (a click there selects it), or {@code null}. */
    public Point where(SourcePos node) {
        return canvas.centre(node);
    }

    /** The line under the view chooser: what the view cannot show or why it is empty. */
    public String message() {
        return message.getText();
    }

    /** The value fields of the selected node, by name. */
    public java.util.Map<String, Text> fields() {
        java.util.Map<String, Text> out = new java.util.LinkedHashMap<>();
        for (Control c : fields.getChildren()) {
            if (c instanceof Text t) {
                out.put((String) t.getData("field"), t);
            }
        }
        return out;
    }

    /** The choosers of the edit row (its inputs that list the script's names), by name. */
    public java.util.Map<String, Combo> choosers() {
        java.util.Map<String, Combo> out = new java.util.LinkedHashMap<>();
        for (Control c : fields.getChildren()) {
            if (c instanceof Combo k) {
                out.put((String) k.getData("field"), k);
            }
        }
        return out;
    }

    /** A click on the canvas: select the node's element, or open an island's text at its line. */
    private void clicked(SourcePos node) {
        offered = null;
        if (shown == null) {
            return;
        }
        if (node == null) {
            if (shown.view() == View.PHASE) {
                return;
            }
            selected = null;
            canvas.select(null);
            showFields();
            return;
        }
        selected = node;
        canvas.select(node);
        showFields();
        if (node.span() != null && node.file().equals(shown.file().toString()) && current()) {
            SourceSpan s = node.span();
            following = true;
            try {
                editor.viewer().setSelectedRange(s.start(), s.end() - s.start());
                editor.viewer().revealRange(s.start(), s.end() - s.start());
            } finally {
                following = false;
            }
        } else if (node.line() > 0 && node.file().equals(shown.file().toString())) {
            editor.reveal(node.line(), node.column());
        }
    }

    /** The caret moved in the text: select the innermost drawn node whose element holds it. */
    private void caretAt(int offset) {
        if (following || shown == null || shown.scene() == null || !current()) {
            return;
        }
        SourcePos best = null;
        for (var s : shown.scene().shapes()) {
            SourcePos p = s instanceof org.parpe.core.diagram.Scene.Rect r ? r.source()
                    : s instanceof org.parpe.core.diagram.Scene.Sector c ? c.source() : null;
            if (p != null && p.span() != null && p.file().equals(shown.file().toString()) && offset >= p.span().start()
                    && offset <= p.span().end()
                    && (best == null || p.span().end() - p.span().start() < best.span().end() - best.span().start())) {
                best = p;
            }
        }
        if (best != null && !best.equals(selected)) {
            selected = best;
            canvas.select(best);
            showFields();
        }
    }

    /** How often the live overlay looks for new states: 40 frames per second at most (the engine publishes up to 50). */
    private static final int LIVE_MS = 25;

    /**
     * Follows runs: while {@code running} holds and the ring or the lanes are shown, each state's
     * arc is marked with the number of modules in it, or each bar with the modules it drives, from what the engine thread published in {@code live}
     * (copied out here, on the UI thread; the engine never waits for the view).
     */
    public void follow(org.parpe.gui.run.LiveStates live, java.util.function.BooleanSupplier running) {
        box.getDisplay().timerExec(LIVE_MS, new Runnable() {
            private long seen = -1;
            private Projection drawn;

            @Override
            public void run() {
                long started = System.nanoTime();
                if (box.isDisposed()) {
                    return;
                }
                if (drawn != shown) {
                    // a new drawing: show the last frame again (a run paused at a breakpoint publishes no new one)
                    drawn = shown;
                    seen = -1;
                }
                if (liveBar.scrubbing()) {
                    // the trace's frame is shown, not the run's
                } else if (box.isVisible() && shown != null && (shown.ring() != null || shown.lanes() != null
                        || shown.gait() != null) && running.getAsBoolean()) {
                    var frame = live.since(seen);
                    if (frame != null && frame.tick() >= 0) {
                        seen = frame.version();
                        liveWhat = PanelMsg.DIAGRAM_LIVE.text();
                        overlay(frame);
                    }
                } else if (liveCounts != null) {
                    liveCounts = null;
                    liveMarks = List.of();
                    repaintOverlay();
                }
                // every LIVE_MS from the start of this frame, not after it
                box.getDisplay().timerExec((int) Math.max(1, LIVE_MS - (System.nanoTime() - started) / 1_000_000), this);
            }
        });
    }

    private int[] liveCounts;
    private long liveTick = -1;
    private String[] liveLabels;
    private double[] liveProgress;
    private String liveWhat = PanelMsg.DIAGRAM_LIVE.text();
    private List<org.parpe.core.diagram.Scene.Shape> liveMarks = List.of();
    /** The phase wheel's hand and ticks where the drag going on would put them. */
    private List<org.parpe.core.diagram.Scene.Shape> dragMarks = List.of();
    private GaitOverlay gaitOverlay;

    /**
     * The run's breakpoints (set on the ring's states), how to go on from one (Continue), and
     * whom to tell when the run stops at one or goes on (the tool bar's Pause/Resume).
     */
    public void breakpoints(org.parpe.core.run.Breakpoints bp, Runnable resume, Runnable changed) {
        liveBar.breakpoints(bp, resume, changed);
    }

    /** Draws the live marks, the breakpoints and the wheel's dragged hand over the drawing. */
    void repaintOverlay() {
        List<org.parpe.core.diagram.Scene.Shape> all = new ArrayList<>(liveMarks);
        all.addAll(dragMarks);
        if (shown != null && shown.ring() != null && shown.scene() != null) {
            all.addAll(liveBar.marks(shown.ring(), shown.scene()));
        }
        canvas.overlay(all);
    }

    /** Shows frame {@code f} as the overlay ({@code what}: "live" or "trace"), or no overlay for {@code null}. */
    void showFrame(org.parpe.gui.run.LiveStates.Frame f, String what) {
        if (f == null || shown == null || shown.scene() == null
                || shown.ring() == null && shown.lanes() == null && shown.gait() == null) {
            liveCounts = null;
            liveMarks = List.of();
            repaintOverlay();
            return;
        }
        liveWhat = what;
        overlay(f);
    }

    /** The script of the open text as loaded now, or {@code null} when it does not load. */
    org.parpe.core.model.Program program() {
        return document.loaded().program();
    }

    /** The open text as loaded now. */
    ScriptDocument.Loaded loaded() {
        return document.loaded();
    }

    /** Opens the trace {@code csv} for scrubbing through the views (as Trace… does). */
    public void scrub(Path csv) {
        liveBar.scrub(csv);
    }

    /** Shows tick {@code k} of the trace being scrubbed (as the slider does). */
    public void scrubTo(int k) {
        liveBar.scrubTo(k);
    }

    /** Brings the pane's tab to the front (as a click on it does) and returns the tab's text. */
    public String showTab() {
        if (box.getParent() instanceof org.eclipse.swt.custom.CTabFolder folder) {
            for (org.eclipse.swt.custom.CTabItem item : folder.getItems()) {
                if (item.getControl() == box) {
                    folder.setSelection(item);
                    folder.notifyListeners(SWT.Selection, new org.eclipse.swt.widgets.Event());
                    return item.getText();
                }
            }
        }
        return "";
    }

    /** Shows the view named {@code name} ({@code PROGRAM}, {@code LANES}, {@code RING}, {@code PHASE}, {@code GAIT}). */
    public void showView(String name) {
        setView(View.valueOf(name));
    }

    /** The name of the view drawn, or {@code ""} before the first. */
    public String viewShown() {
        return shown == null ? "" : shown.view().name();
    }

    /**
     * Draws frame {@code f} as the live overlay and paints it at once (for the benchmark: the time
     * this takes is what one frame of the overlay costs the UI thread).
     */
    public void drawFrame(org.parpe.gui.run.LiveStates.Frame f) {
        showFrame(f, PanelMsg.DIAGRAM_LIVE.text());
        canvas.control().update();
    }

    /** How many times the drawing (with its overlay) was painted on screen (for the benchmark). */
    public long paints() {
        return canvas.paints();
    }

    /** The line of the run row: the breakpoint the run is paused at, or the trace's time. */
    public String liveLine() {
        return liveBar.line();
    }

    /** On the ring, per module, how far it is through its state as its dot shows it (−1: not on this ring); {@code null} without a ring overlay. */
    public double[] liveProgress() {
        return liveCounts == null || liveProgress == null ? null : liveProgress.clone();
    }

    /** On the gait diagram, per module, the state its "now" cell shows; {@code null} without a gait overlay. */
    public String[] liveLabels() {
        return liveCounts == null || liveLabels == null ? null : liveLabels.clone();
    }

    /** Marks the gait diagram with the time of {@code f} and each module's state then. */
    private void gaitOverlay(org.parpe.gui.run.LiveStates.Frame f) {
        if (gaitOverlay == null || gaitOverlay.gait() != shown.gait()) {
            gaitOverlay = new GaitOverlay(shown.gait());
        }
        liveMarks = gaitOverlay.marks(f, liveWhat);
        liveCounts = gaitOverlay.counts();
        liveLabels = gaitOverlay.labels();
        liveProgress = null;
        liveTick = f.tick();
        repaintOverlay();
    }

    /** Marks each bar of the lanes with the modules it drives at {@code f}'s tick. */
    private void lanesOverlay(org.parpe.gui.run.LiveStates.Frame f) {
        var lanes = shown.lanes();
        List<org.parpe.core.diagram.Swimlanes.Bar> bars = new ArrayList<>();
        lanes.lanes().forEach(l -> bars.addAll(l.bars()));
        int[] counts = new int[bars.size()];
        if (f.entry() == lanes.entry()) {
            for (int m = 0; m < f.instance().length; m++) {
                int i = f.instance()[m];
                if (i >= 0 && i < counts.length) {
                    counts[i]++;
                }
            }
        }
        liveCounts = counts;
        liveLabels = null;
        liveProgress = null;
        liveTick = f.tick();
        List<org.parpe.core.diagram.Scene.Shape> marks = new ArrayList<>();
        for (var s : shown.scene().shapes()) {
            for (var b : bars) {
                if (s instanceof org.parpe.core.diagram.Scene.Rect r && b.pos().equals(r.source()) && counts[b.index()] > 0) {
                    marks.add(new org.parpe.core.diagram.Scene.Rect(r.x() - 3, r.y() - 3, r.w() + 6, r.h() + 6,
                            org.parpe.core.diagram.Scene.NONE, 0x009e73, 3, null));
                    marks.add(new org.parpe.core.diagram.Scene.Text(r.x() + r.w() - 8, r.y() + 14, PanelMsg.DIAGRAM_DRIVEN_NOW.text(counts[b.index()]),
                            11, 1, 0x009e73, true));
                }
            }
        }
        marks.add(new org.parpe.core.diagram.Scene.Text(shown.scene().width() - 12, 28, (f.entry() == lanes.entry()
                ? PanelMsg.DIAGRAM_TICK_LANES : PanelMsg.DIAGRAM_TICK_OTHER_ENTRY).text(liveWhat, f.tick()), 11, 1,
                0x222222, false));
        liveMarks = marks;
        repaintOverlay();
    }

    /** Marks each arc of the ring with the modules in its state at {@code f}'s tick. */
    private void overlay(org.parpe.gui.run.LiveStates.Frame f) {
        if (shown.lanes() != null) {
            lanesOverlay(f);
            return;
        }
        if (shown.gait() != null) {
            gaitOverlay(f);
            return;
        }
        var ring = shown.ring();
        int[] counts = new int[ring.arcs().size()];
        List<String> automata = f.entry() >= 0 && f.entry() < shown.automata().size() ? shown.automata().get(f.entry()) : List.of();
        for (int m = 0; m < f.instance().length; m++) {
            int i = f.instance()[m];
            int k = f.state()[m];
            if (i >= 0 && i < automata.size() && automata.get(i).equals(ring.automaton()) && k >= 0 && k < counts.length) {
                counts[k]++;
            }
        }
        liveCounts = counts;
        liveLabels = null;
        liveTick = f.tick();
        List<org.parpe.core.diagram.Scene.Shape> marks = new ArrayList<>();
        for (var s : shown.scene().shapes()) {
            if (s instanceof org.parpe.core.diagram.Scene.Sector c && c.source() != null) {
                for (var arc : ring.arcs()) {
                    if (arc.from() == c.from() && arc.to() == c.to() && counts[arc.index()] > 0) {
                        marks.add(new org.parpe.core.diagram.Scene.Sector(c.cx(), c.cy(), c.r0() - 10, c.r0() - 2, c.from(),
                                c.to(), 0x222222, org.parpe.core.diagram.Scene.NONE, null));
                        double[] p = org.parpe.core.diagram.Scene.onCircle(c.cx(), c.cy(), c.r0() - 22, (c.from() + c.to()) / 2);
                        marks.add(new org.parpe.core.diagram.Scene.Text(p[0], p[1] + 4, Integer.toString(counts[arc.index()]),
                                12, 0, 0x222222, true));
                    }
                }
            }
        }
        liveProgress = new double[f.instance().length];
        marks.addAll(RingProgress.marks(ring, shown.scene(), f, automata, liveProgress));
        // under the ring's title, not beside it, and as much lower as the ring's text is larger ({@link #readable})
        marks.add(new org.parpe.core.diagram.Scene.Text(shown.scene().width() - 12, 50 * textScale,
                PanelMsg.DIAGRAM_TICK_RING.text(liveWhat, f.tick()), 11, 1, 0x222222, false));
        liveMarks = marks;
        repaintOverlay();
    }

    /**
     * The live overlay's modules per state of the ring shown, or per bar of the lanes shown (in
     * instance order), at {@link #liveTick()}; {@code null} when there is no overlay.
     */
    public int[] liveCounts() {
        return liveCounts == null ? null : liveCounts.clone();
    }

    /** The engine tick of the live overlay shown, or −1. */
    public long liveTick() {
        return liveCounts == null ? -1 : liveTick;
    }

    /** The node at canvas pixel {@code x, y} if it can be moved by dragging, else {@code null}. */
    private Projection.Target movable(int x, int y) {
        if (shown == null) {
            return null;
        }
        double[] p = canvas.toScene(x, y);
        Projection.Target t = shown.targets().get(canvas.hit(p[0], p[1]));
        return t != null && t.moveTo() != null ? t : null;
    }

    /** An entry was dragged onto another: move it to that one's place (one Undo step). */
    private void dropEntry(Projection.Target from, Projection.Target onto) {
        if (from == null || onto == null || from.index() == onto.index()) {
            return;
        }
        if (!current()) {
            say(PanelMsg.DIAGRAM_CHANGED.text());
            return;
        }
        apply(from.moveTo().apply(onto.index()));
    }

    /** The wheel's circle (centre and radius, in scene units) while a phase wheel is shown, else {@code null}. */
    private double[] wheel() {
        if (shown == null || shown.wheel() == null || shown.scene() == null) {
            return null;
        }
        for (var s : shown.scene().shapes()) {
            if (s instanceof org.parpe.core.diagram.Scene.Sector c && c.source() == null && c.from() == 0 && c.to() == 1) {
                return new double[] {c.cx(), c.cy(), c.r1()};
            }
        }
        return null;
    }

    private boolean dragged(int x, int y) {
        return Math.abs(x - dragFrom.x) + Math.abs(y - dragFrom.y) > 3;
    }

    /**
     * The phase that puts position 1's tick at canvas pixel {@code x, y}: its angle on the wheel
     * less the offset, in [0, 1) (in (−1, 0] when the phase was negative), to 0.01 of a cycle.
     */
    private double phaseAt(int x, int y) {
        double[] c = wheel();
        double[] p = canvas.toScene(x, y);
        double f = Math.atan2(p[0] - c[0], -(p[1] - c[1])) / (2 * Math.PI);
        double phase = f - shown.wheel().offset();
        phase -= Math.floor(phase);
        if (shown.wheel().phase() < 0 && phase > 0) {
            phase -= 1;
        }
        return Math.round(phase * 100) / 100.0;
    }

    /** While the hand is dragged: the hand and the ticks where {@code phase} puts them, and the delays it gives, in words. */
    private void previewPhase(double phase) {
        var moved = shown.wheel().withPhase(phase);
        dragMarks = org.parpe.core.diagram.Layouts.wheelPreview(moved, textScale);
        repaintOverlay();
        StringBuilder delays = new StringBuilder();
        for (var t : moved.ticks().subList(0, Math.min(6, moved.ticks().size()))) {
            delays.append(delays.length() == 0 ? "" : ", ").append(org.parpe.core.lang.Numbers.format(Math.round(t.delay() * 100) / 100.0));
        }
        message.setText(PanelMsg.DIAGRAM_RELEASE_PHASE.text(org.parpe.core.lang.Numbers.format(phase),
                delays + (moved.ticks().size() > 6 ? ", \u2026" : "")));
    }

    /** The wheel's hand and ticks drawn where the drag going on would put them (empty while none is). */
    public List<org.parpe.core.diagram.Scene.Shape> dragPreview() {
        return dragMarks;
    }

    /** A drag on the phase wheel ended at {@code x, y}: write the phase it sets. */
    private void dropPhase(int x, int y) {
        Projection.Target t = shown.targets().get(shown.wheel().pos());
        if (t == null) {
            say(PanelMsg.DIAGRAM_INSTANCE_ELSEWHERE.text());
            return;
        }
        String value = org.parpe.core.lang.Numbers.format(phaseAt(x, y));
        for (Projection.Field f : t.fields()) {
            if (f.name().equals("phase")) {
                write(f, value);
            }
        }
    }

    /** Where on the canvas the phase wheel's point at fraction {@code f} of a turn is, or {@code null}. */
    public Point onWheel(double f) {
        double[] c = wheel();
        if (c == null) {
            return null;
        }
        double[] p = org.parpe.core.diagram.Scene.onCircle(c[0], c[1], c[2], f);
        return canvas.toCanvas(p[0], p[1]);
    }

    /** The edit row: the selected node's values as fields (Enter in one writes it) and its actions ({@link EditRow}). */
    private void showFields() {
        SourcePos key = selected != null ? selected : shown == null ? null : shown.home();
        // a file with no script (a robot configuration) has no home node: nothing to edit
        Projection.Target t = offered != null ? offered : key == null ? null : shown.targets().get(key);
        EditRow.fill(fields, t, shown == null ? null : org.parpe.gui.editor.NameIndex.of(shown.text()), this::write, this::act,
                pose);
        // a view with nothing to select or edit (the gait diagram) has no edit row
        show(fields, t != null || shown != null && !shown.targets().isEmpty());
        fields.layout(true);
        fitFields();
        liveBar.update();
        say(message.getText());
    }

    /** Shows {@code t} (a palette item's inputs) in the edit row until a node is clicked. */
    void offer(Projection.Target t) {
        offered = t;
        showFields();
    }

    /**
     * Takes poses from {@code selected} (the Pose panel's selected pose as angles, or null): a
     * state's edit row gets "Use pose", and a pose dragged onto a state of the ring becomes its angles.
     */
    public void usePoses(Supplier<String> selected) {
        boolean first = pose == null;
        pose = selected;
        if (!first) {
            showFields();
            return;
        }
        var drop = new org.eclipse.swt.dnd.DropTarget(canvas.control(), org.eclipse.swt.dnd.DND.DROP_COPY
                | org.eclipse.swt.dnd.DND.DROP_DEFAULT);
        drop.setTransfer(org.eclipse.swt.dnd.TextTransfer.getInstance());
        drop.addDropListener(new org.eclipse.swt.dnd.DropTargetAdapter() {
            @Override
            public void drop(org.eclipse.swt.dnd.DropTargetEvent e) {
                Point p = canvas.control().toControl(e.x, e.y);
                dropPose(p.x, p.y, (String) e.data);
            }
        });
        showFields();
    }

    /** Text {@code angles} was dropped at canvas pixel {@code x, y}: the state there takes them as its angles. */
    void dropPose(int x, int y, String angles) {
        double[] p = canvas.toScene(x, y);
        Projection.Target t = shown == null ? null : shown.targets().get(canvas.hit(p[0], p[1]));
        Projection.Field f = t == null ? null : t.fields().stream().filter(g -> g.name().equals("angles")).findFirst().orElse(null);
        if (f == null) {
            say(PanelMsg.DIAGRAM_DROP_POSE.text());
            return;
        }
        act(new Projection.Action(PanelMsg.DIAGRAM_USE_POSE.text(), List.of(), v -> f.edit().apply(EditRow.usable(angles))), List.of());
    }

    /** Opens a gait table the pane has just written with {@code show} (the grid editor's, by table name). */
    public void openTablesWith(java.util.function.Predicate<String> show) {
        tables = show;
    }

    /** The palette, for tests. */
    Palette palette() {
        return palette;
    }

    /** The action buttons of the edit row, by label. */
    public java.util.Map<String, org.eclipse.swt.widgets.Button> actions() {
        java.util.Map<String, org.eclipse.swt.widgets.Button> out = new java.util.LinkedHashMap<>();
        for (Control c : fields.getChildren()) {
            if (c instanceof org.eclipse.swt.widgets.Button b) {
                out.put((String) b.getData("action"), b);
            }
        }
        return out;
    }

    /** Button {@code a} was pressed with its inputs' {@code values}: write its edit (one Undo step). */
    private void act(Projection.Action a, List<String> values) {
        if (!current()) {
            say(PanelMsg.DIAGRAM_CHANGED.text());
            return;
        }
        written = null;
        try {
            apply(a.edit().apply(values));
            if (a.name().equals(Projection.EXPAND.text())) {
                openTable(values.get(0));
            }
            if (written != null) {
                written.run();
            }
        } catch (IllegalArgumentException e) {
            say(e.getMessage());
        } finally {
            written = null;
        }
    }

    /** What to do once the edit being made is in the text (a palette item shows what it added). */
    void whenWritten(Runnable then) {
        written = then;
    }

    /** Says {@code text} on the message line, and again on the drawing of the edit just made. */
    void tell(String text) {
        told = text;
        say(text);
    }

    /** The grid editor beside the text shows gait table {@code name}. */
    void openTable(String name) {
        if (tables != null) {
            tables.test(name);
        }
    }

    /** Shows view {@code v} on {@code subject}, what was just added; the palette's inputs close. */
    void showAdded(View v, String subject) {
        offered = null;
        setView(v, subject);
        showFields();
    }

    /**
     * Writes {@code value} as field {@code f} of the selected node: the edit's replacements
     * become one replacement of the document (one Undo step). Refused, with a message, when the
     * text has changed since the diagram was made.
     */
    private void write(Projection.Field f, String value) {
        if (!current()) {
            say(PanelMsg.DIAGRAM_CHANGED.text());
            return;
        }
        if (value.equals(f.value())) {
            return;
        }
        TextEdit edit;
        try {
            edit = f.edit().apply(value.trim());
        } catch (IllegalArgumentException e) {
            say(e.getMessage());
            return;
        }
        apply(edit);
    }

    /** Applies {@code edit} to the document as one replacement spanning all of its ranges. */
    void apply(TextEdit edit) {
        try {
            editor.apply(edit);
        } catch (BadLocationException e) {
            say(PanelMsg.DIAGRAM_CHANGED_MEANWHILE.text(e.getMessage()));
        }
    }
}
