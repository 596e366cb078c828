package org.parpe.gui.diagram;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Scale;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.diagram.Ring;
import org.parpe.core.diagram.Scene;
import org.parpe.core.model.Program;
import org.parpe.core.run.Breakpoints;
import org.parpe.gui.text.PanelMsg;

/**
 * The Diagram pane's row for runs: breakpoints on the selected state of the ring (on entering
 * it, on its exit condition becoming true), Continue and what stopped the run, and a recorded
 * trace scrubbed with a slider through the same overlay as a live run. UI thread only.
 */
final class LiveBar {
    private static final int RED = 0xcc0000;

    private final DiagramPane pane;
    private final Composite row;
    private final Button onEnter;
    private final Button onExit;
    private final Button resume;
    private final Button openTrace;
    private final Scale slider;
    private final Label says;
    /** The whole line; {@link #says} shows as much of it as its two lines hold. */
    private String line = "";
    private Breakpoints breakpoints;
    private Runnable goOn = () -> { };
    private Runnable changed = () -> { };
    private Breakpoints.Hit shownHit;
    private TraceScrubber trace;

    LiveBar(Composite parent, DiagramPane pane) {
        this.pane = pane;
        row = new Composite(parent, SWT.NONE);
        // one row: the buttons, the slider while a trace is open, and the line beside them (issue 24)
        GridLayout gl = new GridLayout(6, false);
        gl.marginWidth = 0;
        gl.marginHeight = 0;
        gl.horizontalSpacing = 3;
        row.setLayout(gl);
        row.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        onEnter = button(PanelMsg.DIAGRAM_BREAK_ENTRY.text(), PanelMsg.DIAGRAM_BREAK_ENTRY_TIP.text());
        onEnter.addListener(SWT.Selection, e -> toggle(Breakpoints.Kind.ENTER));
        onExit = button(PanelMsg.DIAGRAM_BREAK_EXIT.text(), PanelMsg.DIAGRAM_BREAK_EXIT_TIP.text());
        onExit.addListener(SWT.Selection, e -> toggle(Breakpoints.Kind.EXIT));
        resume = button(PanelMsg.DIAGRAM_CONTINUE.text(), PanelMsg.DIAGRAM_CONTINUE_TIP.text());
        resume.addListener(SWT.Selection, e -> goOn.run());
        openTrace = button(PanelMsg.DIAGRAM_TRACE.text(), PanelMsg.DIAGRAM_TRACE_TIP.text());
        openTrace.addListener(SWT.Selection, e -> chooseTrace());
        slider = new Scale(row, SWT.HORIZONTAL);
        GridData sd = new GridData(SWT.LEFT, SWT.CENTER, false, false);
        sd.widthHint = 200;
        slider.setLayoutData(sd);
        slider.addListener(SWT.Selection, e -> scrubTo(slider.getSelection()));
        says = new Label(row, SWT.WRAP);
        // never narrower than a few words (a narrow tab wrapped it a syllable a line, issue 31), two lines
        // (a longer language's sentence wraps), the same height whatever it says: the drawing under it does
        // not move; what two lines cannot hold ends in "…" and the whole text is its tool tip (decisions.md,
        // "Layouts in the pseudo-language")
        GridData sd2 = new GridData(SWT.FILL, SWT.CENTER, true, false);
        sd2.minimumWidth = 100;
        sd2.widthHint = 160;
        sd2.heightHint = 2 * DiagramPane.lineHeight(says);
        says.setLayoutData(sd2);
        says.addListener(SWT.Resize, e -> fit());
        row.addListener(SWT.Resize, e -> columns());
        update();
        row.getDisplay().timerExec(100, new Runnable() {
            @Override
            public void run() {
                if (row.isDisposed()) {
                    return;
                }
                Breakpoints.Hit h = breakpoints == null ? null : breakpoints.hit();
                if (h != shownHit) {
                    shownHit = h;
                    update();
                    pane.repaintOverlay();
                    changed.run();
                }
                row.getDisplay().timerExec(100, this);
            }
        });
    }

    private Button button(String text, String tip) {
        Button b = new Button(row, SWT.PUSH);
        b.setText(text);
        b.setToolTipText(tip);
        return b;
    }

    /** The run's breakpoints, how to go on from one, and whom to tell when the run stops at one or goes on. */
    void breakpoints(Breakpoints bp, Runnable resume, Runnable onChange) {
        breakpoints = bp;
        goOn = resume;
        changed = onChange;
        update();
    }

    /** The ring arc selected, or {@code null}. */
    private Ring.Arc arc() {
        Projection p = pane.shown();
        SourcePos s = pane.selected();
        if (p == null || p.ring() == null || s == null) {
            return null;
        }
        for (Ring.Arc a : p.ring().arcs()) {
            if (s.equals(a.pos())) {
                return a;
            }
        }
        return null;
    }

