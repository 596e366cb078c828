package org.parpe.gui.robot;

import java.util.ArrayList;
import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.ScrolledComposite;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.layout.RowData;
import org.eclipse.swt.layout.RowLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Text;
import org.parpe.gui.text.ToolMsg;
import org.parpe.gui.view3d.View3D;
import org.parpe.sim.config.PartType;

/**
 * The Robot tab's widgets, laid out: over the 3D view, what is shown and its buttons, the kit
 * palette with the orientation, and the selected part's properties, in rows that wrap; under
 * it, how the robot fits the script and the kit, and what the last action did. The rows scroll
 * when they would take more than {@link #ROWS_SHARE} of the tab (twice the text on a 1366×768
 * screen), so that every control stays reachable and the view keeps its room.
 */
final class TabControls {
    /** The most of the tab's height the rows of controls take before they scroll. */
    static final double ROWS_SHARE = 0.4;

    final Composite root;
    private final ScrolledComposite scroll;
    private final Composite rowsBox;
    final Label source;
    final Button editRobot;
    final Button makeEditable;
    final Button tryIt;
    final Button undo;
    final Button redo;
    final Button kit;
    final Button[] types = new Button[PartType.values().length];
    final Text hubPlates;
    /** 0°, 90°, 180°, 270°: how the new part is turned on its plate. */
    final Button[] turns = new Button[4];
    final Button place;
    final Button connect;
    final Button assignIds;
    final View3D view;
    final Label partName;
    final Text moduleId;
    final Text angle;
    final Button limp;
    /** The root's roll, degrees (a wheel stands on its rim at 90). */
    final Text roll;
    final Button turn;
    final Button delete;
    final Button makeRoot;
    final Label fit;
    final Label message;
    private final List<Composite> rows = new ArrayList<>();
    private final List<Text> boxes = new ArrayList<>();

    TabControls(Composite parent) {
        root = new Composite(parent, SWT.NONE);
        root.setLayout(grid(0, 2));
        scroll = new ScrolledComposite(root, SWT.V_SCROLL);
        scroll.setExpandHorizontal(true);
        scroll.setLayoutData(new GridData(SWT.FILL, SWT.TOP, true, false));
        rowsBox = new Composite(scroll, SWT.NONE);
        rowsBox.setLayout(grid(0, 0));
        scroll.setContent(rowsBox);

        Composite top = row();
        source = new Label(top, SWT.NONE);
        tryIt = button(top, ToolMsg.ROBOT_TRY_IT.text(), ToolMsg.ROBOT_TRY_IT_TIP.text());
        undo = button(top, ToolMsg.ROBOT_UNDO.text(), ToolMsg.ROBOT_UNDO_TIP.text());
        redo = button(top, ToolMsg.ROBOT_REDO.text(), ToolMsg.ROBOT_REDO_TIP.text());
        connect = button(top, ToolMsg.ROBOT_CONNECT.text(), ToolMsg.ROBOT_CONNECT_TIP.text());
        assignIds = button(top, ToolMsg.ROBOT_ASSIGN_IDS.text(), ToolMsg.ROBOT_ASSIGN_IDS_TIP.text());
        kit = button(top, ToolMsg.ROBOT_KIT.text(), ToolMsg.ROBOT_KIT_TIP.text());
        editRobot = button(top, ToolMsg.ROBOT_EDIT.text(), ToolMsg.ROBOT_EDIT_TIP.text());
        makeEditable = button(top, ToolMsg.ROBOT_MAKE_EDITABLE.text(), ToolMsg.ROBOT_MAKE_EDITABLE_TIP.text());

        Composite palette = row();
        new Label(palette, SWT.NONE).setText(ToolMsg.ROBOT_ADD.text());
        typeButtons(group(palette)); // radio buttons of one parent exclude each other
        hubPlates = box(palette, ToolMsg.ROBOT_HUB_PLATES_TIP.text(), 3);
        hubPlates.setText(Integer.toString(PartType.HUB.defaultPlates()));
        new Label(palette, SWT.NONE).setText(ToolMsg.ROBOT_TURNED.text());
        turnButtons(group(palette));
        place = button(palette, ToolMsg.ROBOT_PLACE.text(), ToolMsg.ROBOT_PLACE_TIP.text());

        Composite props = row();
        partName = new Label(props, SWT.NONE);
        new Label(props, SWT.NONE).setText(ToolMsg.ROBOT_WHAT_ID.text());
        moduleId = box(props, ToolMsg.ROBOT_ID_TIP.text(), 4);
        new Label(props, SWT.NONE).setText(ToolMsg.ROBOT_ANGLE.text());
        angle = box(props, ToolMsg.ROBOT_ANGLE_TIP.text(), 6);
        limp = new Button(props, SWT.CHECK);
        limp.setText(ToolMsg.ROBOT_LIMP.text());
        limp.setToolTipText(ToolMsg.ROBOT_LIMP_TIP.text());
        new Label(props, SWT.NONE).setText(ToolMsg.ROBOT_ROLL.text());
        roll = box(props, ToolMsg.ROBOT_ROLL_TIP.text(), 5);
        turn = button(props, ToolMsg.ROBOT_TURN.text(), ToolMsg.ROBOT_TURN_TIP.text());
        delete = button(props, ToolMsg.ROBOT_DELETE.text(), ToolMsg.ROBOT_DELETE_TIP.text());
        makeRoot = button(props, ToolMsg.ROBOT_MAKE_ROOT.text(), ToolMsg.ROBOT_MAKE_ROOT_TIP.text());

        view = new View3D(root);
        view.control().setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        view.setTrackRobot(false);
        view.setEmptyText(ToolMsg.ROBOT_EMPTY.text());
        fit = wrapped();
        message = wrapped();
        root.addListener(SWT.Resize, e -> relayout());
    }

