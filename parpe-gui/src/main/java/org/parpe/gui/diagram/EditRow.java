package org.parpe.gui.diagram;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.function.BiConsumer;
import java.util.function.Supplier;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.RowData;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Text;
import org.parpe.gui.diagram.Projection.Action;
import org.parpe.gui.diagram.Projection.Field;
import org.parpe.gui.diagram.Projection.Target;
import org.parpe.gui.editor.NameIndex;
import org.parpe.gui.text.PanelMsg;

/**
 * The edit row of the Diagram pane for one node: its title, its values as fields (Enter writes
 * one) with the editor's content assist ({@link AssistField}), and its actions as buttons,
 * each with the input fields it needs (a whole number with − and + buttons). The row holds no
 * state of its own: every field and button hands its value to the pane, which writes it into
 * the text. UI thread only.
 */
final class EditRow {
    private EditRow() {
    }

    /**
     * Fills {@code row} (emptied first) with {@code t}'s title, fields and actions; the names of
     * {@code names} are offered in every field.
     */
    static void fill(Composite row, Target t, NameIndex names, BiConsumer<Field, String> write,
                     BiConsumer<Action, List<String>> act, Supplier<String> pose) {
        for (var c : row.getChildren()) {
            c.dispose();
        }
        Label title = new Label(row, SWT.NONE);
        title.setText(t == null ? "" : t.title());
        if (t == null) {
            return;
        }
        for (Field f : t.fields()) {
            Control field = input(row, null, f.name(), f.value(), names);
            if (field instanceof Combo c) {
                // a name picked from the script's is written at once, as Enter writes a typed one
                c.addListener(SWT.Selection, e -> write.accept(f, c.getText()));
            } else {
                tip(field, PanelMsg.DIAGRAM_FIELD_TIP.text(label(f.name())));
            }
            field.addListener(SWT.DefaultSelection, e -> write.accept(f, text(field)));
            if (f.name().equals("angles") && pose != null) {
                button(row, PanelMsg.DIAGRAM_USE_POSE.text(), PanelMsg.DIAGRAM_USE_POSE_TIP.text(),
                        () -> act.accept(new Action(PanelMsg.DIAGRAM_USE_POSE.text(), List.of(), v -> f.edit().apply(usable(pose.get()))), List.of()));
            }
        }
        for (Action a : t.actions()) {
            List<Control> inputs = new ArrayList<>();
            for (int i = 0; i < a.inputs().size(); i++) {
                Control input = input(row, a.name(), a.inputs().get(i), a.values().get(i), names);
                inputs.add(input);
                if (input instanceof Text x && a.values().get(i).matches("[0-9]+")) {
                    stepper(row, a.inputs().get(i), x);
                }
                if (input instanceof Combo c && a.inputs().get(i).equals(STATES)) {
                    listed(c);
                }
            }
            Runnable go = () -> act.accept(a, inputs.stream().map(x -> text(x).trim()).toList());
            button(row, a.name(), null, go);
            inputs.forEach(x -> x.addListener(SWT.DefaultSelection, e -> go.run()));
        }
    }

    /** − and + buttons that change the whole number in {@code input} by one (never below 1): clicks instead of typing. */
    private static void stepper(Composite row, String name, Text input) {
        for (int step : new int[] {-1, 1}) {
            String one = name.replaceAll("s$", "");
            button(row, name + (step < 0 ? "\u2212" : "+"), (step < 0 ? PanelMsg.DIAGRAM_ONE_LESS : PanelMsg.DIAGRAM_ONE_MORE).text(one), () -> {
                int n;
                try {
                    n = Integer.parseInt(input.getText().trim());
                } catch (NumberFormatException e) {
                    n = 1;
                }
                input.setText(Integer.toString(Math.max(1, n + step)));
            }).setText(step < 0 ? "\u2212" : "+");
        }
    }

    private static Button button(Composite row, String name, String tip, Runnable go) {
        Button b = new Button(row, SWT.PUSH);
        b.setText(name);
        b.setData("action", name);
        b.setToolTipText(tip);
        b.addListener(SWT.Selection, e -> go.run());
        return b;
    }

