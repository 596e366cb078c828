package org.parpe.sim;

import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.util.List;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.run.RunInfo;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RobotConfigs;
import org.parpe.sim.geom.PartKind;
import org.parpe.sim.snapshot.SimBody;
import org.parpe.sim.snapshot.SimSnapshot;

/** Helpers shared by the simulator tests. */
final class SimTestSupport {
    private SimTestSupport() {
    }

    static RobotConfig config(String spec) {
        DiagnosticList d = new DiagnosticList();
        RobotConfig c = RobotConfigs.resolve(spec, new int[0], d);
        assertNotNull(c, d.all().toString());
        return c;
    }

    /** A started simulator with tick {@code dt} whose program modules are the robot's own. */
    static Simulator started(RobotConfig config, double dt) {
        Simulator sim = new Simulator(config);
        sim.start(new RunInfo(null, sim.moduleIds(), dt));
        return sim;
    }

    /** Commands the same angles for {@code ticks} ticks. */
    static void hold(Simulator sim, double[] angles, int ticks) {
        for (int i = 0; i < ticks; i++) {
            sim.accept(i, i * 0.01, angles);
        }
    }

    static SimBody piece(SimSnapshot s, String part, PartKind kind) {
        List<SimBody> l = s.bodies().stream().filter(b -> b.part().equals(part) && b.kind() == kind).toList();
        return l.get(0);
    }
}
