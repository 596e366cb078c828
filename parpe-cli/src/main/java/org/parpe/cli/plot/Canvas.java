package org.parpe.cli.plot;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;

/**
 * A white image to draw a plot on, and the graphics to draw with, anti-aliased (lines and text),
 * for every PNG the command line writes (traces, sweeps, convergence). Dispose of the graphics
 * when done.
 */
public record Canvas(BufferedImage image, Graphics2D graphics) {

    /** A white {@code width} × {@code height} canvas. */
    public static Canvas white(int width, int height) {
        System.setProperty("java.awt.headless", "true");
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, width, height);
        return new Canvas(img, g);
    }
}
