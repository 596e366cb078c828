package org.parpe.gui.pose;

import java.util.Locale;
import java.util.function.IntConsumer;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.ScrolledComposite;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableItem;
import org.eclipse.swt.widgets.Text;
import org.parpe.gui.text.PanelMsg;
import org.parpe.gui.panels.TitleWidths;

/**
 * The list of poses with the time since the previous one, and the buttons that edit it: move up
 * or down, duplicate, mirror, delete, retime and update a pose from the sliders. Selecting a pose
 * shows it on the sliders. UI thread only.
 */
final class PoseTable {
    /** The rows the table shows before the side scrolls. */
    private static final int ROWS_AT_LEAST = 3;
    /** What the table asks of the panel. */
    interface Owner {
        /** The current angles of the sliders, group order. */
        double[] sliders();

        /** Mirrors pose {@code i} (the panel knows the robot's left and right groups). */
        void mirror(int i);

        /** A pose was selected: show it. */
        void selected(PoseList.Pose pose);

        /** A message for the status bar. */
        void say(String text);
    }

    /** The table, its buttons and its time row; they scroll in a pane too low for them (a docked tutorial beside them). */
    private final ScrolledComposite scroll;
    private final Composite box;
    private final Table table;
    private final Text time;
    private final Owner owner;
    private PoseList list;

    PoseTable(Composite parent, Owner owner) {
        this.owner = owner;
        scroll = new ScrolledComposite(parent, SWT.V_SCROLL);
        scroll.setExpandHorizontal(true);
        scroll.setExpandVertical(true);
        box = new Composite(scroll, SWT.NONE);
        scroll.setContent(box);
        GridLayout gl = new GridLayout(1, false);
        gl.marginWidth = 0;
        gl.marginHeight = 0;
        box.setLayout(gl);
        table = new Table(box, SWT.BORDER | SWT.SINGLE | SWT.FULL_SELECTION);
        table.setHeaderVisible(true);
        table.setLinesVisible(true);
        GridData td = new GridData(SWT.FILL, SWT.FILL, true, true);
        td.heightHint = table.getHeaderHeight() + ROWS_AT_LEAST * table.getItemHeight(); // more where the pane has room
        table.setLayoutData(td);
        column("#", 34);
        column(PanelMsg.POSE_COL_AFTER.text(), 70);
        column(PanelMsg.POSE_COL_ANGLES.text(), 220);
        table.addListener(SWT.Selection, e -> rowSelected());
        Composite buttons = org.parpe.gui.panels.WrapRow.of(box);
        button(buttons, PanelMsg.POSE_UP.text(), PanelMsg.POSE_UP_TIP.text(), i -> select(list.move(i, -1)));
        button(buttons, PanelMsg.POSE_DOWN.text(), PanelMsg.POSE_DOWN_TIP.text(), i -> select(list.move(i, 1)));
        button(buttons, PanelMsg.POSE_DUPLICATE.text(), PanelMsg.POSE_DUPLICATE_TIP.text(), i -> select(list.duplicate(i)));
        button(buttons, PanelMsg.POSE_MIRROR.text(), PanelMsg.POSE_MIRROR_TIP.text(), owner::mirror);
        button(buttons, PanelMsg.POSE_UPDATE.text(), PanelMsg.POSE_UPDATE_TIP.text(), i -> list.set(i, owner.sliders()));
        button(buttons, PanelMsg.POSE_DELETE.text(), PanelMsg.POSE_DELETE_TIP.text(), i -> {
            list.remove(i);
            select(Math.min(i, list.size() - 1));
        });
        Composite timing = org.parpe.gui.panels.WrapRow.of(box); // a narrow pane wraps it, never widens the table's side
        new Label(timing, SWT.NONE).setText(PanelMsg.POSE_TIME.text());
        time = new Text(timing, SWT.BORDER);
        time.setText("1.00");
        time.setToolTipText(PanelMsg.POSE_TIME_TIP.text(PoseList.MIN_INTERVAL, (int) PoseList.MAX_INTERVAL));
        time.setLayoutData(new org.eclipse.swt.layout.RowData(50, SWT.DEFAULT));
        time.addListener(SWT.DefaultSelection, e -> retime());
        new Label(timing, SWT.NONE).setText("s");
        button(timing, PanelMsg.POSE_SET_TIME.text(), PanelMsg.POSE_SET_TIME_TIP.text(), i -> retime());
        scroll.addListener(SWT.Resize, e -> fit());
    }

