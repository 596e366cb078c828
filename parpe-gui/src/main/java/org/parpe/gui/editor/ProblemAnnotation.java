package org.parpe.gui.editor;

import org.eclipse.jface.text.source.Annotation;
import org.eclipse.jface.text.source.IAnnotationPresentation;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Canvas;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;

/** An error or warning marker in the editor: a squiggle in the text and a badge in the ruler. */
public final class ProblemAnnotation extends Annotation implements IAnnotationPresentation {
    /** Annotation type of errors. */
    public static final String ERROR = "org.parpe.gui.error";
    /** Annotation type of warnings. */
    public static final String WARNING = "org.parpe.gui.warning";

    static final Color ERROR_COLOR = new Color(0xD0, 0x21, 0x21);
    static final Color WARNING_COLOR = new Color(0xE0, 0x9A, 0x10);

    private final Diagnostic diagnostic;

    ProblemAnnotation(Diagnostic d) {
        super(d.severity() == Severity.ERROR ? ERROR : WARNING, false, d.message());
        this.diagnostic = d;
    }

    /** The diagnostic shown. */
    public Diagnostic diagnostic() {
        return diagnostic;
    }

    /** Whether this is an error rather than a warning. */
    public boolean isError() {
        return diagnostic.severity() == Severity.ERROR;
    }

    @Override
    public int getLayer() {
        return isError() ? 2 : 1;
    }

    @Override
    public void paint(GC gc, Canvas canvas, Rectangle r) {
        int size = Math.min(Math.min(r.width, r.height), 14) - 2;
        int x = r.x + (r.width - size) / 2;
        int y = r.y + Math.max(0, (Math.min(r.height, 18) - size) / 2);
        int old = gc.getAntialias();
        gc.setAntialias(SWT.ON);
        gc.setBackground(isError() ? ERROR_COLOR : WARNING_COLOR);
        if (isError()) {
            gc.fillOval(x, y, size, size);
        } else {
            gc.fillPolygon(new int[] {x + size / 2, y, x + size, y + size, x, y + size});
        }
        gc.setForeground(canvas.getDisplay().getSystemColor(SWT.COLOR_WHITE));
        gc.setLineWidth(2);
        int cx = x + size / 2;
        gc.drawLine(cx, y + 3, cx, y + size - 5);
        gc.drawPoint(cx, y + size - 3);
        gc.setLineWidth(1);
        gc.setAntialias(old);
    }
}