    /** One radio button a part type, the segment chosen. */
    private void typeButtons(Composite box) {
        for (PartType t : PartType.values()) {
            Button b = new Button(box, SWT.RADIO);
            b.setText(t.xmlName().substring(0, 1).toUpperCase(java.util.Locale.ROOT) + t.xmlName().substring(1));
            types[t.ordinal()] = b;
        }
        types[PartType.SEGMENT.ordinal()].setSelection(true);
    }

    /** One radio button a quarter turn, 0° chosen. */
    private void turnButtons(Composite box) {
        for (int q = 0; q < 4; q++) {
            turns[q] = new Button(box, SWT.RADIO);
            turns[q].setText(q * 90 + "\u00B0");
            turns[q].setToolTipText(ToolMsg.ROBOT_TURNED_TIP.text());
        }
        turns[0].setSelection(true);
    }

    private static GridLayout grid(int margin, int spacing) {
        GridLayout gl = new GridLayout(1, false);
        gl.marginWidth = margin;
        gl.marginHeight = margin;
        gl.verticalSpacing = spacing;
        return gl;
    }

    private Composite row() {
        Composite c = new Composite(rowsBox, SWT.NONE);
        RowLayout rl = new RowLayout(SWT.HORIZONTAL);
        rl.wrap = true;
        rl.center = true;
        rl.marginTop = 1;
        rl.marginBottom = 1;
        rl.marginLeft = 0; // a line as wide as the row (a radio group at 200 %) is not cut by a margin
        rl.marginRight = 0;
        rl.spacing = 4;
        c.setLayout(rl);
        c.setLayoutData(new GridData(SWT.FILL, SWT.TOP, true, false));
        rows.add(c);
        return c;
    }

    /** A row of radio buttons inside a row. */
    private static Composite group(Composite parent) {
        Composite c = new Composite(parent, SWT.NONE);
        RowLayout rl = new RowLayout(SWT.HORIZONTAL);
        rl.marginLeft = 0;
        rl.marginRight = 0;
        rl.marginTop = 0;
        rl.marginBottom = 0;
        rl.spacing = 2;
        c.setLayout(rl);
        return c;
    }