    /** Scrolls when the pane is lower than the rows need at its width (the button rows wrap to it). */
    private void fit() {
        int width = scroll.getClientArea().width;
        if (width > 0) {
            scroll.setMinHeight(box.computeSize(width, SWT.DEFAULT).y);
        }
    }

    private void rowSelected() {
        int i = table.getSelectionIndex();
        if (list != null && i >= 0 && i < list.size()) {
            time.setText(seconds(list.get(i).interval()));
            owner.selected(list.get(i));
        }
    }

    private void column(String title, int width) {
        TitleWidths.column(table, SWT.LEFT, title, width);
    }

    private void button(Composite parent, String text, String tip, IntConsumer onSelected) {
        Button b = new Button(parent, SWT.PUSH);
        b.setText(text);
        b.setToolTipText(tip);
        b.addListener(SWT.Selection, e -> {
            int i = table.getSelectionIndex();
            if (list == null || i < 0 || i >= list.size()) {
                owner.say(PanelMsg.POSE_SELECT_FIRST.text());
                return;
            }
            onSelected.accept(i);
            refresh();
        });
    }

    Control control() {
        return scroll;
    }

    /** Shows {@code poses} (null: none). */
    void show(PoseList poses) {
        list = poses;
        refresh();
    }

    /** Redraws the rows from the list, keeping the selection. */
    void refresh() {
        int sel = table.getSelectionIndex();
        table.removeAll();
        if (list == null) {
            return;
        }
        for (int i = 0; i < list.size(); i++) {
            PoseList.Pose p = list.get(i);
            TableItem it = new TableItem(table, SWT.NONE);
            StringBuilder a = new StringBuilder();
            for (double v : p.angles()) {
                a.append(a.length() == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.1f", v));
            }
            it.setText(new String[] {Integer.toString(i + 1), seconds(p.interval()), a.toString()});
        }
        if (sel >= 0 && sel < list.size()) {
            table.setSelection(sel);
        }
    }

    /** Selects pose {@code i} (−1: none) as a click would. */
    void select(int i) {
        refresh();
        if (i < 0 || list == null || i >= list.size()) {
            table.deselectAll();
            return;
        }
        table.setSelection(i);
        table.showSelection();
        table.notifyListeners(SWT.Selection, new org.eclipse.swt.widgets.Event());
    }

    /** The selected pose's index, or −1. */
    int selection() {
        return table.getSelectionIndex();
    }

    /** The time typed for new poses, s; null (and a message) when it is not a number in range. */
    Double interval() {
        Double v = PoseList.parseInterval(time.getText());
        if (v == null) {
            owner.say(PanelMsg.POSE_TIME_NOT_A_NUMBER.text(PoseList.MIN_INTERVAL, (int) PoseList.MAX_INTERVAL, time.getText().trim()));
        }
        return v;
    }

    /** Shows {@code seconds} in the time box (the real time since the last capture). */
    void setInterval(double seconds) {
        time.setText(seconds(seconds));
    }

    private void retime() {
        int i = table.getSelectionIndex();
        Double v = interval();
        if (list == null || i < 0 || v == null) {
            if (v != null) {
                owner.say(PanelMsg.POSE_SELECT_FIRST.text());
            }
            return;
        }
        list.retime(i, v);
        refresh();
    }

    /** The table (tests click it and read it). */
    Table table() {
        return table;
    }

    /** The button labelled {@code text} (mnemonics ignored) anywhere in {@code parent}, or null (tests press it). */
    static Button find(Composite parent, String text) {
        for (Control c : parent.getChildren()) {
            if (c instanceof Button b && b.getText().replace("&", "").equals(text)) {
                return b;
            }
            if (c instanceof Composite child) {
                Button b = find(child, text);
                if (b != null) {
                    return b;
                }
            }
        }
        return null;
    }

    /** The time box (tests type in it). */
    Text timeBox() {
        return time;
    }

    static String seconds(double s) {
        return String.format(Locale.ROOT, "%.2f", s);
    }
}
