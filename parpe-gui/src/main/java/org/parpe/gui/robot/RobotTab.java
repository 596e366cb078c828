package org.parpe.gui.robot;

import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.eclipse.jface.resource.JFaceResources;
import org.eclipse.jface.text.ITextOperationTarget;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.edit.TextEdit;
import org.parpe.core.model.Program;
import org.parpe.gui.panels.Zoom;
import org.parpe.gui.text.ToolMsg;
import org.parpe.gui.view3d.View3D;
import org.parpe.sim.snapshot.SimBody;
import org.parpe.sim.snapshot.SimSnapshot;
import org.parpe.sim.build.BuildEdit;
import org.parpe.sim.build.BuildPlate;
import org.parpe.sim.build.RobotDraft;
import org.parpe.sim.config.PartSpec;
import org.parpe.sim.config.PartType;

/**
 * The Robot tab (issue 33): the robot of the file in the editor in 3D, its free plates as
 * targets. Click a plate, pick a part and its orientation (previewed translucent), Place (or
 * double-click the plate); click a part to change or delete it; Ctrl+click a second plate to
 * close a loop. Each change is a {@link RobotDraft} edit applied to the editor's document as one
 * Undo step, so the text is the source and the tab re-reads it after each check of the text.
 * UI thread only.
 */
public final class RobotTab {
    private final RobotHost host;
    private final TabControls ui;
    private final Targets targets;
    private final Outside outside;
    private Shown shown = new Shown(Shown.Kind.NOTHING, null, null, null, "");
    private SimSnapshot picture;
    /** The size of the robot when the view last framed it, m. */
    private double framed;
    private BuildEdit pending;
    /** The last script that loaded (what "Try it" runs and what the parts are coloured by) and its file. */
    private Program script;

    public RobotTab(Composite parent, RobotHost host) {
        this.host = host;
        ui = new TabControls(parent);
        targets = new Targets(ui.view, new Picks());
        outside = new Outside(host, ui.root.getShell(), this::say);
        ui.view.setBuilder(targets);
        ui.view.setSource(() -> picture);
        ui.view.startAnimation();
        wire();
        update();
    }

    private void wire() {
        ui.editRobot.addListener(SWT.Selection, e -> {
            if (shown.config() != null) {
                host.open(shown.config());
            }
        });
        ui.makeEditable.addListener(SWT.Selection, e -> outside.makeEditable(shown).ifPresent(this::show));
        ui.tryIt.addListener(SWT.Selection, e -> tryIt());
        ui.undo.addListener(SWT.Selection, e -> editorOperation(ITextOperationTarget.UNDO));
        ui.redo.addListener(SWT.Selection, e -> editorOperation(ITextOperationTarget.REDO));
        ui.kit.addListener(SWT.Selection, e -> {
            if (outside.chooseKit()) {
                show(shown);
            }
        });
        for (org.eclipse.swt.widgets.Button c : ui.types) {
            c.addListener(SWT.Selection, e -> chosen(c));
        }
        PartEdits.typed(ui.hubPlates, () -> {
            preview();
            update();
        });
        for (org.eclipse.swt.widgets.Button c : ui.turns) {
            c.addListener(SWT.Selection, e -> chosen(c));
        }
        ui.place.addListener(SWT.Selection, e -> place());
        ui.connect.addListener(SWT.Selection, e -> connect());
        ui.assignIds.addListener(SWT.Selection, e -> edit(d -> d.assignIds()));
        new PartEdits(ui, () -> shown, () -> targets.part, this::apply, this::say);
    }

    /** A radio button of the palette was pressed: the preview follows the one now chosen. */
    private void chosen(org.eclipse.swt.widgets.Button b) {
        if (b.getSelection()) { // the button let go of sends its event too
            preview();
            update();
        }
    }

    /** The tab's contents. */
    public Control control() {
        return ui.root;
    }

    /**
     * The text in the editor was checked ({@code program}: the script it loaded to, or null):
     * the tab shows its robot again. True when the editor holds a robot configuration (not a
     * blank file, which the tab shows as an empty robot and the IDE as an empty script); then
     * {@link #problems()} are the file's problems, not the script loader's.
     */
    public boolean documentChecked(Program program) {
        String text = host.editor().document().get();
        if (Shown.isConfig(text)) {
            boolean blank = org.parpe.core.edit.SectionEdits.blank(text);
            // shown already: the same text, or (blank) the empty robot of the same file
            boolean same = shown.editable() && (blank ? shown.draft().partNames().isEmpty() && host.file().equals(shown.config())
                    : shown.draft().text().equals(text));
            if (!same) {
                show(Shown.of(host.file(), text, null, null));
            }
            // a blank file is the IDE's (an empty script or an empty robot): nothing to report
            return !blank;
        }
        if (program != null && java.nio.file.Files.isRegularFile(host.file())) { // an untitled script is no one's robot test
            script = program;
            outside.scriptLoaded(host.file());
        }
        show(Shown.of(host.file(), text, program, host.robotChoice()));
        return false;
    }