    /**
     * {@code angles} (a pose from the Pose panel, or text dropped on the diagram) if it is a list
     * of numbers, else refused with a message.
     */
    static String usable(String angles) {
        if (angles == null) {
            throw new IllegalArgumentException(PanelMsg.DIAGRAM_SELECT_POSE.text());
        }
        if (!angles.matches("\\s*-?[0-9.eE+-]+(\\s*,\\s*-?[0-9.eE+-]+)*\\s*")) {
            throw new IllegalArgumentException(PanelMsg.DIAGRAM_ONLY_A_POSE.text(angles));
        }
        return angles.trim();
    }

    /**
     * The input that lists states: a state picked from the chooser is added to the list typed so
     * far. Its name is the key tests and the completion find it by; its label is in the user's
     * language ({@link #label}).
     */
    static final String STATES = "add state";

    /**
     * What the row writes before input {@code name}: the attribute's name, which is PARSL and
     * stays English as the file writes it, or for the list of states, words in the user's language.
     */
    static String label(String name) {
        return name.equals(STATES) ? PanelMsg.DIAGRAM_ADD_STATE.text() : name;
    }

    /**
     * The script's names offered by a chooser for input {@code name} (of action {@code action},
     * {@code null} for a node's own field): its groups, automata, states, or, for an instance,
     * its behaviors; empty where a new name is typed (a new behavior, the start's group).
     */
    static List<String> choices(String action, String name, NameIndex names) {
        if (names == null) {
            return List.of();
        }
        Collection<String> out = switch (name) {
            case "group" -> Projection.START.text().equals(action) ? List.of() : names.groups();
            case "automaton" -> PanelMsg.DIAGRAM_MAKE_PHASE_AUTOMATON.text().equals(action) ? List.of() : names.automata();
            case STATES -> names.states();
            case "behavior" -> PanelMsg.DIAGRAM_ADD_INSTANCE.text().equals(action) ? names.behaviorNames() : List.of();
            default -> List.of();
        };
        return out.stream().sorted().toList();
    }

    /** A chooser of the script's names when it has some for {@code name} ({@link #choices}), else a field. */
    private static Control input(Composite row, String action, String name, String value, NameIndex names) {
        List<String> items = choices(action, name, names);
        if (items.isEmpty()) {
            return field(row, name, value, names);
        }
        new Label(row, SWT.NONE).setText(label(name) + ":");
        Combo c = new Combo(row, SWT.DROP_DOWN);
        c.setItems(items.toArray(String[]::new));
        c.setText(value);
        c.setData("field", name);
        c.setVisibleItemCount(Math.min(12, items.size()));
        tip(c, PanelMsg.DIAGRAM_PICK_NAME_TIP.text());
        int widest = items.stream().mapToInt(String::length).max().orElse(0);
        c.setLayoutData(new RowData(Math.max(90, 9 * (Math.max(widest, value.length()) + 2)), SWT.DEFAULT));
        return c;
    }

    /** Chooser {@code c} adds each state picked to the list typed so far ("raise, lower, …"). */
    private static void listed(Combo c) {
        String[] typed = {c.getText()};
        c.addListener(SWT.KeyUp, e -> typed[0] = c.getText());
        c.addListener(SWT.Selection, e -> {
            String picked = c.getText();
            typed[0] = typed[0].isBlank() ? picked : typed[0].strip().replaceAll(",$", "") + ", " + picked;
            c.setText(typed[0]);
        });
        tip(c, PanelMsg.DIAGRAM_PICK_STATES_TIP.text());
    }

    /**
     * Puts {@code tip} on the name before {@code input}, not on the input: a tool tip over a field
     * or a chooser covered its open list (issue 31).
     */
    private static void tip(Control input, String tip) {
        Control[] row = input.getParent().getChildren();
        for (int i = 1; i < row.length; i++) {
            if (row[i] == input && row[i - 1] instanceof Label l) {
                l.setToolTipText(tip);
            }
        }
    }

    /** The text of a field or a chooser. */
    static String text(Control input) {
        return input instanceof Combo c ? c.getText() : ((Text) input).getText();
    }

    private static Text field(Composite row, String name, String value, NameIndex names) {
        new Label(row, SWT.NONE).setText(label(name) + ":");
        Text field = new Text(row, SWT.BORDER | SWT.SINGLE);
        field.setData("field", name);
        field.setText(value);
        field.setLayoutData(new RowData(Math.max(60, 9 * (value.length() + 2)), SWT.DEFAULT));
        AssistField.attach(field, name, names);
        return field;
    }
}
