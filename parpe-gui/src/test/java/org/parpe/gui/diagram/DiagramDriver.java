package org.parpe.gui.diagram;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Text;
import org.parpe.core.diag.SourcePos;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;
import org.parpe.gui.diagram.Projection.View;

/**
 * Works the Diagram pane of an open IDE as a user does: shows a view, clicks and drags on the
 * canvas with mouse events, types into the edit row's fields and presses its buttons. Nothing
 * here types into the text editor.
 */
final class DiagramDriver {
    private final IdeWindow ide;

    DiagramDriver(IdeWindow ide) {
        this.ide = ide;
    }

    /** Opens the IDE at 1366×768 with its settings in a new folder named from {@code prefix}, never asking to save. */
    static DiagramDriver open(String prefix) throws java.io.IOException {
        IdeWindow ide = IdeAccess.openIde(java.nio.file.Files.createTempDirectory(prefix));
        IdeAccess.shell(ide).setSize(1366, 768);
        IdeAccess.dontSave(ide);
        return new DiagramDriver(ide);
    }

    IdeWindow ide() {
        return ide;
    }

    DiagramPane pane() {
        return IdeAccess.diagram(ide);
    }

    String text() {
        return IdeAccess.editor(ide).document().get();
    }

    /** Brings the Diagram tab to the front and waits for its first drawing. */
    void front() {
        assertEquals("Diagram", pane().showTab());
        IdeAccess.pump(() -> pane().current(), "the diagram of the text");
    }

    /** Shows view {@code v} on {@code subject} (null: the default one) and waits until it shows the text. */
    void show(View v, String subject) {
        DiagramWindow.show(ide, v, subject);
    }

    /** Waits until the diagram shows the text as it is now. */
    void caughtUp() {
        IdeAccess.pump(() -> pane().current(), "the diagram of the edited text");
    }

    /** A left-button mouse event of {@code type} at {@code at} on the canvas. */
    void mouse(int type, Point at) {
        Event e = new Event();
        e.button = 1;
        e.x = at.x;
        e.y = at.y;
        pane().canvas().notifyListeners(type, e);
    }

    /** Clicks where {@code node} is drawn. */
    void click(SourcePos node) {
        Point p = pane().where(node);
        assertNotNull(p, node + " is not drawn");
        mouse(SWT.MouseDown, p);
        mouse(SWT.MouseUp, p);
    }

    /** Clicks on no node: the edit row shows the view's own subject. */
    void clickAside() {
        mouse(SWT.MouseDown, new Point(0, 0));
        mouse(SWT.MouseUp, new Point(0, 0));
        assertEquals(null, pane().selected(), "a click on no node selects none");
    }

    /** Drags with the left button from where {@code from} is drawn to where {@code to} is. */
    void drag(SourcePos from, SourcePos to) {
        Point a = pane().where(from);
        Point b = pane().where(to);
        mouse(SWT.MouseDown, a);
        mouse(SWT.MouseMove, new Point((a.x + b.x) / 2, (a.y + b.y) / 2));
        mouse(SWT.MouseMove, b);
        mouse(SWT.MouseUp, b);
    }

    /** The editable node whose element starts on the line that holds {@code needle}. */
    SourcePos node(String needle) {
        int line = lineOf(needle);
        return pane().shown().targets().keySet().stream().filter(p -> p.line() == line).findFirst()
                .orElseThrow(() -> new AssertionError("no editable node on line " + line + " (" + needle + ") in " + pane().shown().view() + " " + pane().shown().subject() + ": " + pane().shown().targets().keySet()));
    }

    int lineOf(String needle) {
        String[] lines = text().split("\n", -1);
        for (int i = 0; i < lines.length; i++) {
            if (lines[i].contains(needle)) {
                return i + 1;
            }
        }
        throw new AssertionError("no line holds " + needle);
    }

    /** Types {@code value} into field {@code name} of the edit row (a form, not the script) and presses Enter. */
    void type(String name, String value) {
        enter(pane(), name, value);
        caughtUp();
    }

    /** Types {@code value} into field or chooser {@code name} of {@code pane}'s edit row and presses Enter. */
    static void enter(DiagramPane pane, String name, String value) {
        Control field = input(pane, name);
        set(field, value);
        field.notifyListeners(SWT.DefaultSelection, new Event());
    }

    /** Field or chooser {@code name} of {@code pane}'s edit row. */
    static Control input(DiagramPane pane, String name) {
        Control c = pane.fields().containsKey(name) ? pane.fields().get(name) : pane.choosers().get(name);
        assertNotNull(c, "no field '" + name + "'; fields: " + pane.fields().keySet() + ", choosers: " + pane.choosers().keySet());
        return c;
    }

    /** Types {@code value} into a field or a chooser (a form, not the script). */
    static void set(Control input, String value) {
        if (input instanceof Combo c) {
            c.setText(value);
        } else {
            ((Text) input).setText(value);
        }
    }

    /** Clicks the bar of the lanes drawn for the instance written on the line holding {@code needle}, and fills its fields. */
    void bar(String needle, String... fields) {
        click(node(needle));
        for (int i = 0; i < fields.length; i += 2) {
            type(fields[i], fields[i + 1]);
            if (i + 2 < fields.length) {
                click(node(needle));
            }
        }
    }

    /** Fills the inputs {@code name=value} pairs of the edit row and presses button {@code action}. */
    void press(String action, String... inputs) {
        for (int i = 0; i < inputs.length; i += 2) {
            set(input(pane(), inputs[i]), inputs[i + 1]);
        }
        Button b = pane().actions().get(action);
        assertNotNull(b, "no button '" + action + "'; buttons: " + pane().actions().keySet() + " (" + pane().message() + ")");
        b.notifyListeners(SWT.Selection, new Event());
        caughtUp();
    }
}
