package org.parpe.gui.panels;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.ScrolledComposite;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.layout.RowLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Scale;
import org.eclipse.swt.widgets.Text;
import org.parpe.core.model.Control.ControlType;
import org.parpe.core.lang.Numbers;
import org.parpe.core.model.Program;
import org.parpe.gui.text.ToolMsg;

/**
 * The control panel generated from a script's {@code <controls>}: a slider, a set of radio
 * buttons or a number box per control, plus the keyboard bindings of {@code keys}. Every change
 * is sent at once to the running program through {@link ControlSink}.
 */
public final class ControlPanel {
    /** Where changes go (the run controller's command queue). */
    public interface ControlSink {
        void setControl(String name, double value);

        void setControlWord(String name, String word);
    }

    private final ScrolledComposite scroll;
    private final Composite body;
    private final ControlSink target;
    private final List<ControlRow> rows = new ArrayList<>();

    public ControlPanel(Composite parent, ControlSink target) {
        this.target = target;
        scroll = new ScrolledComposite(parent, SWT.V_SCROLL);
        body = new Composite(scroll, SWT.NONE);
        body.setLayout(new GridLayout(3, false));
        scroll.setContent(body);
        scroll.setExpandHorizontal(true);
        scroll.setExpandVertical(true);
        scroll.addListener(SWT.Resize, e -> relayout());
        show(null);
    }

    /** The top-level control. */
    public Control control() {
        return scroll;
    }

    /** Rebuilds the panel for {@code program} (null: no program). */
    public void show(Program program) {
        for (Control c : body.getChildren()) {
            c.dispose();
        }
        rows.clear();
        if (program == null || program.controls().isEmpty()) {
            Label l = new Label(body, SWT.WRAP);
            l.setText(program == null ? ToolMsg.PANEL_CONTROLS_APPEAR.text() : ToolMsg.PANEL_NO_CONTROLS.text());
            l.setLayoutData(new GridData(SWT.FILL, SWT.TOP, true, false, 3, 1));
        } else {
            for (org.parpe.core.model.Control c : program.controls()) {
                rows.add(ControlRow.create(body, c, program, target));
            }
            Label hint = new Label(body, SWT.WRAP);
            hint.setText(ToolMsg.PANEL_KEYS_HINT.text());
            hint.setForeground(body.getDisplay().getSystemColor(SWT.COLOR_DARK_GRAY));
            hint.setLayoutData(new GridData(SWT.FILL, SWT.TOP, true, false, 3, 1));
        }
        for (Control c : body.getChildren()) {
            wheelScrolls(c);
        }
        relayout();
    }

    /**
     * The wheel over {@code c} (and its children) scrolls the panel: over a slider it changed the
     * value, and so steered the running robot, when the user only meant to reach the next control.
     */
    private void wheelScrolls(Control c) {
        c.addListener(SWT.MouseVerticalWheel, e -> {
            e.doit = false; // the slider or box under the mouse does not see it
            org.eclipse.swt.graphics.Point o = scroll.getOrigin();
            scroll.setOrigin(o.x, Math.max(0, o.y - e.count * WHEEL_PIXELS));
        });
        if (c instanceof Composite k) {
            for (Control child : k.getChildren()) {
                wheelScrolls(child);
            }
        }
    }

    /** Pixels the panel scrolls per unit of a wheel event's count (GTK counts 3 per notch). */
    private static final int WHEEL_PIXELS = 12;

    private void relayout() {
        int w = scroll.getClientArea().width;
        scroll.setMinSize(body.computeSize(w > 0 ? w : SWT.DEFAULT, SWT.DEFAULT));
        body.layout(true, true);
    }

    /** Sends every control's current value (at the start of a run). */
    public void pushAll() {
        rows.forEach(ControlRow::push);
    }

    /** Applies a key press to the control bound to it; true if a control took it. */
    public boolean key(Event e) {
        String name = keyName(e);
        if (name == null) {
            return false;
        }
        for (ControlRow r : rows) {
            if (r.key(name)) {
                return true;
            }
        }
        return false;
    }

    /** Sets a control as if the user had changed it (tests, stimulus-like automation). */
    public boolean set(String control, String value) {
        for (ControlRow r : rows) {
            if (r.name().equals(control)) {
                return r.set(value);
            }
        }
        return false;
    }

    /** The SWT-style name of a key ({@code a}, {@code 7}, {@code Up}, {@code space}), or null. */
    static String keyName(Event e) {
        switch (e.keyCode) {
            case SWT.ARROW_UP:
                return "Up";
            case SWT.ARROW_DOWN:
                return "Down";
            case SWT.ARROW_LEFT:
                return "Left";
            case SWT.ARROW_RIGHT:
                return "Right";
            case ' ':
                return "space";
            default:
                char c = (char) e.keyCode;
                return Character.isLetterOrDigit(c) && c < 128 ? String.valueOf(c).toLowerCase(Locale.ROOT) : null;
        }
    }

    /** One generated row: label, input widget(s), value or key hint. */
    abstract static class ControlRow {
        final org.parpe.core.model.Control def;
        final ControlSink target;

        ControlRow(org.parpe.core.model.Control def, ControlSink target) {
            this.def = def;
            this.target = target;
        }

