package org.parpe.gui.diagram;

import java.util.Arrays;
import java.util.List;
import java.util.function.Function;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.parpe.core.diagram.BehaviorEdits;
import org.parpe.core.diagram.PaletteEdits;
import org.parpe.core.edit.SectionEdits;
import org.parpe.core.edit.TextEdit;
import org.parpe.core.model.Program;
import org.parpe.gui.diagram.Projection.Action;
import org.parpe.gui.diagram.Projection.Target;
import org.parpe.gui.diagram.Projection.View;
import org.parpe.gui.editor.ScriptDocument;
import org.parpe.gui.text.PanelMsg;

/**
 * The diagram palette: buttons that define something new in the script, each opening its
 * inputs in the edit row, which lists the script's own names where one is chosen. The beginner
 * palette has poses, gait tables, phase automata and behaviors (the paper's Levels I to IV: the
 * Fig. 7 wheel needs an automaton); the full one adds groups, parameters and instances. After an
 * Add the view that draws the new element shows it. A section the file lacks is written with its first element, so an empty file that
 * {@link Projection} has started a robot in is built up by these buttons alone. Every
 * item writes through the core's edits ({@link PaletteEdits}, {@link BehaviorEdits}) into the
 * text shown at the moment the button is pressed, as one Undo step. UI thread only.
 */
final class Palette {
    /**
     * One button: its label, what it is for, its inputs, the view that draws what it adds (its
     * subject the first input; {@code null}: none draws it) and its edit of a loaded text.
     */
    private record Item(PanelMsg name, PanelMsg noun, PanelMsg add, PanelMsg tip, boolean beginner, List<String> inputs, View shows,
                        Function<Loaded, Function<List<String>, TextEdit>> edit) {
    }

    /** A text with the program loaded from it. */
    private record Loaded(String text, Program p) {
    }

    private static final List<Item> ITEMS = List.of(
            new Item(PanelMsg.PALETTE_POSE, PanelMsg.PALETTE_POSE_NOUN, PanelMsg.PALETTE_ADD_POSE, PanelMsg.PALETTE_POSE_TIP, true,
                    List.of("name", "angles"), null, l -> v -> PaletteEdits.addPose(l.text, l.p, v.get(0), v.get(1))),
            new Item(PanelMsg.PALETTE_GAIT_TABLE, PanelMsg.PALETTE_GAIT_TABLE_NOUN, PanelMsg.PALETTE_ADD_GAIT_TABLE, PanelMsg.PALETTE_GAIT_TABLE_TIP, true,
                    List.of("name", "rows", "modules", "times"), View.RING, l -> v -> PaletteEdits.addGaitTable(l.text, l.p,
                            v.get(0), v.get(1), v.get(2), v.get(3))),
            new Item(PanelMsg.PALETTE_AUTOMATON, PanelMsg.PALETTE_AUTOMATON_NOUN, PanelMsg.PALETTE_ADD_AUTOMATON, PanelMsg.PALETTE_AUTOMATON_TIP, true,
                    List.of("name", EditRow.STATES, "times"), View.RING,
                    l -> v -> PaletteEdits.addAutomaton(l.text, l.p, v.get(0), v.get(1), v.get(2))),
            new Item(PanelMsg.PALETTE_BEHAVIOR, PanelMsg.PALETTE_BEHAVIOR_NOUN, PanelMsg.DIAGRAM_ADD_BEHAVIOR, PanelMsg.PALETTE_BEHAVIOR_TIP, true,
                    List.of("behavior", "automaton", "group", "time"), View.LANES,
                    l -> v -> BehaviorEdits.addBehavior(l.text, l.p, v.get(0), v.get(1), v.get(2), v.get(3))),
            new Item(PanelMsg.PALETTE_GROUP, PanelMsg.PALETTE_GROUP_NOUN, PanelMsg.PALETTE_ADD_GROUP, PanelMsg.PALETTE_GROUP_TIP, false,
                    List.of("name", "elements"), null, l -> v -> PaletteEdits.addGroup(l.text, l.p, v.get(0), v.get(1))),
            new Item(PanelMsg.PALETTE_PARAMETER, PanelMsg.PALETTE_PARAMETER_NOUN, PanelMsg.PALETTE_ADD_PARAMETER, PanelMsg.PALETTE_PARAMETER_TIP,
                    false, List.of("name", "value", "min", "max", "label"), null, l -> v -> PaletteEdits.addParameter(l.text, l.p,
                            v.get(0), v.get(1), v.get(2), v.get(3), v.get(4))),
            new Item(PanelMsg.PALETTE_INSTANCE, PanelMsg.PALETTE_INSTANCE_NOUN, PanelMsg.DIAGRAM_ADD_INSTANCE, PanelMsg.PALETTE_INSTANCE_TIP, false,
                    List.of("behavior", "automaton", "group"), View.LANES, l -> v -> BehaviorEdits.addInstance(l.text,
                            l.p.behavior(v.get(0)).orElseThrow(() -> new IllegalArgumentException(
                                    PanelMsg.PALETTE_NO_BEHAVIOR.text(v.get(0)))), v.get(1), v.get(2))));

