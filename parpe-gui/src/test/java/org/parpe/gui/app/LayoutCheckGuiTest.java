package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableColumn;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.parpe.core.text.Pseudo;

/** The layout checker finds what it is for, and only that (real widgets under Xvfb). */
class LayoutCheckGuiTest {
    private Shell shell;

    @BeforeEach
    void open() {
        shell = new Shell(Gui.display(), SWT.SHELL_TRIM);
        shell.setText("check");
        shell.setLayout(new GridLayout(1, false));
    }

    @AfterEach
    void close() {
        shell.dispose();
    }

    private List<String> problems() {
        shell.setSize(500, 400);
        shell.open();
        shell.layout(true, true);
        Gui.settle();
        return LayoutCheck.problems(shell);
    }

    @Test
    void aLayoutThatGrowsWithItsTextsHasNoProblem() {
        new Label(shell, SWT.NONE).setText("Speed");
        new Button(shell, SWT.PUSH).setText("Open file\u2026");
        Label wrapped = new Label(shell, SWT.WRAP);
        wrapped.setText("A long explanation that wraps at the width of the window it is shown in, as a paragraph does.");
        wrapped.setLayoutData(new GridData(SWT.FILL, SWT.TOP, true, false));
        assertEquals(List.of(), problems());
    }

    @Test
    void aLabelSizedForItsEnglishTextClipsThePseudoText() {
        Label l = new Label(shell, SWT.NONE);
        l.setText("Open file\u2026");
        GridData d = new GridData();
        d.widthHint = l.computeSize(SWT.DEFAULT, SWT.DEFAULT).x; // the English text's width, fixed
        l.setLayoutData(d);
        assertEquals(List.of(), problems());
        l.setText(Pseudo.text("Open file\u2026"));
        shell.layout(true, true);
        List<String> found = LayoutCheck.problems(shell);
        assertEquals(1, found.size(), found.toString());
        assertTrue(found.get(0).startsWith("clipped: Shell 'check' / Label#0 '[\u00d6\u00fe\u00e9\u00f1 f\u00ee\u0142\u00e9\u2026 ~~~]' needs "),
                found.get(0));
    }

    @Test
    void overlappingSiblingsAChildPastItsParentAndANarrowHeaderAreFound() {
        Composite free = new Composite(shell, SWT.NONE);
        free.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        Button a = new Button(free, SWT.PUSH);
        a.setText("Run");
        a.setBounds(0, 0, 120, 40);
        Button b = new Button(free, SWT.PUSH);
        b.setText("Stop");
        b.setBounds(60, 10, 120, 40);
        Button far = new Button(free, SWT.PUSH);
        far.setText("Far");
        far.setBounds(2000, 0, 80, 40);
        Table t = new Table(shell, SWT.BORDER);
        t.setHeaderVisible(true);
        TableColumn c = new TableColumn(t, SWT.NONE);
        c.setText("Angle of the joint");
        c.setWidth(30);
        List<String> found = problems();
        assertEquals(3, found.size(), String.join("\n", found));
        assertTrue(found.get(0).startsWith("overlaps: Shell 'check' / Composite#0 / Button#1 'Stop' "), found.get(0));
        assertTrue(found.get(0).contains("covers Button 'Run'"), found.get(0));
        assertTrue(found.get(1).startsWith("cut off by its parent: Shell 'check' / Composite#0 / Button#2 'Far' "), found.get(1));
        assertTrue(found.get(2).startsWith("clipped header: Shell 'check' / Table#1 column 'Angle of the joint' needs "), found.get(2));
    }
}
