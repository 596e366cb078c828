package org.parpe.gui.view3d;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Issue 23, item 5: a missed drag orbited to a ground-level view, and Reset view / double-click
 * did not restore the angle.
 */
class CameraTest {
    @Test
    void aDragCannotReachGroundLevelAndResetRestoresTheAngle() {
        Camera c = new Camera();
        c.rotate(2.0, -10);
        assertTrue(c.pitch >= Math.toRadians(10) - 1e-12, "pitch " + Math.toDegrees(c.pitch) + "° is almost ground level");
        c.resetAngles();
        assertEquals(Camera.HOME_YAW, c.yaw);
        assertEquals(Camera.HOME_PITCH, c.pitch);
    }
}