    private void toggle(Breakpoints.Kind kind) {
        Ring.Arc a = arc();
        if (breakpoints == null || a == null) {
            return;
        }
        breakpoints.toggle(new Breakpoints.Point(pane.shown().ring().automaton(), a.index(), kind));
        update();
        pane.repaintOverlay();
    }

    /** The buttons and the line again, after a selection, a new view, a hit or a trace. */
    void update() {
        if (row.isDisposed()) {
            return;
        }
        Ring.Arc a = arc();
        String automaton = a == null ? null : pane.shown().ring().automaton();
        onEnter.setEnabled(breakpoints != null && a != null);
        onExit.setEnabled(breakpoints != null && a != null && a.exit() != null);
        onEnter.setText(a != null && breakpoints != null
                && breakpoints.has(new Breakpoints.Point(automaton, a.index(), Breakpoints.Kind.ENTER))
                ? PanelMsg.DIAGRAM_CLEAR_ENTRY.text() : PanelMsg.DIAGRAM_BREAK_ENTRY.text());
        onExit.setText(a != null && a.exit() != null && breakpoints != null
                && breakpoints.has(new Breakpoints.Point(automaton, a.index(), Breakpoints.Kind.EXIT))
                ? PanelMsg.DIAGRAM_CLEAR_EXIT.text() : PanelMsg.DIAGRAM_BREAK_EXIT.text());
        resume.setEnabled(shownHit != null);
        slider.setVisible(trace != null);
        ((GridData) slider.getLayoutData()).exclude = trace == null;
        if (shownHit != null) {
            tell(PanelMsg.DIAGRAM_PAUSED.text(hit(shownHit)));
        } else if (trace != null) {
            int k = slider.getSelection();
            String at = PanelMsg.DIAGRAM_TRACE_AT.text(trace.file().getFileName(), org.parpe.core.lang.Numbers.format(trace.time(k)), k,
                    trace.ticks() - 1);
            tell(Double.isNaN(trace.differsFrom()) ? at
                    : PanelMsg.DIAGRAM_TRACE_DIFFERS.text(at, org.parpe.core.lang.Numbers.format(trace.differsFrom())));
        } else {
            tell(a != null ? "" : PanelMsg.DIAGRAM_SELECT_STATE.text());
        }
        onEnter.pack();
        onExit.pack();
        pane.layoutAgain();
    }

    /** Which module reached which breakpoint, when (as {@code Breakpoints.Hit.describe()}, in the IDE's language). */
    private static String hit(Breakpoints.Hit h) {
        String t = org.parpe.core.lang.Numbers.format(Math.round(h.time() * 1e6) / 1e6);
        return (h.point().kind() == Breakpoints.Kind.ENTER ? PanelMsg.DIAGRAM_HIT_ENTER : PanelMsg.DIAGRAM_HIT_EXIT)
                .text(h.moduleId(), h.point().automaton() + "." + h.state(), h.tick(), t);
    }

    private void tell(String text) {
        line = text;
        says.setToolTipText(text.isEmpty() ? null : text);
        says.setText(text);
        pane.layoutAgain();
        fit();
    }

    /**
     * As many of the row's cells side by side as its width holds: all of them in one row where
     * there is room, else the buttons in fewer columns and the line under them across the row
     * (a tab beside the docked tutorial, a longer language), instead of buttons past the edge.
     */
    private void columns() {
        int width = row.getClientArea().width;
        List<Control> cells = new ArrayList<>();
        for (Control c : row.getChildren()) {
            if (c != says && !(c.getLayoutData() instanceof GridData g && g.exclude)) {
                cells.add(c);
            }
        }
        GridLayout gl = (GridLayout) row.getLayout();
        int n = cells.size() + 1;
        int lineWidth = ((GridData) says.getLayoutData()).minimumWidth;
        if (widths(cells, n - 1) + gl.horizontalSpacing + lineWidth > width) {
            n = cells.size();
            while (n > 1 && widths(cells, n) > width) {
                n--;
            }
        }
        GridData sd = (GridData) says.getLayoutData();
        int span = n > cells.size() ? 1 : n;
        if (gl.numColumns != n || sd.horizontalSpan != span) {
            gl.numColumns = n;
            sd.horizontalSpan = span;
            pane.layoutAgain();
        }
    }

    /** The width of {@code cells} in {@code n} columns, each as wide as its widest cell. */
    private int widths(List<Control> cells, int n) {
        int[] column = new int[n];
        for (int i = 0; i < cells.size(); i++) {
            GridData g = (GridData) cells.get(i).getLayoutData();
            int w = g != null && g.widthHint != SWT.DEFAULT ? g.widthHint : cells.get(i).computeSize(SWT.DEFAULT, SWT.DEFAULT).x;
            column[i % n] = Math.max(column[i % n], w);
        }
        int sum = (n - 1) * ((GridLayout) row.getLayout()).horizontalSpacing;
        for (int w : column) {
            sum += w;
        }
        return sum;
    }