    private final DiagramPane pane;
    private final Composite buttons;
    private final Button mode;

    /** The palette's row in {@code parent}, offering its items' inputs in {@code pane}'s edit row. */
    Palette(Composite parent, DiagramPane pane) {
        this.pane = pane;
        // in the row of the view chooser (issue 24: few rows above the drawing)
        Composite row = new Composite(parent, SWT.NONE);
        row.setLayout(DiagramPane.row());
        Label label = new Label(row, SWT.NONE);
        label.setText(PanelMsg.PALETTE_NEW.text());
        // on the label, not the chooser: a tool tip over it covered its open list (issue 31)
        label.setToolTipText(PanelMsg.PALETTE_NEW_TIP.text());
        buttons = new Composite(row, SWT.NONE);
        buttons.setLayout(DiagramPane.row());
        // a check box, narrower than a chooser: the view's and the palette's row stays one row at 1366×768
        mode = new Button(row, SWT.CHECK);
        mode.setText(PanelMsg.PALETTE_FULL.text());
        mode.setToolTipText(PanelMsg.PALETTE_FULL_TIP.text());
        mode.addListener(SWT.Selection, e -> fill());
        fill();
    }

    /** Shows the full palette ({@code true}) or the beginner one. */
    void full(boolean full) {
        mode.setSelection(full);
        fill();
    }

    /** The labels of the buttons shown. */
    List<String> items() {
        return Arrays.stream(buttons.getChildren()).map(c -> ((Button) c).getText()).toList();
    }

    /** Presses button {@code name}: its inputs open in the edit row (nothing when the palette shown lacks it). */
    void choose(String name) {
        for (Item item : ITEMS) {
            if (item.name().text().equals(name) && items().contains(name)) {
                pane.offer(new Target(PanelMsg.PALETTE_NEW_TITLE.text(item.noun().text(), item.tip().text()), List.of(), -1, null,
                        List.of(new Action(item.add().text(), item.inputs(), starting(item), v -> {
                            TextEdit edit = item.edit().apply(load()).apply(v);
                            pane.link().whenWritten(() -> added(item, v.get(0)));
                            return edit;
                        }))));
            }
        }
    }

    /** The inputs of {@code item} as the edit row starts them: a gait table of 4 rows × the robot's modules. */
    private List<String> starting(Item item) {
        if (item.name() != PanelMsg.PALETTE_GAIT_TABLE) {
            return java.util.Collections.nCopies(item.inputs().size(), "");
        }
        Projection shown = pane.shown();
        Program p = shown == null || SectionEdits.blank(shown.text()) ? null : pane.program();
        int modules = p == null || p.moduleIds().length == 0 ? 4 : p.moduleIds().length;
        return List.of("", "4", Integer.toString(modules), "");
    }

    /** {@code item} named {@code name} was written: the view that draws it shows it, or the line says where it went. */
    private void added(Item item, String name) {
        if (item.name() == PanelMsg.PALETTE_GAIT_TABLE) {
            pane.link().openTable(name.trim());
        }
        if (item.shows() != null) {
            pane.showAdded(item.shows(), name.trim());
        } else {
            pane.tell((item.name() == PanelMsg.PALETTE_POSE ? PanelMsg.PALETTE_ADDED_POSE : PanelMsg.PALETTE_ADDED)
                    .text(item.noun().text(), name.trim()));
        }
    }

    private void fill() {
        for (var c : buttons.getChildren()) {
            c.dispose();
        }
        boolean full = mode.getSelection();
        for (Item item : ITEMS) {
            if (full || item.beginner()) {
                Button b = new Button(buttons, SWT.PUSH);
                b.setText(item.name().text());
                b.setToolTipText(PanelMsg.PALETTE_ITEM_TIP.text(item.tip().text()));
                b.addListener(SWT.Selection, e -> choose(item.name().text()));
            }
        }
        buttons.getParent().layout(true, true);
        buttons.getParent().getParent().layout(true, true);
    }

    /** The text the diagram shows, loaded (the edit is refused if it does not load). */
    private Loaded load() {
        Projection shown = pane.shown();
        if (shown == null) {
            throw new IllegalArgumentException(PanelMsg.PALETTE_NO_DIAGRAM.text());
        }
        if (SectionEdits.blank(shown.text())) {
            throw new IllegalArgumentException(PanelMsg.PALETTE_FILE_EMPTY.text(Projection.START.text()));
        }
        ScriptDocument.Loaded now = pane.loaded();
        if (now.program() == null) {
            throw new IllegalArgumentException(PanelMsg.PALETTE_DOES_NOT_LOAD.text());
        }
        return new Loaded(now.text(), now.program());
    }
}
