package org.parpe.gui.diagram;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.parpe.core.diagram.Scene;
import org.parpe.gui.run.LiveStates;

/**
 * Where each module is within its state on the ring: a dot per module just outside the ring, on
 * its state's arc as far along as the module is through the state (the engine's
 * {@code Engine.moduleProgress}). Part of the live overlay of the ring.
 */
final class RingProgress {
    private static final int DOT = 0x222222;

    private RingProgress() {
    }

    /**
     * The dots for frame {@code f} on the ring whose shapes {@code index} has. {@code shown} gets,
     * per module, the progress drawn, or −1 for a module not in a state of this ring.
     */
    static List<Scene.Shape> marks(ShapeIndex index, LiveStates.Frame f, double[] shown) {
        Arrays.fill(shown, -1);
        List<Scene.Shape> marks = new ArrayList<>();
        for (int m = 0; m < f.instance().length && m < shown.length; m++) {
            Scene.Sector c = index.arc(f.state()[m]);
            if (!index.plays(f.entry(), f.instance()[m]) || c == null || f.progress()[m] < 0) {
                continue;
            }
            shown[m] = f.progress()[m];
            double at = c.from() + Math.min(1, shown[m]) * (c.to() - c.from());
            double[] p = Scene.onCircle(c.cx(), c.cy(), c.r1() + 6, at);
            marks.add(new Scene.Sector(p[0], p[1], 0, 3, 0, 1, DOT, Scene.NONE, null));
        }
        return marks;
    }
}
