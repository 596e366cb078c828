package org.parpe.gui.sweep;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.text.DecimalFormatSymbols;
import java.util.Map;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.ScrolledComposite;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Spinner;
import org.eclipse.swt.widgets.Text;
import org.parpe.core.lang.Numbers;
import org.parpe.core.model.Parameter;
import org.parpe.gui.text.ToolMsg;
import org.parpe.sim.sweep.Axis;
import org.parpe.sim.sweep.SweepException;
import org.parpe.sim.sweep.SweepSpec;
import org.parpe.sim.sweep.VarySpec;

/**
 * The Sweep tab: one line per script parameter (vary it or not, from, to, number of values; the
 * value it is held at when it is not varied, as {@code parpe sweep --param}; its bounds beside), a grid or a random draw with its count, runs per combination and the
 * seed. {@link #spec} turns the boxes into the engine's {@link SweepSpec} with the engine's
 * own checks and messages ({@link VarySpec}).
 */
final class SweepTab {
    private static final ToolMsg[] COLUMNS = {ToolMsg.SWEEP_VARY, ToolMsg.SWEEP_PARAMETER, ToolMsg.SWEEP_FROM, ToolMsg.SWEEP_TO,
        ToolMsg.SWEEP_VALUES, ToolMsg.SWEEP_HOLD_AT, ToolMsg.SWEEP_BOUNDS};
    private final Composite root;
    private final Composite lines;
    private final ScrolledComposite scroller;
    private final Map<String, Line> byName = new LinkedHashMap<>();
    private final Button grid;
    private final Button random;
    private final Spinner count;
    private final Spinner repeat;
    private final Text seed;

    /** The widgets of one parameter. */
    record Line(Parameter parameter, Button vary, Text from, Text to, Text values, Text hold) {
    }

    /**
     * What the Values box says: a whole number is how many evenly spaced values from From to To;
     * anything else is the values themselves ({@code 2.5}, {@code 0.1; 0.2}), read with the decimal
     * separator of {@code locale} too (a student in Germany types {@code 2,5}). A spin box took
     * "2.5" as 25 (issue 23, item 13).
     *
     * @param count how many values from From to To, or 0 when {@code list} holds them
     * @param list  the values typed, or empty
     */
    record Values(int count, List<Double> list) {
        static Values read(String typed, Locale locale) throws SweepException {
            String t = typed.trim();
            if (t.matches("\\d{1,7}")) {
                int n = Integer.parseInt(t);
                if (n < 1) {
                    throw new SweepException(ToolMsg.SWEEP_BAD_COUNT.text(t));
                }
                return new Values(n, List.of());
            }
            boolean decimalComma = DecimalFormatSymbols.getInstance(locale).getDecimalSeparator() == ',';
            List<Double> out = new ArrayList<>();
            for (String token : t.split(decimalComma ? "[;\\s]+" : "[;,\\s]+")) {
                Double v = token.isEmpty() ? null : Numbers.parsePlain(decimalComma ? token.replace(',', '.') : token);
                if (v == null || !Double.isFinite(v)) {
                    throw new SweepException(ToolMsg.SWEEP_BAD_VALUES.text(t));
                }
                out.add(v);
            }
            return new Values(0, List.copyOf(out));
        }
    }

    SweepTab(Composite parent) {
        root = new Composite(parent, SWT.NONE);
        root.setLayout(new GridLayout(1, false));
        scroller = new ScrolledComposite(root, SWT.V_SCROLL | SWT.BORDER);
        scroller.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        scroller.setExpandHorizontal(true);
        lines = new Composite(scroller, SWT.NONE);
        scroller.setContent(lines);
        lines.setLayout(new GridLayout(COLUMNS.length, false));
        Composite how = new Composite(root, SWT.NONE);
        how.setLayout(new GridLayout(8, false));
        grid = new Button(how, SWT.RADIO);
        grid.setText(ToolMsg.SWEEP_GRID.text());
        grid.setSelection(true);
        random = new Button(how, SWT.RADIO);
        random.setText(ToolMsg.SWEEP_RANDOM.text());
        count = spinner(how, 1, 1_000_000, 20);
        count.setToolTipText(ToolMsg.SWEEP_RANDOM_TIP.text());
        new Label(how, SWT.NONE).setText("   " + ToolMsg.SWEEP_REPEAT.text());
        repeat = spinner(how, 1, 1000, 1);
        repeat.setToolTipText(ToolMsg.SWEEP_REPEAT_TIP.text());
        new Label(how, SWT.NONE).setText("   " + ToolMsg.SWEEP_SEED.text());
        seed = new Text(how, SWT.BORDER);
        seed.setText("0");
        seed.setLayoutData(new GridData(70, SWT.DEFAULT));
    }

    private static Spinner spinner(Composite parent, int min, int max, int value) {
        Spinner s = new Spinner(parent, SWT.BORDER);
        s.setValues(value, min, max, 0, 1, 10);
        return s;
    }

    Control control() {
        return root;
    }

