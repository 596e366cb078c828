package org.parpe.gui.diagram;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import java.util.function.Predicate;
import java.util.function.Supplier;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.CTabFolder;
import org.eclipse.swt.custom.CTabItem;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.RowLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Canvas;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Text;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.diagram.NodePlaces;
import org.parpe.core.diagram.Scene;
import org.parpe.core.model.Program;
import org.parpe.core.run.Breakpoints;
import org.parpe.gui.diagram.Projection.View;
import org.parpe.gui.editor.AfterChange;
import org.parpe.gui.editor.NameIndex;
import org.parpe.gui.editor.ParslEditor;
import org.parpe.gui.editor.ScriptDocument;
import org.parpe.gui.panels.WrapRow;
import org.parpe.gui.run.LiveStates;
import org.parpe.gui.text.PanelMsg;

/**
 * The Diagram pane: one view of the open document (program lane, swimlanes, automaton ring,
 * phase wheel, gait diagram) drawn from the text, never stored anywhere else. It is made again a
 * moment after the text changes ({@link AfterChange}, as the grid editor), off the UI thread and
 * only while the pane is shown ({@link Drawing}). The selected node's values are fields of the
 * edit row: Enter writes the value as one replacement of the document, so Edit → Undo takes it
 * back in one step ({@link EditorLink}); nodes are also dragged ({@link CanvasDrags},
 * {@link FreeNodes}); runs and traces are drawn over it ({@link LiveOverlay}, {@link LiveBar}).
 * This class holds the widgets and the selection and hands the rest to those. UI thread only.
 */
public final class DiagramPane {
    private final Composite box;
    private final ViewChooser chooser;
    private final FieldsRow fields;
    private final Label message;
    private final SceneCanvas canvas;
    private final LiveBar liveBar;
    private final Palette palette;
    private final Drawing drawing;
    private final LiveOverlay overlay;
    private final EditorLink link;
    private final CanvasDrags drags;
    private final FreeNodes freeNodes;
    private SourcePos selected;
    private Projection.Target offered;
    private Supplier<String> pose;
    private String told;
    private boolean layoutAsked;

    /** The pane in {@code parent}, showing {@code document}, the text of {@code editor}. */
    public DiagramPane(Composite parent, ParslEditor editor, ScriptDocument document) {
        box = new Composite(parent, SWT.NONE);
        // few rows above the drawing (issue 24): the drawing keeps at least half the tab, and where
        // the rows need more (a narrow tab, a longer language) they scroll
        Composite above = AboveTheDrawing.controlsOf(box);
        Composite bar = new Composite(above, SWT.NONE);
        bar.setLayout(row());
        bar.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        chooser = new ViewChooser(bar, this::setView, this::relayout);
        palette = new Palette(bar, this);
        fields = new FieldsRow(above, this::layoutAgain);
        message = messageLine(above);
        liveBar = new LiveBar(above, this);
        canvas = new SceneCanvas(box, node -> {
            offered = null;
            link().clicked(node);
        });
        AboveTheDrawing.drawing(box, canvas.control());
        drawing = new Drawing(this, editor, document, canvas);
        overlay = new LiveOverlay(this, canvas, liveBar);
        link = new EditorLink(this, editor);
        showFields();
        freeNodes = new FreeNodes(this, canvas);
        drags = new CanvasDrags(this, canvas);
        canvas.control().addListener(SWT.Resize, e -> drawing.laidOutAgain());
        AfterChange soon = new AfterChange(box, editor.document(), this::relayout);
        box.addListener(SWT.Show, e -> soon.schedule());
        box.addListener(SWT.Dispose, e -> drawing.dispose());
    }

    private static Label messageLine(Composite box) {
        Label message = new Label(box, SWT.WRAP);
        // two lines, always there, whatever it says: a message after an edit does not move the drawing
        // under the mouse (issue 31); a wider text wraps at the tab's width instead of widening it
        GridData md = new GridData(SWT.FILL, SWT.TOP, true, false);
        md.heightHint = 2 * lineHeight(message);
        md.widthHint = 100;
        message.setLayoutData(md);
        return message;
    }

    /** A row of controls that wraps only when the tab is too narrow, with little margin. */
    static RowLayout row() {
        return WrapRow.layout();
    }

    /** The height of a line of text in {@code c}'s font. */
    static int lineHeight(Control c) {
        GC gc = new GC(c);
        try {
            return gc.getFontMetrics().getHeight();
        } finally {
            gc.dispose();
        }
    }