        String name() {
            return def.name();
        }

        static ControlRow create(Composite body, org.parpe.core.model.Control c, Program p, ControlSink t) {
            Label l = new Label(body, SWT.NONE);
            l.setText(c.displayLabel());
            l.setToolTipText("$" + c.name());
            ControlRow row = switch (c.type()) {
                case SLIDER -> new SliderRow(body, c, t);
                case RADIO -> new RadioRow(body, c, p, t);
                case TEXT -> new TextRow(body, c, t);
            };
            Label keys = new Label(body, SWT.NONE);
            keys.setText(c.keys().isEmpty() ? "" : "\u2328 " + String.join(" ", c.keys()));
            keys.setForeground(body.getDisplay().getSystemColor(SWT.COLOR_DARK_GRAY));
            return row;
        }

        abstract void push();

        abstract boolean key(String key);

        abstract boolean set(String value);
    }

    private static final class SliderRow extends ControlRow {
        private final Scale scale;
        private final Label value;
        private final double step;

        SliderRow(Composite body, org.parpe.core.model.Control c, ControlSink t) {
            super(c, t);
            Composite box = new Composite(body, SWT.NONE);
            box.setLayout(new GridLayout(2, false));
            box.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
            step = c.step() != null ? c.step() : (c.max() - c.min()) / 100.0;
            scale = new Scale(box, SWT.HORIZONTAL);
            scale.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
            scale.setMinimum(0);
            scale.setMaximum((int) Math.max(1, Math.round((c.max() - c.min()) / step)));
            scale.setSelection((int) Math.round((c.value() - c.min()) / step));
            value = new Label(box, SWT.RIGHT);
            value.setLayoutData(new GridData(60, SWT.DEFAULT));
            scale.addListener(SWT.Selection, e -> push());
            update();
        }

        private double current() {
            return Math.min(def.max(), def.min() + scale.getSelection() * step);
        }

        private void update() {
            value.setText(Numbers.format(Math.round(current() * 1e6) / 1e6));
        }

        @Override
        void push() {
            update();
            target.setControl(def.name(), current());
        }

        @Override
        boolean key(String key) {
            int k = def.keys().indexOf(key);
            if (k < 0 || scale.isDisposed()) {
                return false;
            }
            scale.setSelection(scale.getSelection() + (k == 0 ? 1 : -1));
            push();
            return true;
        }

        @Override
        boolean set(String text) {
            Double v = Numbers.parsePlain(text);
            if (v == null || v < def.min() || v > def.max()) {
                return false;
            }
            scale.setSelection((int) Math.round((v - def.min()) / step));
            push();
            return true;
        }
    }

    private static final class RadioRow extends ControlRow {
        private final List<Button> buttons = new ArrayList<>();

        RadioRow(Composite body, org.parpe.core.model.Control c, Program p, ControlSink t) {
            super(c, t);
            Composite box = new Composite(body, SWT.NONE);
            box.setLayout(new RowLayout(SWT.HORIZONTAL));
            box.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
            for (String w : c.words()) {
                Button b = new Button(box, SWT.RADIO);
                b.setText(w);
                b.setSelection(p.radioWords().getOrDefault(w, -1) == (int) c.value());
                b.addListener(SWT.Selection, e -> {
                    if (b.getSelection()) {
                        target.setControlWord(def.name(), w);
                    }
                });
                buttons.add(b);
            }
        }

        @Override
        void push() {
            for (Button b : buttons) {
                if (b.getSelection()) {
                    target.setControlWord(def.name(), b.getText());
                }
            }
        }

        @Override
        boolean key(String key) {
            int k = def.keys().indexOf(key);
            return k >= 0 && k < def.words().size() && set(def.words().get(k));
        }

        @Override
        boolean set(String word) {
            if (!def.words().contains(word)) {
                return false;
            }
            for (Button b : buttons) {
                b.setSelection(b.getText().equals(word));
            }
            target.setControlWord(def.name(), word);
            return true;
        }
    }

    private static final class TextRow extends ControlRow {
        private final Text text;

        TextRow(Composite body, org.parpe.core.model.Control c, ControlSink t) {
            super(c, t);
            text = new Text(body, SWT.BORDER | SWT.SINGLE);
            text.setText(Numbers.format(c.value()));
            text.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
            text.setToolTipText(ToolMsg.PANEL_TYPE_NUMBER.text());
            text.addListener(SWT.DefaultSelection, e -> push());
            text.addListener(SWT.FocusOut, e -> push());
        }

        @Override
        void push() {
            Double v = Numbers.parsePlain(text.getText());
            if (v == null) {
                text.setBackground(text.getDisplay().getSystemColor(SWT.COLOR_YELLOW));
                text.setToolTipText(ToolMsg.PANEL_NOT_A_NUMBER_KEEPS.text(text.getText(), def.name()));
                return;
            }
            text.setBackground(null);
            text.setToolTipText(ToolMsg.PANEL_TYPE_NUMBER.text());
            target.setControl(def.name(), v);
        }

        @Override
        boolean key(String key) {
            return false;
        }

        @Override
        boolean set(String value) {
            text.setText(value);
            push();
            return Numbers.parsePlain(value) != null;
        }
    }
}