    /** Another file is in the editor: the view frames its robot afresh. */
    public void documentSwitched() {
        ui.view.clear();
        clearSelection();
    }

    /** The robot choice of the script in the editor changed. */
    public void robotChosen() {
        documentChecked(script != null && host.file().toString().equals(script.file()) ? script : null);
    }

    /** The problems of the configuration in the editor (located), empty when it holds none. */
    public List<Diagnostic> problems() {
        return shown.editable() ? shown.draft().problems() : List.of();
    }

    /** Larger ({@code steps} &gt; 0) or normal text in the tab's controls (View > Zoom In). */
    public void zoom(int steps) {
        for (Control c : ui.all()) {
            Zoom.apply(c, JFaceResources.getDialogFont(), steps);
        }
        ui.relayout();
    }

    private void show(Shown s) {
        boolean wasEmpty = shown.draft() == null || shown.draft().bodies().isEmpty();
        if (s.kind() != shown.kind() || !java.util.Objects.equals(s.config(), shown.config())) {
            ui.line(ui.message, s.editable() ? s.note() : ""); // another robot: what to do with it
        }
        shown = s;
        RobotDraft d = s.draft();
        List<SimBody> bodies = d == null ? List.of() : d.bodies();
        picture = bodies.isEmpty() ? null : Pictures.snapshot(bodies);
        double size = Pictures.size(bodies);
        if (wasEmpty && !bodies.isEmpty() || size > framed * 1.25 || size < framed * 0.8) {
            ui.view.clear(); // the first part, or the robot grew or shrank (a wheel stood up): frame it again
            framed = size;
        }
        targets.plates = d == null ? List.of() : d.freePlates();
        Colours.paint(targets, d, script, s.editable());
        keepSelection();
        preview();
        update();
    }

    /** The selection after a change: what still exists stays selected. */
    private void keepSelection() {
        RobotDraft d = shown.draft();
        if (d == null) {
            clearSelection();
            return;
        }
        if (targets.part != null && d.part(targets.part).isEmpty()) {
            targets.part = null;
        }
        targets.first = stillFree(targets.first);
        targets.second = stillFree(targets.second);
    }

    private BuildPlate stillFree(BuildPlate p) {
        return p == null ? null : targets.plates.stream().filter(q -> Targets.same(p, q)).findFirst().orElse(null);
    }

    private void clearSelection() {
        targets.part = null;
        targets.first = null;
        targets.second = null;
        targets.ghosts = List.of();
        pending = null;
    }

    /** Computes the part Place would add and shows it translucent (or says why it cannot be added). */
    private void preview() {
        pending = null;
        targets.ghosts = List.of();
        RobotDraft d = shown.draft();
        if (!shown.editable() || d == null || d.config() == null && !d.partNames().isEmpty()) {
            ui.view.control().redraw();
            return;
        }
        PartType type = ui.type();
        int quarter = ui.quarterTurns();
        if (d.partNames().isEmpty()) {
            pending = d.first(type, hubPlates());
        } else if (targets.first != null) {
            pending = d.add(targets.first.part(), targets.first.plate(), type, 0, quarter, hubPlates(), outside.kit());
        }
        if (pending != null && pending.refused()) {
            say(targets.first == null ? pending.refusal() : ToolMsg.ROBOT_PLATE_REFUSAL.text(targets.first.ref(), pending.refusal()));
        } else if (pending != null) {
            targets.ghosts = Pictures.ghosts(d, d.apply(pending));
        }
        ui.view.control().redraw();
    }

    /** The hub plates typed, or the default when the box holds no whole number. */
    private int hubPlates() {
        try {
            return Integer.parseInt(ui.hubPlates.getText().trim());
        } catch (NumberFormatException e) {
            return PartType.HUB.defaultPlates();
        }
    }

    private void place() {
        if (pending == null) {
            say(shown.editable() ? ToolMsg.ROBOT_CLICK_PLATE.text() : ToolMsg.ROBOT_READ_ONLY.text(shown.note()));
            return;
        }
        BuildEdit e = pending;
        apply(e);
    }

