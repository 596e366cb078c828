package org.parpe.gui.automation;

import org.parpe.gui.text.UiMsg;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.graphics.ImageData;
import org.eclipse.swt.graphics.ImageLoader;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Shell;
import org.parpe.core.io.AtomicFiles;

/** Saves a PNG picture of a window, as the screen shows it. */
public final class Screenshot {
    private Screenshot() {
    }

    /**
     * Captures {@code shell} into {@code file}.
     *
     * @throws IOException with a message if the picture cannot be taken or written
     */
    public static void save(Shell shell, Path file) throws IOException {
        Display display = shell.getDisplay();
        shell.forceActive();
        while (display.readAndDispatch()) {
            // Let every pending paint happen before the capture.
        }
        display.update();
        Rectangle b = shell.getBounds().intersection(display.getBounds());
        Image image = new Image(display, b.width, b.height);
        try {
            GC gc = new GC(display);
            try {
                gc.copyArea(image, b.x, b.y);
            } finally {
                gc.dispose();
            }
            if (isBlank(image.getImageData())) {
                GC pg = new GC(image);
                try {
                    shell.print(pg);
                } finally {
                    pg.dispose();
                }
            }
            write(image.getImageData(), file);
        } catch (org.eclipse.swt.SWTException e) {
            throw new IOException(UiMsg.SCREENSHOT_CANNOT_CAPTURE.text(e.getMessage()), e);
        } finally {
            image.dispose();
        }
    }

    /** Writes {@code data} as a PNG to {@code file} (a picture drawn off screen, such as the 3D view's). */
    public static void write(ImageData data, Path file) throws IOException {
        Path abs = file.toAbsolutePath();
        if (abs.getParent() != null) {
            Files.createDirectories(abs.getParent());
        }
        ImageLoader loader = new ImageLoader();
        loader.data = new ImageData[] {data};
        try {
            AtomicFiles.write(abs, out -> loader.save(out, SWT.IMAGE_PNG)); // the output rules: whole or not at all
        } catch (org.eclipse.swt.SWTException e) {
            throw new IOException(UiMsg.SCREENSHOT_CANNOT_WRITE.text(abs, e.getMessage()), e);
        }
    }

    /** Whether a picture is one colour only (nothing was captured). */
    public static boolean isBlank(ImageData d) {
        return distinctColours(d, 2) < 2;
    }

    /** The number of distinct pixel values in a sample grid of {@code d}, counting up to {@code limit}. */
    public static int distinctColours(ImageData d, int limit) {
        java.util.Set<Integer> seen = new java.util.HashSet<>();
        int stepX = Math.max(1, d.width / 97);
        int stepY = Math.max(1, d.height / 89);
        for (int y = 0; y < d.height; y += stepY) {
            for (int x = 0; x < d.width; x += stepX) {
                seen.add(d.getPixel(x, y));
                if (seen.size() >= limit) {
                    return seen.size();
                }
            }
        }
        return seen.size();
    }
}
