package org.parpe.gui.view3d;

import org.eclipse.swt.graphics.GC;
import org.parpe.sim.snapshot.SimBody;

/**
 * What a builder (the Robot tab) adds to a {@link View3D}: it draws over each frame, picks on
 * clicks, paints pieces in its own colours and shows pieces not yet placed translucent.
 */
public interface BuildLayer {
    /**
     * A left click ({@code twice}: a double click) at (x, y) with the modifier keys
     * {@code stateMask}; true when it was taken (a double click then does not reset the view).
     */
    boolean clicked(int x, int y, int stateMask, boolean twice);

    /** The colour (0xRRGGBB) to paint {@code body} in, or −1 for its usual colour. */
    int colour(SimBody body);

    /** Pieces drawn translucent over the robot (a part previewed before it is placed). */
    java.util.List<SimBody> ghosts();

    /** Draws over the frame (after the robot), with {@link View3D#project} for world points. */
    void decorate(GC gc);
}
