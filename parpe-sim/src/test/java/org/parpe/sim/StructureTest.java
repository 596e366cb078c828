package org.parpe.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.parpe.sim.geom.PartKind;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.snapshot.SimBody;
import org.parpe.sim.snapshot.SimSnapshot;

/** Generated structures, closed loops and collisions between modules. */
class StructureTest {

    @Test
    void generatorsBuildThePapersRobots() {
        assertEquals(55, SimTestSupport.config("centipede").moduleIds().length);
        assertEquals(14, SimTestSupport.config("centipede").parts().stream()
                .filter(p -> p.type() == org.parpe.sim.config.PartType.FOOT).count());
        assertEquals(15, SimTestSupport.config("humanoid").moduleIds().length);
        assertEquals(8, SimTestSupport.config("wheel").moduleIds().length);
        assertEquals(12, SimTestSupport.config("snake:n=12").moduleIds().length);
    }

    @Test
    void aClosedLoopStaysClosedWhileItMoves() {
        try (Simulator sim = SimTestSupport.started(SimTestSupport.config("loop:n=8"), 0.01)) {
            double[] cmd = new double[8];
            for (int k = 0; k < 400; k++) {
                for (int m = 0; m < 8; m++) {
                    cmd[m] = 45 + 15 * Math.sin(2 * Math.PI * (k * 0.01 - m / 8.0));
                }
                sim.accept(k, k * 0.01, cmd);
            }
            SimSnapshot s = sim.snapshot();
            Vec3 last = SimTestSupport.piece(s, "s7", PartKind.SEGMENT_ARM).position();
            Vec3 first = SimTestSupport.piece(s, "s0", PartKind.SEGMENT_BASE).position();
            double gap = Math.hypot(Math.hypot(last.x() - first.x(), last.y() - first.y()), last.z() - first.z());
            // the halves bolted plate to plate close the loop: their centres stay 2 × 13 mm apart
            assertEquals(0.026, gap, 0.001, "loop closure");
            double sum = s.measuredAngles().values().stream().mapToDouble(Double::doubleValue).sum();
            assertEquals(360, sum, 3, "a closed planar loop turns through 360 degrees: " + s.measuredAngles());
            assertFalse(sim.hasNaN());
        }
    }

    @Test
    void modulesCollideWithEachOther() {
        // a pitch snake curling every joint to +90 would fold through itself without collisions
        try (Simulator sim = SimTestSupport.started(SimTestSupport.config("snake:n=6"), 0.01)) {
            double[] cmd = {90, 90, 90, 90, 90, 90};
            boolean selfContact = false;
            for (int k = 0; k < 300; k++) {
                sim.accept(k, k * 0.01, cmd);
                selfContact |= sim.snapshot().contacts().stream().anyMatch(c -> !c.withGround());
            }
            assertTrue(selfContact, "no module-module contact while curling");
            SimSnapshot s = sim.snapshot();
            for (SimBody a : s.bodies()) {
                for (SimBody b : s.bodies()) {
                    if (a != b && !a.part().equals(b.part())) {
                        double d = Math.hypot(Math.hypot(a.position().x() - b.position().x(),
                                a.position().y() - b.position().y()), a.position().z() - b.position().z());
                        assertTrue(d > 0.012, a.part() + " and " + b.part() + " overlap: " + d);
                    }
                }
            }
        }
    }

    @Test
    void limpModulesAreReportedAndHoldingResumes() {
        try (Simulator sim = SimTestSupport.started(SimTestSupport.config("snake:n=3"), 0.01)) {
            sim.setLimp(1, true);
            sim.step(1);
            assertEquals(java.util.Set.of(1), sim.snapshot().limpModules());
            sim.setLimp(false);
            sim.step(1);
            assertTrue(sim.snapshot().limpModules().isEmpty());
        }
    }
}