    private void connect() {
        BuildPlate a = targets.first;
        BuildPlate b = targets.second;
        if (a == null || b == null) {
            say(ToolMsg.ROBOT_SELECT_TWO.text());
            return;
        }
        BuildEdit e = shown.draft().closeLoop(a.part(), a.plate(), b.part(), b.plate());
        if (e.refused()) {
            // the distance, unless the refusal says it already (the builder's "plates … mm apart", in any language)
            String gap = String.format(java.util.Locale.ROOT, "%.1f",
                    shown.draft().gap(a.part(), a.plate(), b.part(), b.plate()) * 1000);
            say(e.refusal().contains(gap) ? e.refusal() : ToolMsg.ROBOT_REFUSAL_GAP.text(e.refusal(), gap));
            return;
        }
        apply(e);
    }

    private void edit(java.util.function.Function<RobotDraft, BuildEdit> make) {
        if (shown.editable() && shown.draft() != null) {
            apply(make.apply(shown.draft()));
        }
    }

    /**
     * Applies {@code e} to the editor's document as one Undo step (a refusal is said instead)
     * and shows the result at once, without waiting for the check of the text (the tab's
     * buttons; the benchmark).
     */
    public void apply(BuildEdit e) {
        if (e.refused()) {
            say(e.refusal());
            return;
        }
        String doc = host.editor().document().get();
        RobotDraft d = shown.draft();
        TextEdit edit = e.edit();
        if (!d.text().equals(doc)) {
            if (!org.parpe.core.edit.SectionEdits.blank(doc)) {
                show(Shown.of(host.file(), doc, null, null));
                say(ToolMsg.ROBOT_CHANGED_TRY_AGAIN.text());
                return;
            }
            edit = Pictures.startIn(doc, d.apply(e).text()); // a blank file: the empty configuration and the part at once
        }
        try {
            host.editor().apply(edit);
        } catch (org.eclipse.jface.text.BadLocationException ex) {
            say(ToolMsg.ROBOT_CHANGED.text(ex.getMessage()));
            return;
        }
        show(Shown.of(host.file(), host.editor().document().get(), null, null));
        say(ToolMsg.ROBOT_UNDO_TAKES_BACK.text(e.description()));
    }

    private void editorOperation(int op) {
        host.editor().run(op);
        if (Shown.isConfig(host.editor().document().get())) {
            show(Shown.of(host.file(), host.editor().document().get(), null, null));
        }
    }

    private void tryIt() {
        outside.tryIt(shown, script).ifPresent(p -> {
            script = p;
            if (ui.root.getParent() instanceof org.eclipse.swt.custom.CTabFolder f) {
                f.setSelection(0); // the 3D view, where the run is drawn
            }
        });
    }

    private final class Picks implements Targets.Picked {
        @Override
        public void plate(BuildPlate p, boolean adding, boolean twice) {
            targets.part = null;
            if (adding && targets.first != null && !Targets.same(p, targets.first)) {
                targets.second = p; // the part previewed on the first plate stays as it is
                double gap = shown.draft().gap(targets.first.part(), targets.first.plate(), p.part(), p.plate());
                say(ToolMsg.ROBOT_PLATES_APART.text(targets.first.ref(), p.ref(), String.format(java.util.Locale.ROOT, "%.1f", gap * 1000)));
                ui.view.control().redraw();
            } else {
                targets.first = p;
                targets.second = null;
                say(ToolMsg.ROBOT_PLATE_PICKED.text(p.ref()));
                preview();
            }
            update();
            if (twice && !adding) {
                place();
            }
        }

        @Override
        public void part(String name) {
            clearSelection();
            targets.part = name;
            say((shown.editable() ? ToolMsg.ROBOT_PART_EDITABLE : ToolMsg.ROBOT_PART).text(name));
            update();
            ui.view.control().redraw();
        }

        @Override
        public void nothing() {
            clearSelection();
            update();
            ui.view.control().redraw();
        }
    }

