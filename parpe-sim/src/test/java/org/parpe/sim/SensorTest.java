package org.parpe.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.parpe.core.sensor.Channel;
import org.parpe.core.sensor.SensorTable;
import org.parpe.sim.config.PartSpec;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RootPose;

/** The sensors of PARSL.md §10 as the simulator measures them. */
class SensorTest {

    private static RobotConfig lying(double roll) {
        return new RobotConfig("one", java.util.List.of(PartSpec.segment("s0", 0, 0)), java.util.List.of(),
                new RootPose("s0", 0, 0, roll, 0, 0));
    }

    @Test
    void accelReadsMinus100OnTheAxisPointingUp() {
        // roll 90: body y points up, so y·ĝ = −1; x and z are horizontal
        try (Simulator sim = SimTestSupport.started(lying(90), 0.01)) {
            sim.step(50);
            SensorTable t = sim.readings();
            assertEquals(-100, t.get(0, Channel.ACCEL_Y), 1.0);
            assertEquals(0, t.get(0, Channel.ACCEL_X), 1.0);
            assertEquals(0, t.get(0, Channel.ACCEL_Z), 1.0);
        }
    }

    @Test
    void accelReadsPlus100OnTheAxisPointingDown() {
        // roll 180: body z points down
        try (Simulator sim = SimTestSupport.started(lying(180), 0.01)) {
            sim.step(50);
            assertEquals(100, sim.readings().get(0, Channel.ACCEL_Z), 1.0);
        }
    }

    @Test
    void touchSwitchesOnForTheSideOnTheGround() {
        // roll 90: +y (left) up, −y (right) on the ground; roll −90: the other way round
        try (Simulator sim = SimTestSupport.started(lying(90), 0.01)) {
            sim.step(30);
            SensorTable t = sim.readings();
            assertEquals(0, t.get(0, Channel.TOUCH_LEFT));
            assertEquals(1, t.get(0, Channel.TOUCH_RIGHT));
        }
        try (Simulator sim = SimTestSupport.started(lying(-90), 0.01)) {
            sim.step(30);
            SensorTable t = sim.readings();
            assertEquals(1, t.get(0, Channel.TOUCH_LEFT));
            assertEquals(0, t.get(0, Channel.TOUCH_RIGHT));
        }
    }

    @Test
    void touchIsOffInTheAir() {
        RobotConfig high = new RobotConfig("air", java.util.List.of(PartSpec.segment("s0", 0, 0)), java.util.List.of(),
                new RootPose("s0", 0, 0, 90, 0, 0, 2.0));
        try (Simulator sim = SimTestSupport.started(high, 0.01)) {
            sim.step(5);
            SensorTable t = sim.readings();
            assertEquals(0, t.get(0, Channel.TOUCH_LEFT) + t.get(0, Channel.TOUCH_RIGHT));
        }
    }
}
