package org.parpe.gui.diagram;

import java.util.ArrayList;
import java.util.List;
import java.util.function.BiConsumer;
import java.util.function.Supplier;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.RowData;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Text;
import org.parpe.gui.diagram.Projection.Action;
import org.parpe.gui.diagram.Projection.Field;
import org.parpe.gui.diagram.Projection.Target;
import org.parpe.gui.editor.NameIndex;

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
            Text field = field(row, f.name(), f.value(), names);
            field.setToolTipText("Enter writes the new " + f.name() + " into the text (one Undo step); Ctrl+Space offers names");
            field.addListener(SWT.DefaultSelection, e -> write.accept(f, field.getText()));
            if (f.name().equals("angles") && pose != null) {
                button(row, "Use pose", "The pose selected in the Pose panel becomes this state's angles (or drag it onto the state)",
                        () -> act.accept(new Action("Use pose", List.of(), v -> f.edit().apply(usable(pose.get()))), List.of()));
            }
        }
        for (Action a : t.actions()) {
            List<Text> inputs = new ArrayList<>();
            for (int i = 0; i < a.inputs().size(); i++) {
                Text input = field(row, a.inputs().get(i), a.values().get(i), names);
                inputs.add(input);
                if (a.values().get(i).matches("[0-9]+")) {
                    stepper(row, a.inputs().get(i), input);
                }
            }
            Runnable go = () -> act.accept(a, inputs.stream().map(x -> x.getText().trim()).toList());
            button(row, a.name(), null, go);
            inputs.forEach(x -> x.addListener(SWT.DefaultSelection, e -> go.run()));
        }
    }

    /** − and + buttons that change the whole number in {@code input} by one (never below 1): clicks instead of typing. */
    private static void stepper(Composite row, String name, Text input) {
        for (int step : new int[] {-1, 1}) {
            String one = name.replaceAll("s$", "");
            button(row, name + (step < 0 ? "\u2212" : "+"), step < 0 ? "One " + one + " less" : "One more " + one, () -> {
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
            throw new IllegalArgumentException("Select a pose in the Pose panel first (or drag one onto the state).");
        }
        if (!angles.matches("\\s*-?[0-9.eE+-]+(\\s*,\\s*-?[0-9.eE+-]+)*\\s*")) {
            throw new IllegalArgumentException("Only a pose (numbers separated by commas) can become a state's angles, not '"
                    + angles + "'.");
        }
        return angles.trim();
    }

    private static Text field(Composite row, String name, String value, NameIndex names) {
        new Label(row, SWT.NONE).setText(name + ":");
        Text field = new Text(row, SWT.BORDER | SWT.SINGLE);
        field.setData("field", name);
        field.setText(value);
        field.setLayoutData(new RowData(Math.max(60, 9 * (value.length() + 2)), SWT.DEFAULT));
        AssistField.attach(field, name, names);
        return field;
    }
}