    /** Enables what can be done now and shows the selected part's properties. */
    private void update() {
        boolean edit = shown.editable();
        RobotDraft d = shown.draft();
        String sourceText = shown.kind() == Shown.Kind.GENERATOR ? shown.spec()
                : shown.config() != null ? shown.config().getFileName().toString() : "";
        ui.source.setToolTipText(shown.note());
        ui.editRobot.setEnabled(shown.kind() == Shown.Kind.FILE);
        ui.makeEditable.setEnabled(shown.kind() == Shown.Kind.GENERATOR);
        ui.tryIt.setEnabled(d != null && d.config() != null);
        ui.undo.setEnabled(edit);
        ui.redo.setEnabled(edit);
        ui.place.setEnabled(edit && pending != null && !pending.refused());
        ui.connect.setEnabled(edit && targets.first != null && targets.second != null);
        ui.assignIds.setEnabled(edit && d != null && d.config() != null);
        PartSpec p = d == null || targets.part == null ? null : d.part(targets.part).orElse(null);
        String partText = p == null ? ToolMsg.ROBOT_NO_PART.text() : p.name() + " (" + p.type().xmlName() + ")";
        boolean seg = edit && p != null && p.isSegment();
        ui.moduleId.setEnabled(seg);
        ui.angle.setEnabled(seg);
        ui.limp.setEnabled(seg);
        ui.moduleId.setText(p != null && p.isSegment() ? Integer.toString(p.moduleId()) : "");
        ui.angle.setText(p != null && p.isSegment() ? org.parpe.core.xml.FlatXmlFile.plain(p.angle()) : "");
        ui.limp.setSelection(p != null && p.limp());
        boolean root = p != null && p.name().equals(d.root());
        ui.roll.setEnabled(edit && root && d.config() != null);
        ui.roll.setText(root && d.config() != null ? org.parpe.core.xml.FlatXmlFile.plain(d.config().root().roll()) : "");
        ui.turn.setEnabled(edit && p != null && !root);
        ui.delete.setEnabled(edit && p != null);
        ui.makeRoot.setEnabled(edit && p != null && !p.name().equals(d.root()));
        String fit = Colours.fit(d, script, outside.kit());
        ui.line(ui.fit, shown.editable() ? fit : shown.note() + (fit.isEmpty() ? "" : "\n" + fit));
        if (!ui.partName.getText().equals(partText) || !ui.source.getText().equals(sourceText)) {
            ui.partName.setText(partText);
            ui.source.setText(sourceText);
            ui.relayout(); // only a label of the rows changes their size
        }
    }

    private void say(String message) {
        ui.line(ui.message, message == null ? "" : message);
        host.say(message);
    }

    // --- for tests and the benchmark ---

    /** Brings the tab to the front of its folder. */
    public void showTab() {
        if (ui.root.getParent() instanceof org.eclipse.swt.custom.CTabFolder folder) {
            for (org.eclipse.swt.custom.CTabItem item : folder.getItems()) {
                if (item.getControl() == ui.root) {
                    folder.setSelection(item);
                    folder.notifyListeners(SWT.Selection, new org.eclipse.swt.widgets.Event());
                }
            }
        }
    }

    /** The 3D view of the tab. */
    public View3D view() {
        return ui.view;
    }

    /** The robot shown now (null: none). */
    public RobotDraft draft() {
        return shown.draft();
    }

    /** Where free plate {@code part.plate} is on the tab's canvas, or null (not free, not in sight, or facing away: turn the view). */
    public Point platePoint(String part, int plate) {
        return targets.screenPoint(part, plate);
    }

    /**
     * Where a click on the canvas selects part {@code part} (the centre of one of its pieces,
     * neither behind another part nor under a plate's disc), or null: turn the view.
     */
    public Point partPoint(String part) {
        List<SimBody> bodies = shown.draft() == null ? List.of() : shown.draft().bodies();
        for (SimBody b : bodies) {
            double[] s = b.part().equals(part) ? ui.view.project(b.position()) : null;
            if (s != null) {
                int x = (int) Math.round(s[0]);
                int y = (int) Math.round(s[1]);
                if (targets.plateAt(x, y) == null && part.equals(ui.view.partAt(x, y))) {
                    return new Point(x, y);
                }
            }
        }
        return null;
    }

    /** The line under the view saying what the last action did. */
    public String message() {
        return ui.message.getText();
    }

    /** The line saying how the robot fits the script and the kit. */
    public String fitText() {
        return ui.fit.getText();
    }

    /** Scrolls the rows of controls so that {@code c} is in sight (they scroll with large text on a small screen). */
    public void reveal(Control c) {
        ui.reveal(c);
    }

    /** The tab's buttons and fields (tests find them by their text). */
    public List<Control> controls() {
        return ui.all();
    }

    /** The part selected (null: none). */
    public String selectedPart() {
        return targets.part;
    }

    /** The parts painted in the colour of a problem. */
    public Set<String> faultyParts() {
        Set<String> out = new TreeSet<>();
        targets.paint.forEach((k, v) -> {
            if (v == Targets.FAULT) {
                out.add(k);
            }
        });
        return out;
    }

    /** The parts whose plates are marked as able to latch. */
    public Set<String> latchingParts() {
        return targets.latching;
    }

    /** Answers the questions of Make editable and Kit (tests). */
    public void answerWith(Outside.Questions q) {
        outside.answerWith(q);
    }
}
