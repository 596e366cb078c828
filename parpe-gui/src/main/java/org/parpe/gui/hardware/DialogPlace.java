package org.parpe.gui.hardware;

import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.graphics.Rectangle;

/**
 * Where the hardware dialog goes: over the IDE window, never at the screen's corner over the
 * menu, and where it covers as little as possible of the bottom panels (the Pose panel and its
 * Capture button, used while the dialog stays open): of the window's four corners and its top
 * centre, inside the screen, the place that overlaps them least.
 */
final class DialogPlace {
    private DialogPlace() {
    }

    /** The dialog's bounds, {@code size} big, over {@code owner} on {@code screen}, overlapping {@code avoid} least. */
    static Rectangle over(Rectangle owner, Rectangle screen, Point size, Rectangle avoid) {
        int top = owner.y + Math.max(40, owner.height / 12);
        int[][] candidates = {
            {owner.x + (owner.width - size.x) / 2, top},
            {owner.x + owner.width - size.x - 20, top},
            {owner.x + 20, top},
            {owner.x + owner.width - size.x - 20, owner.y + owner.height - size.y - 20},
            {owner.x + 20, owner.y + owner.height - size.y - 20}};
        Rectangle best = null;
        long bestOverlap = Long.MAX_VALUE;
        for (int[] c : candidates) {
            int x = Math.max(screen.x, Math.min(c[0], screen.x + screen.width - size.x));
            int y = Math.max(screen.y, Math.min(c[1], screen.y + screen.height - size.y));
            Rectangle r = new Rectangle(x, y, size.x, size.y);
            Rectangle i = r.intersection(avoid);
            long overlap = (long) Math.max(0, i.width) * Math.max(0, i.height);
            if (overlap < bestOverlap) {
                best = r;
                bestOverlap = overlap;
            }
        }
        return best;
    }
}
