package org.parpe.gui.help;

import java.nio.file.Path;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.ScrolledComposite;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.layout.FillLayout;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Shell;

/**
 * A lesson's picture at its full size, in a window of its own that scrolls where the screen is
 * smaller: in the tutorial's column a screenshot of the IDE is scaled down past reading.
 */
final class PictureWindow {
    private PictureWindow() {
    }

    /** Opens {@code file} at full size beside {@code parent}; null if it cannot be read. */
    static Shell open(Shell parent, Path file) {
        Image img;
        try {
            img = new Image(parent.getDisplay(), file.toString());
        } catch (org.eclipse.swt.SWTException e) {
            return null;
        }
        Shell shell = new Shell(parent, SWT.SHELL_TRIM);
        shell.setText(file.getFileName().toString());
        shell.setLayout(new FillLayout());
        shell.addListener(SWT.Dispose, e -> img.dispose());
        ScrolledComposite scroll = new ScrolledComposite(shell, SWT.H_SCROLL | SWT.V_SCROLL);
        Label picture = new Label(scroll, SWT.NONE);
        picture.setImage(img);
        picture.setSize(picture.computeSize(SWT.DEFAULT, SWT.DEFAULT));
        scroll.setContent(picture);
        Rectangle area = parent.getMonitor().getClientArea();
        Rectangle size = shell.computeTrim(0, 0, img.getBounds().width, img.getBounds().height);
        int w = Math.min(size.width, area.width);
        int h = Math.min(size.height, area.height);
        shell.setBounds(area.x + (area.width - w) / 2, area.y + (area.height - h) / 2, w, h);
        shell.open();
        return shell;
    }
}
