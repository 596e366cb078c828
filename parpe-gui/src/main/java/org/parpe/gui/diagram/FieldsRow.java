package org.parpe.gui.diagram;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BiConsumer;
import java.util.function.Supplier;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Text;
import org.parpe.gui.diagram.Projection.Action;
import org.parpe.gui.diagram.Projection.Field;
import org.parpe.gui.diagram.Projection.Target;
import org.parpe.gui.editor.NameIndex;

/**
 * The place of the Diagram pane's edit row ({@link EditRow}) between the choosers and the
 * drawing: as tall with fields as without (two rows, or as many as the fields need at the tab's
 * width), so that the drawing does not move when a node is selected or edited; hidden in a view
 * with nothing to edit. UI thread only.
 */
final class FieldsRow {
    private final Composite box;
    private final Runnable layoutAgain;
    private final Composite fields;
    private final int twoRows;
    private int fitWidth = -1;

    /** The row, in {@code box} (whose layout is a {@code GridLayout}); {@code layoutAgain} lays the pane out when its height changes. */
    FieldsRow(Composite box, Runnable layoutAgain) {
        this.box = box;
        this.layoutAgain = layoutAgain;
        fields = new Composite(box, SWT.NONE);
        fields.setLayout(DiagramPane.row());
        GridData fd = new GridData(SWT.FILL, SWT.CENTER, true, false);
        // two rows: a palette item or a state has more fields than one row of a narrow tab holds
        Text probe = new Text(fields, SWT.BORDER | SWT.SINGLE);
        twoRows = 2 * probe.computeSize(SWT.DEFAULT, SWT.DEFAULT).y + 4;
        fd.heightHint = twoRows;
        probe.dispose();
        fields.setLayoutData(fd);
        box.addListener(SWT.Resize, e -> fit());
    }

    /**
     * Shows {@code t}'s fields and actions ({@link EditRow#fill}), or an empty row; the row is
     * there only when {@code shown} (a view with something to edit).
     */
    void fill(Target t, boolean shown, NameIndex names, BiConsumer<Field, String> write,
              BiConsumer<Action, List<String>> act, Supplier<String> pose) {
        EditRow.fill(fields, t, names, write, act, pose);
        fields.setVisible(shown);
        ((GridData) fields.getLayoutData()).exclude = !shown;
        fields.layout(true);
        fit();
    }

    /**
     * The row's height: two rows of fields, or as many as its fields need at the tab's width, so
     * that no Add button is hidden under the message line. The same node after an edit needs the
     * same height: nothing moves.
     */
    private void fit() {
        GridData fd = (GridData) fields.getLayoutData();
        int width = box.getClientArea().width; // the controls have no margin (AboveTheDrawing)
        int need = width > 0 ? fields.computeSize(width, SWT.DEFAULT).y : 0;
        // at the same width the row never shrinks: what an Add switches to does not pull the drawing up
        int h = Math.max(width == fitWidth ? fd.heightHint : twoRows, need);
        fitWidth = width;
        if (fd.heightHint != h) {
            fd.heightHint = h;
            layoutAgain.run();
        }
    }

    /** The value fields, by name. */
    Map<String, Text> fields() {
        return controls(Text.class, "field");
    }

    /** The choosers (the inputs that list the script's names), by name. */
    Map<String, Combo> choosers() {
        return controls(Combo.class, "field");
    }

    /** The action buttons, by label. */
    Map<String, Button> actions() {
        return controls(Button.class, "action");
    }

    private <T extends Control> Map<String, T> controls(Class<T> type, String key) {
        Map<String, T> out = new LinkedHashMap<>();
        for (Control c : fields.getChildren()) {
            if (type.isInstance(c)) {
                out.put((String) c.getData(key), type.cast(c));
            }
        }
        return out;
    }
}