    /** Shows as much of the line as the label's two lines hold at its width: the rest elided with "…". */
    private void fit() {
        int width = says.getSize().x;
        int room = says.getSize().y;
        says.setText(line);
        if (width <= 0 || room <= 0 || says.computeSize(width, SWT.DEFAULT).y <= room) {
            return;
        }
        int fits = 0;
        int over = line.length();
        while (over - fits > 1) { // the longest start of the line that fits with "…" after it
            int mid = (fits + over) / 2;
            says.setText(elided(mid));
            if (says.computeSize(width, SWT.DEFAULT).y <= room) {
                fits = mid;
            } else {
                over = mid;
            }
        }
        says.setText(elided(fits));
    }

    /** The first {@code n} characters of the line (a character whole) and "…". */
    private String elided(int n) {
        int end = n > 0 && Character.isHighSurrogate(line.charAt(n - 1)) ? n - 1 : n;
        return line.substring(0, end).stripTrailing() + "\u2026";
    }

    /** A new drawing is shown: the buttons for its selection, and the trace's frame on it. */
    void shown() {
        update();
        if (trace != null) {
            pane.showFrame(trace.frame(slider.getSelection()), PanelMsg.DIAGRAM_TRACE_WORD.text());
        } else {
            pane.repaintOverlay();
        }
    }

    /** The whole line (what the label shows may end elided): the breakpoint the run is paused at, the trace's time, or a hint. */
    String line() {
        return line;
    }

    /** Whether a trace is being scrubbed (the overlay shows it, not the run). */
    boolean scrubbing() {
        return trace != null;
    }

    private void chooseTrace() {
        if (trace != null) {
            stopScrubbing();
            return;
        }
        Path chosen = org.parpe.gui.panels.FileDialogs.ask(row.getShell(), SWT.OPEN,
                PanelMsg.DIAGRAM_OPEN_TRACE_TITLE.text(), "*.csv", null, null);
        if (chosen != null) {
            scrub(chosen);
        }
    }

    /** Opens {@code csv} for scrubbing; a trace that cannot be used is told on the line. */
    void scrub(Path csv) {
        Program p = pane.program();
        if (p == null) {
            tell(PanelMsg.DIAGRAM_TRACE_NEEDS_SCRIPT.text());
            return;
        }
        try {
            trace = TraceScrubber.load(p, csv);
        } catch (java.io.IOException e) {
            tell(PanelMsg.DIAGRAM_CANNOT_READ.text(csv, org.parpe.core.io.IoReasons.of(e)));
            return;
        } catch (IllegalArgumentException e) {
            tell(e.getMessage());
            return;
        }
        slider.setMinimum(0);
        slider.setMaximum(Math.max(1, trace.ticks() - 1));
        slider.setPageIncrement(Math.max(1, trace.ticks() / 20));
        slider.setSelection(0);
        openTrace.setText(PanelMsg.DIAGRAM_CLOSE_TRACE.text());
        update();
        scrubTo(0);
    }

    /** Shows tick {@code k} of the trace. */
    void scrubTo(int k) {
        if (trace == null) {
            return;
        }
        int t = Math.max(0, Math.min(trace.ticks() - 1, k));
        slider.setSelection(t);
        update();
        pane.showFrame(trace.frame(t), PanelMsg.DIAGRAM_TRACE_WORD.text());
    }

    private void stopScrubbing() {
        trace = null;
        openTrace.setText(PanelMsg.DIAGRAM_TRACE.text());
        update();
        pane.showFrame(null, null);
    }

    /** The breakpoints drawn on ring {@code r}, its arcs as {@code index} has them: a red dot at each state's start, a red ring while it is hit. */
    List<Scene.Shape> marks(Ring r, ShapeIndex index) {
        List<Scene.Shape> marks = new ArrayList<>();
        if (breakpoints == null || r == null) {
            return marks;
        }
        for (Ring.Arc a : r.arcs()) {
            Scene.Sector c = index.arc(a.index());
            if (c == null) {
                continue;
            }
            for (Breakpoints.Kind kind : Breakpoints.Kind.values()) {
                Breakpoints.Point pt = new Breakpoints.Point(r.automaton(), a.index(), kind);
                if (breakpoints.has(pt)) {
                    // entering: at the arc's start; exit: at its end, where the edge leaves it
                    double[] at = Scene.onCircle(c.cx(), c.cy(), c.r1() + 18, kind == Breakpoints.Kind.ENTER
                            ? c.from() + 0.01 : c.to() - 0.01);
                    marks.add(new Scene.Sector(at[0], at[1], 0, 7, 0, 1, RED, 0xffffff, null));
                }
                if (shownHit != null && shownHit.point().equals(pt)) {
                    marks.add(new Scene.Sector(c.cx(), c.cy(), c.r1() + 10, c.r1() + 13, c.from(), c.to(), RED,
                            Scene.NONE, null));
                }
            }
        }
        return marks;
    }
}