    /** A box for a number of up to {@code chars} characters (its width follows the font). */
    private Text box(Composite parent, String tip, int chars) {
        Text t = new Text(parent, SWT.BORDER | SWT.SINGLE);
        t.setToolTipText(tip);
        t.setData("chars", chars);
        boxes.add(t);
        return t;
    }

    private Label wrapped() {
        Label l = new Label(root, SWT.WRAP);
        GridData gd = new GridData(SWT.FILL, SWT.TOP, true, false);
        gd.widthHint = 100;
        gd.exclude = true; // empty: no room taken ({@link #line})
        l.setLayoutData(gd);
        l.setVisible(false);
        return l;
    }

    /** Shows {@code text} in {@code label} (one of the lines under the view); an empty line takes no room. */
    void line(Label label, String text) {
        if (label.getText().equals(text)) {
            return;
        }
        label.setText(text);
        boolean empty = text.isEmpty();
        ((GridData) label.getLayoutData()).exclude = empty;
        label.setVisible(!empty);
        relayout();
    }

    private static Button button(Composite parent, String text, String tip) {
        Button b = new Button(parent, SWT.PUSH);
        b.setText(text);
        b.setToolTipText(tip);
        return b;
    }

    /** The orientation chosen, in quarter turns. */
    int quarterTurns() {
        for (int q = 0; q < 4; q++) {
            if (turns[q].getSelection()) {
                return q;
            }
        }
        return 0;
    }

    /** The part type chosen in the palette. */
    PartType type() {
        for (PartType t : PartType.values()) {
            if (types[t.ordinal()].getSelection()) {
                return t;
            }
        }
        return PartType.SEGMENT;
    }

    /** Every control of the tab but the 3D view (to zoom their text, and tests), in order. */
    List<Control> all() {
        List<Control> out = new ArrayList<>();
        for (Composite r : rows) {
            for (Control c : r.getChildren()) {
                if (c instanceof Composite box) {
                    out.addAll(List.of(box.getChildren()));
                } else {
                    out.add(c);
                }
            }
        }
        out.add(fit);
        out.add(message);
        return out;
    }

    /** Brings {@code c} (one of the rows' controls) into sight in the rows' scrolled box. */
    void reveal(Control c) {
        for (Control up = c; up != null; up = up.getParent()) {
            if (up == rowsBox) {
                scroll.showControl(c);
                return;
            }
        }
    }

    /**
     * Lays the tab out again for its size and text: the number boxes as wide as their longest
     * value, the rows wrapped to the width, and scrolling when they would take more than
     * {@link #ROWS_SHARE} of the height.
     */
    void relayout() {
        for (Text t : boxes) {
            if (t.getData("font") != t.getFont()) { // sized for each font (the zoom), not at each layout
                GC gc = new GC(t);
                int w = gc.textExtent("0".repeat((Integer) t.getData("chars"))).x;
                gc.dispose();
                t.setLayoutData(new RowData(w + 16, SWT.DEFAULT));
                t.setData("font", t.getFont());
            }
        }
        int width = Math.max(50, root.getClientArea().width);
        Point want = rowsBox.computeSize(width, SWT.DEFAULT, true);
        // the lines under the view keep their room first (a long language at 200 % wraps them to several lines)
        int lines = 0;
        for (Label l : new Label[] {fit, message}) {
            lines += l.getVisible() ? l.computeSize(width, SWT.DEFAULT).y : 0;
        }
        int most = (int) (Math.max(0, root.getClientArea().height - lines) * ROWS_SHARE);
        boolean scrolls = want.y > most && root.getClientArea().height > 0;
        int inner = scrolls ? width - scroll.getVerticalBar().getSize().x : width;
        want = rowsBox.computeSize(inner, SWT.DEFAULT, true);
        rowsBox.setSize(inner, want.y);
        scroll.setMinHeight(want.y);
        ((GridData) scroll.getLayoutData()).heightHint = scrolls ? most : want.y;
        root.layout(true, true);
        rowsBox.setSize(inner, want.y);
    }
}
