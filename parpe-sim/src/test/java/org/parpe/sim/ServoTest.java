package org.parpe.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.run.RunInfo;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RobotConfigs;

class ServoTest {

    static RobotConfig config(String spec) {
        DiagnosticList d = new DiagnosticList();
        RobotConfig c = RobotConfigs.resolve(spec, new int[0], d);
        assertTrue(c != null, d.all().toString());
        return c;
    }

    @Test
    void positiveAngleLiftsTheNextModuleOfAPitchSnake() {
        try (Simulator sim = new Simulator(config("snake:n=3"))) {
            sim.start(new RunInfo(null, new int[] {0, 1, 2}, 0.01));
            double[] cmd = {0, 30, 0};
            for (int i = 0; i < 100; i++) {
                sim.accept(i, i * 0.01, cmd);
            }
            SimSnapshot s = sim.snapshot();
            assertEquals(30, s.angle(1), 1.0, s.measuredAngles().toString());
            double zArm = s.bodies().stream().filter(b -> b.moduleId() == 1 && b.kind() == PartKind.SEGMENT_ARM)
                    .findFirst().orElseThrow().position().z();
            double zBase = s.bodies().stream().filter(b -> b.moduleId() == 1 && b.kind() == PartKind.SEGMENT_BASE)
                    .findFirst().orElseThrow().position().z();
            Mat3 rb = s.bodies().stream().filter(b -> b.moduleId() == 1 && b.kind() == PartKind.SEGMENT_BASE)
                    .findFirst().orElseThrow().rotation();
            Mat3 ra = s.bodies().stream().filter(b -> b.moduleId() == 1 && b.kind() == PartKind.SEGMENT_ARM)
                    .findFirst().orElseThrow().rotation();
            Vec3 xb = rb.axis(0);
            Vec3 xa = ra.axis(0);
            Vec3 zb = rb.axis(2);
            double sin = (xb.y() * xa.z() - xb.z() * xa.y()) * zb.x() + (xb.z() * xa.x() - xb.x() * xa.z()) * zb.y()
                    + (xb.x() * xa.y() - xb.y() * xa.x()) * zb.z();
            System.out.println("base z " + zBase + " arm z " + zArm + " sin " + sin + " zb " + zb + " xb " + xb);
        }
    }
}
