package org.parpe.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.parpe.core.sensor.Channel;
import org.parpe.core.sensor.SensorTable;
import org.parpe.sim.config.PartSpec;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RootPose;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.PartKind;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.snapshot.SimSnapshot;

/** Physical plausibility: free fall, energy, servo tracking, determinism. */
class PhysicsTest {

    @Test
    void aDroppedModuleFallsHalfGTSquared() {
        RobotConfig one = new RobotConfig("drop", List.of(PartSpec.segment("s0", 0, 0)), List.of(),
                new RootPose("s0", 0, 0, 0, 0, 0, 5.0));
        try (Simulator sim = SimTestSupport.started(one, 0.001)) {
            double z0 = sim.snapshot().centerOfMass().z();
            sim.step(600);
            double fallen = z0 - sim.snapshot().centerOfMass().z();
            double expected = 0.5 * 9.81 * 0.6 * 0.6;
            assertEquals(expected, fallen, 0.01 * expected, "fell " + fallen + " m in 0.6 s");
        }
    }

    @Test
    void aSwingingLimpChainKeepsBoundedEnergy() {
        RobotConfig chain = new RobotConfig("swing", List.of(PartSpec.segment("s0", 0, 0),
                PartSpec.segment("s1", 1, 60), PartSpec.segment("s2", 2, -45)),
                List.of(org.parpe.sim.config.Connection.of("s0", 1, "s1", 0, 0),
                        org.parpe.sim.config.Connection.of("s1", 1, "s2", 0, 0)),
                new RootPose("s0", 0, 0, 90, 0, 0, 30.0));
        try (Simulator sim = SimTestSupport.started(chain, 0.01)) {
            sim.setLimp(true);
            sim.step(1);
            double e0 = sim.energy();
            double max = e0;
            for (int i = 0; i < 150; i++) {
                sim.step(1);
                max = Math.max(max, sim.energy());
            }
            double scale = sim.totalMass() * 9.81 * 0.2;
            assertTrue(max - e0 < 0.02 * scale, "energy grew from " + e0 + " to " + max + " J");
            assertFalse(sim.hasNaN());
        }
    }

    @Test
    void servoTracksTheCommandAndPositiveLiftsTheNextModule() {
        try (Simulator sim = SimTestSupport.started(SimTestSupport.config("snake:n=3"), 0.01)) {
            SimTestSupport.hold(sim, new double[] {0, 30, 0}, 100);
            SimSnapshot s = sim.snapshot();
            assertEquals(30, s.angle(1), 1.0);
            Mat3 base = SimTestSupport.piece(s, "s1", PartKind.SEGMENT_BASE).rotation();
            Mat3 arm = SimTestSupport.piece(s, "s1", PartKind.SEGMENT_ARM).rotation();
            Vec3 xb = base.axis(0);
            Vec3 xa = arm.axis(0);
            Vec3 zb = base.axis(2);
            double sin = (xb.y() * xa.z() - xb.z() * xa.y()) * zb.x() + (xb.z() * xa.x() - xb.x() * xa.z()) * zb.y()
                    + (xb.x() * xa.y() - xb.y() * xa.x()) * zb.z();
            assertEquals(0.5, sin, 0.02, "the arm turns about +z of the base");
        }
    }

    @Test
    void servoSpeedIsLimited() {
        try (Simulator sim = SimTestSupport.started(SimTestSupport.config("snake:n=2"), 0.01)) {
            SimTestSupport.hold(sim, new double[] {0, 90}, 10);
            double after = sim.snapshot().angle(1);
            assertTrue(after < 0.1 * 300 + 3 && after > 15, "turned " + after + " degrees in 0.1 s at 300 deg/s");
        }
    }

    @Test
    void identicalInputsGiveIdenticalMotion() {
        double[] a = run();
        double[] b = run();
        assertEquals(a.length, b.length);
        for (int i = 0; i < a.length; i++) {
            assertEquals(Double.doubleToLongBits(a[i]), Double.doubleToLongBits(b[i]), "value " + i);
        }
    }

    private static double[] run() {
        try (Simulator sim = SimTestSupport.started(SimTestSupport.config("snake:n=6,axes=alternate"), 0.01)) {
            double[] cmd = new double[6];
            for (int k = 0; k < 300; k++) {
                for (int m = 0; m < 6; m++) {
                    cmd[m] = 40 * Math.sin(2 * Math.PI * (k * 0.01 - m * 0.2));
                }
                sim.accept(k, k * 0.01, cmd);
            }
            SensorTable t = sim.readings();
            SimSnapshot s = sim.snapshot();
            return new double[] {s.centerOfMass().x(), s.centerOfMass().y(), s.centerOfMass().z(),
                t.get(3, Channel.ANGLE), t.get(5, Channel.ACCEL_X), s.bodies().get(7).position().x()};
        }
    }
}
