package org.parpe.sim.internal;

import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.sim.geom.Geo;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.config.Connection;
import org.parpe.sim.config.PartSpec;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RootPose;

/**
 * Places every part of a configuration in the world at its initial joint angles, breadth first
 * from the root part along the connections. A connection between two parts already placed
 * closes a loop and must fit (plates together within 3 mm and 3°). A configuration with several
 * roots is placed robot by robot, each from its own root's pose.
 */
final class Placement {
    private final RobotConfig config;
    private final List<PartGeometry> geos;
    private final DiagnosticSink diags;
    private final Map<String, Integer> index = new HashMap<>();
    private final Mat3[] rotation;
    private final Vec3[] position;
    private final int[] chain;
    private int rootIndex;

    Placement(RobotConfig config, List<PartGeometry> geos, DiagnosticSink diags) {
        this.config = config;
        this.geos = geos;
        this.diags = diags;
        for (int i = 0; i < config.parts().size(); i++) {
            index.put(config.parts().get(i).name(), i);
        }
        rotation = new Mat3[config.parts().size()];
        position = new Vec3[config.parts().size()];
        chain = new int[config.parts().size()];
    }

    Mat3 rotation(int part) {
        return rotation[part];
    }

    Vec3 position(int part) {
        return position[part];
    }

    int rootIndex() {
        return rootIndex;
    }

    /** Which root's robot part {@code part} belongs to (an index into the configuration's roots). */
    int chain(int part) {
        return chain[part];
    }

    boolean run() {
        boolean ok = true;
        boolean[] done = new boolean[config.parts().size()];
        List<List<Connection>> byPart = connectionsByPart();
        List<RootPose> roots = config.roots();
        rootIndex = index.get(roots.get(0).part());
        for (int k = 0; k < roots.size(); k++) {
            RootPose root = roots.get(k);
            int part = index.get(root.part());
            if (done[part]) {
                PartSpec p = config.parts().get(part);
                diags.error(p.pos(), org.parpe.core.text.Msg.ROOT_CONNECTED_TO_ROOT, p.name(), roots.get(chain[part]).part());
                ok = false;
                continue;
            }
            rotation[part] = Geo.clean(Geo.rollPitchYaw(root.roll(), root.pitch(), root.yaw()));
            position[part] = new Vec3(root.x(), root.y(), 0);
            ok &= placeFrom(part, k, done, byPart);
        }
        for (int i = 0; i < done.length; i++) {
            if (!done[i]) {
                PartSpec p = config.parts().get(i);
                diags.error(p.pos(), roots.size() > 1 ? org.parpe.core.text.Msg.NOT_CONNECTED_TO_ROOTS
                        : org.parpe.core.text.Msg.NOT_CONNECTED_TO_ROOT, p.name(), roots.get(0).part());
                ok = false;
            }
        }
        return ok;
    }

    /** Places every part reached from the placed part {@code start}, breadth first, as robot {@code k}. */
    private boolean placeFrom(int start, int k, boolean[] done, List<List<Connection>> byPart) {
        boolean ok = true;
        Deque<Integer> queue = Assembly.queueOf(start);
        while (!queue.isEmpty()) {
            int part = queue.poll();
            if (done[part]) {
                continue;
            }
            done[part] = true;
            chain[part] = k;
            for (Connection c : byPart.get(part)) {
                int a = index.get(c.from());
                int b = index.get(c.to());
                if (a == part && !done[b]) {
                    ok &= attach(c, a, c.fromPlate(), b, c.toPlate(), queue);
                } else if (b == part && !done[a]) {
                    ok &= attach(c, b, c.toPlate(), a, c.fromPlate(), queue);
                }
            }
        }
        return ok;
    }

    /**
     * Each part's connections in configuration order: looking through all of them for every
     * part grew with parts × connections, 10^8 steps for a robot of 10 000 parts.
     */
    private List<List<Connection>> connectionsByPart() {
        List<List<Connection>> out = new ArrayList<>();
        for (int i = 0; i < config.parts().size(); i++) {
            out.add(new ArrayList<>());
        }
        for (Connection c : config.connections()) {
            int a = index.get(c.from());
            int b = index.get(c.to());
            out.get(a).add(c);
            if (b != a) {
                out.get(b).add(c);
            }
        }
        return out;
    }

    /** Places part {@code b} against plate {@code pa} of placed part {@code a}, or checks the fit. */
    private boolean attach(Connection c, int a, int pa, int b, int pb, Deque<Integer> queue) {
        Frame plateA = plateFrame(a, pa, rotation[a], position[a]);
        PartGeometry.Plate local = localPlate(b, pb);
        Vec3 up = Geo.mul(Geo.axisAngle(plateA.normal, c.quarterTurns() * Math.PI / 2), plateA.up);
        Vec3 n = Geo.scale(plateA.normal, -1);
        Mat3 target = Geo.columns(n, up, Geo.cross(n, up));
        Mat3 localFrame = Geo.columns(local.normal(), local.up(), Geo.cross(local.normal(), local.up()));
        Mat3 r = Geo.clean(Geo.mul(target, Geo.transpose(localFrame)));
        Vec3 p = Geo.sub(plateA.centre, Geo.mul(r, local.centre()));
        if (rotation[b] == null) {
            rotation[b] = r;
            position[b] = p;
            queue.add(b);
            return true;
        }
        double gap = Geo.sub(p, position[b]).length();
        double twist = Geo.angleBetween(r, rotation[b]);
        if (gap > Assembly.loopGap() || twist > Assembly.loopTwist()) {
            diags.error(c.pos(), org.parpe.core.text.Msg.LOOP_DOES_NOT_FIT, c.from(), c.fromPlate(), c.to(), c.toPlate(),
                    one(gap * 1000), one(Math.toDegrees(twist)), none(Assembly.loopGap() * 1000),
                    none(Math.toDegrees(Assembly.loopTwist())));
            return false;
        }
        return true;
    }

    /** A plate of a part in the part frame, at the part's initial joint angle. */
    private PartGeometry.Plate localPlate(int part, int plate) {
        PartGeometry.Plate p = geos.get(part).plates().get(plate);
        PartGeometry.Piece piece = geos.get(part).pieces().get(p.piece());
        Mat3 turn = PartGeometry.pieceRotation(piece, Math.toRadians(config.parts().get(part).angle()));
        return new PartGeometry.Plate(p.piece(), Geo.mul(turn, p.centre()), Geo.mul(turn, p.normal()),
                Geo.mul(turn, p.up()));
    }

    private Frame plateFrame(int part, int plate, Mat3 r, Vec3 p) {
        PartGeometry.Plate local = localPlate(part, plate);
        return new Frame(Geo.add(p, Geo.mul(r, local.centre())), Geo.mul(r, local.normal()), Geo.mul(r, local.up()));
    }

    private record Frame(Vec3 centre, Vec3 normal, Vec3 up) {
    }

    private static String one(double v) {
        return String.format(java.util.Locale.ROOT, "%.1f", v);
    }

    private static String none(double v) {
        return String.format(java.util.Locale.ROOT, "%.0f", v);
    }
}