    /**
     * One line per parameter of {@code parameters}; a parameter that had a line before keeps
     * what was typed for it (the script was edited while the dialog was open).
     */
    void setParameters(List<Parameter> parameters) {
        Map<String, String[]> typed = new LinkedHashMap<>();
        byName.forEach((n, l) -> typed.put(n, new String[] {Boolean.toString(l.vary().getSelection()), l.from().getText(),
            l.to().getText(), l.values().getText(), l.hold().getText()}));
        for (Control c : lines.getChildren()) {
            c.dispose();
        }
        byName.clear();
        for (ToolMsg h : COLUMNS) {
            Label l = new Label(lines, SWT.NONE);
            l.setText(h.text());
        }
        for (Parameter p : parameters) {
            Line line = line(p);
            String[] before = typed.get(p.name());
            if (before != null) {
                line.vary().setSelection(Boolean.parseBoolean(before[0]));
                line.from().setText(before[1]);
                line.to().setText(before[2]);
                line.values().setText(before[3]);
                line.hold().setText(before[4]);
            }
            byName.put(p.name(), line);
        }
        if (parameters.isEmpty()) {
            Label none = new Label(lines, SWT.WRAP);
            none.setText(ToolMsg.SWEEP_NO_PARAMETERS.text());
            none.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, COLUMNS.length, 1));
        }
        lines.setSize(lines.computeSize(SWT.DEFAULT, SWT.DEFAULT));
        // The same size as before would not lay the new lines out by itself.
        lines.layout(true, true);
        scroller.setMinHeight(lines.getSize().y);
    }

    private Line line(Parameter p) {
        Button vary = new Button(lines, SWT.CHECK);
        new Label(lines, SWT.NONE).setText(p.displayLabel().equals(p.name()) ? p.name() : p.name() + " (" + p.displayLabel() + ")");
        Text from = new Text(lines, SWT.BORDER);
        from.setText(Numbers.format(p.min() != null ? p.min() : p.value()));
        from.setLayoutData(new GridData(70, SWT.DEFAULT));
        Text to = new Text(lines, SWT.BORDER);
        to.setText(Numbers.format(p.max() != null ? p.max() : p.value()));
        to.setLayoutData(new GridData(70, SWT.DEFAULT));
        Text values = new Text(lines, SWT.BORDER);
        values.setText("3");
        values.setLayoutData(new GridData(70, SWT.DEFAULT));
        values.setToolTipText(ToolMsg.SWEEP_VALUES_TIP.text());
        Text hold = new Text(lines, SWT.BORDER);
        hold.setText(Numbers.format(p.value()));
        hold.setLayoutData(new GridData(70, SWT.DEFAULT));
        hold.setToolTipText(ToolMsg.SWEEP_HOLD_TIP.text(p.name(), Numbers.format(p.value())));
        Label bounds = new Label(lines, SWT.NONE);
        bounds.setText((p.min() == null ? "-\u221e" : Numbers.format(p.min())) + " \u2026 "
                + (p.max() == null ? "+\u221e" : Numbers.format(p.max())) + "   (" + Numbers.format(p.value()) + ")");
        bounds.setForeground(lines.getDisplay().getSystemColor(SWT.COLOR_DARK_GRAY));
        return new Line(p, vary, from, to, values, hold);
    }

    /** The line of parameter {@code name}, or null (tests, automation). */
    Line line(String name) {
        return byName.get(name);
    }

    /** Chooses a random sweep of {@code n} combinations, or a grid when {@code n} is 0 (tests, automation). */
    void setRandom(int n) {
        random.setSelection(n > 0);
        grid.setSelection(n <= 0);
        if (n > 0) {
            count.setSelection(n);
        }
    }

    /**
     * The sweep the boxes describe for {@code parameters} (the script as it is now); a bad range
     * or seed throws with one line naming the parameter and the value.
     */
    SweepSpec spec(List<Parameter> parameters) throws SweepException {
        List<Axis> axes = new ArrayList<>();
        boolean draw = random.getSelection();
        for (Line l : byName.values()) {
            if (!l.vary().getSelection()) {
                continue;
            }
            String name = l.parameter().name();
            String range = l.from().getText().trim() + ".." + l.to().getText().trim();
            Values v = Values.read(l.values().getText(), Locale.getDefault());
            String body = !v.list().isEmpty() ? String.join(",", v.list().stream().map(Numbers::format).toList())
                    : range + (draw ? "" : ":" + v.count());
            Axis a = VarySpec.parse(name + "=" + body, parameters);
            // A random sweep draws anywhere in the range unless the parameter counts something.
            axes.add(draw && a.kind() == Axis.Kind.INTEGERS && !whole(l.parameter()) ? Axis.continuous(name, a.lo(), a.hi()) : a);
        }
        if (axes.isEmpty()) {
            throw new SweepException(ToolMsg.SWEEP_NOTHING_TO_VARY.text());
        }
        Double s = Numbers.parsePlain(seed.getText());
        if (s == null || s != Math.rint(s) || Math.abs(s) > 1e15) {
            throw new SweepException(ToolMsg.SWEEP_BAD_SEED.text(seed.getText().trim()));
        }
        SweepSpec spec = draw ? SweepSpec.random(axes, count.getSelection(), repeat.getSelection(), s.longValue())
                : SweepSpec.grid(axes, repeat.getSelection(), s.longValue());
        spec.check();
        return spec;
    }

    /**
     * The values the parameters that are not varied are held at, as {@code --param NAME=VALUE}
     * gives them; a box that is not a number throws with one line naming the parameter.
     */
    Map<String, Double> held() throws SweepException {
        Map<String, Double> out = new LinkedHashMap<>();
        for (Line l : byName.values()) {
            if (l.vary().getSelection()) {
                continue;
            }
            Double v = Numbers.parsePlain(l.hold().getText());
            if (v == null || !Double.isFinite(v)) {
                throw new SweepException(ToolMsg.SWEEP_BAD_HOLD.text(l.parameter().name(), l.hold().getText().trim()));
            }
            if (v != l.parameter().value()) {
                out.put(l.parameter().name(), v);
            }
        }
        return out;
    }

    /** Whether {@code p} counts something: its default and bounds are whole numbers. */
    private static boolean whole(Parameter p) {
        return p.value() == Math.rint(p.value()) && p.min() != null && p.min() == Math.rint(p.min())
                && p.max() != null && p.max() == Math.rint(p.max());
    }
}
