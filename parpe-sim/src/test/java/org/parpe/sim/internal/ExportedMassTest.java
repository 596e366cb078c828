package org.parpe.sim.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.ode4j.math.DMatrix3C;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DMass;
import org.ode4j.ode.OdeHelper;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.sim.geom.Geo;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.bridge.RobotModel;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RobotConfigs;

/**
 * The first suspect when a robot moves differently in MuJoCo (issue 34, the Fig. 7 wheel that
 * rolls in PARPE and rocks in MuJoCo): does the export give the other engine the robot PARPE
 * simulates? The exported links' masses, centre of mass and inertia about it, summed from
 * {@link RobotModel#inertia} (the MJCF's {@code diaginertia}) and the links' poses, are those of
 * the simulator's ODE bodies ({@code DMass} of each piece, as {@link PhysicsWorld} builds its
 * bodies), for every generator. They are: the wheel's 1.06 kg, its centre 160.9 mm up and its
 * inertia (5.257, 9.871, 5.257)·10⁻³ kg·m² agree to the last digit, so the wheel's difference is
 * not its mass (docs/simulator.md, "PARPE against MuJoCo").
 */
class ExportedMassTest {
    @ParameterizedTest
    @ValueSource(strings = {"wheel", "snake:n=8", "centipede", "loop", "humanoid"})
    void theExportCarriesTheSimulatorsMassCentreAndInertia(String robot) {
        DiagnosticList d = new DiagnosticList();
        RobotConfig c = RobotConfigs.resolve(robot, new int[0], d);
        assertNotNull(c, d.all().toString());
        Assembly a = Assembly.build(c, d);
        assertNotNull(a, d.all().toString());
        RobotModel m = RobotModel.of(c, a);

        DMass ode = OdeHelper.createMass();
        ode.setZero();
        for (Assembly.PlacedPiece p : a.pieces()) {
            ode.add(WorldBodies.pieceMass(p.def().shape(), p.def().mass(), p.rotation(), p.position()));
        }
        DVector3C c0 = ode.getC();
        Vec3 oc = new Vec3(c0.get0(), c0.get1(), c0.get2());
        ode.translate(-oc.x(), -oc.y(), -oc.z());

        double mass = 0;
        Vec3 moment = Vec3.ZERO;
        for (RobotModel.Link l : m.links()) {
            mass += l.mass();
            moment = Geo.add(moment, Geo.scale(l.position(), l.mass()));
        }
        Vec3 com = Geo.scale(moment, 1 / mass);
        double[][] inertia = new double[3][3];
        for (int i = 0; i < m.links().size(); i++) {
            addAbout(inertia, m, i, com);
        }

        assertEquals(ode.getMass(), mass, 1e-12, robot + ": total mass");
        assertEquals(oc.x(), com.x(), 1e-12, robot + ": centre of mass x");
        assertEquals(oc.y(), com.y(), 1e-12, robot + ": centre of mass y");
        assertEquals(oc.z(), com.z(), 1e-12, robot + ": centre of mass z");
        DMatrix3C oi = ode.getI();
        for (int r = 0; r < 3; r++) {
            for (int k = 0; k < 3; k++) {
                assertEquals(oi.get(r, k), inertia[r][k], 1e-12, robot + ": inertia about the centre, row " + r + " column " + k);
            }
        }
    }

    /** Adds link {@code i}'s inertia, turned into the world frame and moved to {@code about}, to {@code sum}. */
    private static void addAbout(double[][] sum, RobotModel m, int i, Vec3 about) {
        RobotModel.Link l = m.links().get(i);
        Vec3 principal = m.inertia(i);
        double[] diag = {principal.x(), principal.y(), principal.z()};
        Mat3 r = l.rotation();
        Vec3 d = Geo.sub(l.position(), about);
        double[] v = {d.x(), d.y(), d.z()};
        double dd = Geo.dot(d, d);
        for (int row = 0; row < 3; row++) {
            for (int col = 0; col < 3; col++) {
                double turned = 0;
                for (int k = 0; k < 3; k++) {
                    turned += r.get(row, k) * diag[k] * r.get(col, k);
                }
                sum[row][col] += turned + l.mass() * ((row == col ? dd : 0) - v[row] * v[col]);
            }
        }
    }
}