    /**
     * The pane laid out again, its controls and the drawing under them (after a row changed its
     * height): now, and once more after the event that asked, because a row that changes its
     * height while the scrolled controls are being laid out is not seen by that layout.
     */
    void layoutAgain() {
        box.layout(true, true);
        if (!layoutAsked) {
            layoutAsked = true;
            box.getDisplay().asyncExec(() -> {
                layoutAsked = false;
                if (!box.isDisposed()) {
                    box.layout(true, true);
                }
            });
        }
    }

    /** Sets the message line (its row keeps its height; a text longer than it shows whole as its tool tip). */
    void say(String text) {
        message.setText(text);
        message.setToolTipText(text.isEmpty() ? null : text);
        box.layout(true, true);
    }

    /** Sets the message line's text while a drag goes on, and nothing else. */
    void hint(String text) {
        message.setText(text);
    }

    /** The pane's control (the host puts it in a tab). */
    public Control control() {
        return box;
    }

    /** Shows view {@code v} of the document. */
    public void setView(View v) {
        setView(v, null);
    }

    /** Shows view {@code v} on {@code label} (a behavior, automaton or instance as the subject chooser names it). */
    public void setView(View v, String label) {
        chooser.choose(v, label);
        selected = null;
        relayout();
    }

    /** Projects the current text on the worker if the pane is shown; the newest request wins. */
    void relayout() {
        if (!box.isDisposed() && box.isVisible()) {
            drawing.relayout(chooser.view(), chooser.subject(), freeNodes.places().places());
        }
    }

    /** Shows projection {@code p}, just laid out: its subjects, its selection, its drawing, its edit row. */
    void show(Projection p) {
        chooser.shown(p);
        if (p.view() == View.PHASE && p.targets().size() == 1) {
            selected = p.targets().keySet().iterator().next();
        } else if (selected != null && !p.targets().containsKey(selected) && canvas.centre(selected) == null) {
            selected = null;
        }
        canvas.show(p.scene() == null ? new Scene(1, 1) : p.scene());
        overlay.cleared();
        liveBar.shown();
        canvas.select(selected);
        message.setText(!p.message().isEmpty() ? p.message() : told != null ? told : !p.targets().isEmpty() ? PanelMsg.DIAGRAM_HINT.text() : "");
        told = null;
        showFields();
        box.layout(true, true);
    }

    /** The ring or the wheel shown was laid out again as {@code p} (a new size or zoom). */
    void redrawn(Projection p) {
        canvas.show(p.scene());
        canvas.select(selected);
        repaintOverlay();
    }

    /** The text scale the ring or the wheel shown is laid out with. */
    double textScale() {
        return drawing.textScale();
    }

    /**
     * The drawing's smallest text is {@code steps} × 2 points larger than normal (the window's
     * zoom, {@link org.parpe.gui.panels.Zoom}): other text grows to it, and the ring and the wheel
     * are laid out again so that their labels stay apart.
     */
    public void zoom(int steps) {
        drawing.zoom(steps);
    }

    /** Selects {@code node} (or nothing) on the drawing and shows its edit row. */
    void select(SourcePos node) {
        selected = node;
        canvas.select(node);
        showFields();
    }

    /** The edit row: the selected node's values as fields (Enter in one writes it) and its actions ({@link EditRow}). */
    private void showFields() {
        Projection shown = shown();
        SourcePos key = selected != null ? selected : shown == null ? null : shown.home();
        // a file with no script (a robot configuration) has no home node: nothing to edit
        Projection.Target t = offered != null ? offered : key == null ? null : shown.targets().get(key);
        // a view with nothing to select or edit (the gait diagram) has no edit row
        fields.fill(t, t != null || shown != null && !shown.targets().isEmpty(), shown == null ? null : NameIndex.of(shown.text()),
                link::write, link::act, pose);
        liveBar.update();
        say(message.getText());
    }

    /** Shows {@code t} (a palette item's inputs) in the edit row until a node is clicked. */
    void offer(Projection.Target t) {
        offered = t;
        showFields();
    }

    /** Shows view {@code v} on {@code subject}, what was just added; the palette's inputs close. */
    void showAdded(View v, String subject) {
        offered = null;
        setView(v, subject);
        showFields();
    }

    /** Says {@code text} on the message line, and again on the drawing of the edit just made. */
    void tell(String text) {
        told = text;
        say(text);
    }

    /**
     * Takes poses from {@code selected} (the Pose panel's selected pose as angles, or null): a
     * state's edit row gets "Use pose", and a pose dragged onto a state of the ring becomes its angles.
     */
    public void usePoses(Supplier<String> selected) {
        pose = selected;
        drags.takePoses();
        showFields();
    }

