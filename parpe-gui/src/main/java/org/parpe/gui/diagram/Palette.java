package org.parpe.gui.diagram;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.parpe.core.diagram.BehaviorEdits;
import org.parpe.core.diagram.PaletteEdits;
import org.parpe.core.diagram.SectionEdits;
import org.parpe.core.diagram.TextEdit;
import org.parpe.core.load.LoadResult;
import org.parpe.core.model.Program;
import org.parpe.gui.diagram.Projection.Action;
import org.parpe.gui.diagram.Projection.Target;
import org.parpe.gui.editor.Validator;

/**
 * The diagram palette: buttons that define something new in the script, each opening its
 * inputs in the edit row. The beginner palette has poses, gait tables and one behavior (the
 * paper's Levels I, II and IV); the full one adds groups, parameters, phase automata and
 * instances. A section the file lacks is written with its first element, so an empty file that
 * {@link Projection} has started a robot in is built up by these buttons alone. Every
 * item writes through the core's edits ({@link PaletteEdits}, {@link BehaviorEdits}) into the
 * text shown at the moment the button is pressed, as one Undo step. UI thread only.
 */
final class Palette {
    /** One button: its label, what it is for, its inputs and its edit of a loaded text. */
    private record Item(String name, String tip, boolean beginner, List<String> inputs,
                        Function<Loaded, Function<List<String>, TextEdit>> edit) {
    }

    /** A text with the program loaded from it. */
    private record Loaded(String text, Program p) {
    }

    private static final List<Item> ITEMS = List.of(
            new Item("Pose", "a named state: one angle for the whole group, or one per module", true,
                    List.of("name", "angles"), l -> v -> PaletteEdits.addPose(l.text, l.p, v.get(0), v.get(1))),
            new Item("Gait table", "rows of angles, one column per module; separate rows with ;", true,
                    List.of("name", "rows", "times"), l -> v -> PaletteEdits.addGaitTable(l.text, l.p, v.get(0),
                            Arrays.stream(v.get(1).split(";")).map(String::trim).toList(), v.get(2))),
            new Item("Behavior", "a behavior running one automaton on one group, run from <main>", true,
                    List.of("behavior", "automaton", "group", "time"),
                    l -> v -> BehaviorEdits.addBehavior(l.text, l.p, v.get(0), v.get(1), v.get(2), v.get(3))),
            new Item("Group", "a group of modules: IDs such as 0, 2, 4 or 0..7", false,
                    List.of("name", "elements"), l -> v -> PaletteEdits.addGroup(l.text, l.p, v.get(0), v.get(1))),
            new Item("Parameter", "a number fixed for a run, used by name in angles, times and ranges; min, max, label optional",
                    false, List.of("name", "value", "min", "max", "label"), l -> v -> PaletteEdits.addParameter(l.text, l.p,
                            v.get(0), v.get(1), v.get(2), v.get(3), v.get(4))),
            new Item("Automaton", "a phase automaton: defined states in cycle order, and their times", false,
                    List.of("name", "add state", "times"),
                    l -> v -> PaletteEdits.addAutomaton(l.text, l.p, v.get(0), v.get(1), v.get(2))),
            new Item("Instance", "an automaton on a group in an existing behavior (! mirrors the group)", false,
                    List.of("behavior", "automaton", "group"), l -> v -> BehaviorEdits.addInstance(l.text,
                            l.p.behavior(v.get(0)).orElseThrow(() -> new IllegalArgumentException(
                                    "there is no behavior '" + v.get(0) + "'")), v.get(1), v.get(2))));

    private final DiagramPane pane;
    private final Composite buttons;
    private final Combo mode;

    /** The palette's row in {@code parent}, offering its items' inputs in {@code pane}'s edit row. */
    Palette(Composite parent, DiagramPane pane) {
        this.pane = pane;
        // in the row of the view chooser (issue 24: few rows above the drawing)
        Composite row = new Composite(parent, SWT.NONE);
        row.setLayout(DiagramPane.row());
        new Label(row, SWT.NONE).setText("New:");
        buttons = new Composite(row, SWT.NONE);
        buttons.setLayout(DiagramPane.row());
        mode = new Combo(row, SWT.READ_ONLY);
        mode.setItems("Beginner", "Full");
        mode.select(0);
        mode.setToolTipText("Palette: the beginner one has poses, gait tables and one behavior; the full one everything");
        mode.addListener(SWT.Selection, e -> fill());
        fill();
    }

    /** Shows the full palette ({@code true}) or the beginner one. */
    void full(boolean full) {
        mode.select(full ? 1 : 0);
        fill();
    }

    /** The labels of the buttons shown. */
    List<String> items() {
        return Arrays.stream(buttons.getChildren()).map(c -> ((Button) c).getText()).toList();
    }

    /** Presses button {@code name}: its inputs open in the edit row. */
    void choose(String name) {
        for (Item item : ITEMS) {
            if (item.name().equals(name)) {
                pane.offer(new Target("New " + item.name().toLowerCase(java.util.Locale.ROOT) + ": " + item.tip(),
                        List.of(), -1, null, List.of(new Action("Add " + item.name().toLowerCase(java.util.Locale.ROOT),
                                item.inputs(), v -> item.edit().apply(load()).apply(v)))));
            }
        }
    }

    private void fill() {
        for (var c : buttons.getChildren()) {
            c.dispose();
        }
        boolean full = mode.getSelectionIndex() == 1;
        for (Item item : ITEMS) {
            if (full || item.beginner()) {
                Button b = new Button(buttons, SWT.PUSH);
                b.setText(item.name());
                b.setToolTipText("New " + item.tip());
                b.addListener(SWT.Selection, e -> choose(item.name()));
            }
        }
        buttons.getParent().layout(true, true);
        buttons.getParent().getParent().layout(true, true);
    }

    /** The text the diagram shows, loaded (the edit is refused if it does not load). */
    private Loaded load() {
        Projection shown = pane.shown();
        if (shown == null) {
            throw new IllegalArgumentException("no diagram yet; try again in a moment");
        }
        if (SectionEdits.blank(shown.text())) {
            throw new IllegalArgumentException("The file is empty: start a robot first (" + Projection.START
                    + ", in the row below), then add to it.");
        }
        Path f = shown.file();
        LoadResult r = Validator.load(f, shown.text(), Map.of());
        if (r.program() == null) {
            throw new IllegalArgumentException("the script does not load; mend it first (see Problems)");
        }
        return new Loaded(shown.text(), r.program());
    }
}