    /** The drags on the drawing (a dragged hand's preview, poses dropped, for tests). */
    CanvasDrags drags() {
        return drags;
    }

    /** Opens a gait table the pane has just written with {@code show} (the grid editor's, by table name). */
    public void openTablesWith(Predicate<String> show) {
        link.openTablesWith(show);
    }

    /** The link to the editor's text: selection both ways, and every edit written into the text. */
    EditorLink link() {
        return link;
    }

    /**
     * Another document is shown ({@code file}, or {@code null} when untitled): the free nodes
     * take the places kept beside it ({@link PlacesBeside}).
     */
    public void documentSwitched(Path file) {
        // a palette item's inputs belong to the file they were opened on
        offered = null;
        freeNodes.places().documentSwitched(file);
        relayout();
    }

    /** The document was saved as {@code file}: its free nodes' places go beside it. */
    public void documentRenamed(Path file) {
        freeNodes.places().documentRenamed(file);
    }

    /** What the places beside the script cannot be read or written is said with {@code status} (once each). */
    public void sayPlacesWith(Consumer<String> status) {
        freeNodes.places().sayWith(status);
    }

    /** The places of the free nodes now (what is, or will be, beside the script). */
    public NodePlaces places() {
        return freeNodes.places().places();
    }

    /** The workbench's free nodes (where they are, for tests). */
    FreeNodes workbench() {
        return freeNodes;
    }

    /** The projection shown, or {@code null} before the first. */
    public Projection shown() {
        // the live bar, made before the drawing (it is above it), asks while the pane is being built
        return drawing == null ? null : drawing.shown();
    }

    /** Whether the diagram shows the editor's current text. */
    public boolean current() {
        return drawing.current();
    }

    /** The node selected, or {@code null}. */
    public SourcePos selected() {
        return selected;
    }

    /** The canvas, for tests that click on it. */
    public Canvas canvas() {
        return canvas.control();
    }

    /** The drawing's texts as last painted: each one's extent on the canvas (pixels) and its text. */
    public List<Map.Entry<Rectangle, String>> drawnTexts() {
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
    public Map<String, Text> fields() {
        return fields.fields();
    }

    /** The choosers of the edit row (its inputs that list the script's names), by name. */
    public Map<String, Combo> choosers() {
        return fields.choosers();
    }

    /** The action buttons of the edit row, by label. */
    public Map<String, Button> actions() {
        return fields.actions();
    }

    /** The palette, for tests. */
    Palette palette() {
        return palette;
    }

    /**
     * Follows runs: while {@code running} holds and the ring, the lanes or the gait diagram are
     * shown, they are marked with what the engine thread published in {@code live} ({@link LiveOverlay}).
     */
    public void follow(LiveStates live, BooleanSupplier running) {
        overlay.follow(live, running);
    }

    /**
     * The run's breakpoints (set on the ring's states), how to go on from one (Continue), and
     * whom to tell when the run stops at one or goes on (the tool bar's Pause/Resume).
     */
    public void breakpoints(Breakpoints bp, Runnable resume, Runnable changed) {
        liveBar.breakpoints(bp, resume, changed);
    }

    /** Draws the live marks, the breakpoints and the wheel's dragged hand over the drawing. */
    void repaintOverlay() {
        overlay.repaint();
    }

    /** Shows frame {@code f} as the overlay ({@code what}: "live" or "trace"), or no overlay for {@code null}. */
    void showFrame(LiveStates.Frame f, String what) {
        overlay.showFrame(f, what);
    }

    /** The script of the open text as loaded now, or {@code null} when it does not load. */
    Program program() {
        return drawing.program();
    }

    /** The open text as loaded now. */
    ScriptDocument.Loaded loaded() {
        return drawing.loaded();
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
        if (box.getParent() instanceof CTabFolder folder) {
            for (CTabItem item : folder.getItems()) {
                if (item.getControl() == box) {
                    folder.setSelection(item);
                    folder.notifyListeners(SWT.Selection, new Event());
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
        return shown() == null ? "" : shown().view().name();
    }

    /**
     * Draws frame {@code f} as the live overlay and paints it at once (for the benchmark: the time
     * this takes is what one frame of the overlay costs the UI thread).
     */
    public void drawFrame(LiveStates.Frame f) {
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

    /** The engine tick of the live overlay shown, or −1. */
    public long liveTick() {
        return overlay.tick();
    }

    /** The live overlay (what it shows, for tests). */
    LiveOverlay live() {
        return overlay;
    }
}
