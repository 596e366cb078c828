package org.parpe.gui.robot;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import org.parpe.sim.snapshot.SimBody;
import org.parpe.sim.snapshot.SimSnapshot;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.build.RobotDraft;

/** The Robot tab's pictures for the 3D view (the robot at rest, a part previewed on it), and a robot's start in a blank file. */
final class Pictures {
    private Pictures() {
    }

    /** The pieces of {@code after} that {@code before} lacks, where they go on the robot drawn now. */
    static List<SimBody> ghosts(RobotDraft before, RobotDraft after) {
        Set<String> had = new HashSet<>(before.partNames());
        Vec3 shift = Vec3.ZERO;
        String root = before.root();
        SimBody a = first(before.bodies(), root);
        SimBody b = first(after.bodies(), root);
        if (a != null && b != null) {
            // the whole robot may sit differently on the floor with the new part: draw it on the robot as it is
            shift = new Vec3(b.position().x() - a.position().x(), b.position().y() - a.position().y(),
                    b.position().z() - a.position().z());
        }
        List<SimBody> out = new ArrayList<>();
        for (SimBody s : after.bodies()) {
            if (!had.contains(s.part())) {
                Vec3 p = s.position();
                out.add(new SimBody(s.moduleId(), s.part(), s.kind(), s.shape(),
                        new Vec3(p.x() - shift.x(), p.y() - shift.y(), p.z() - shift.z()), s.rotation()));
            }
        }
        return out;
    }

    static SimBody first(List<SimBody> bodies, String part) {
        return part == null ? null : bodies.stream().filter(s -> s.part().equals(part)).findFirst().orElse(null);
    }

    /** A picture of the robot at rest for the view. */
    static SimSnapshot snapshot(List<SimBody> bodies) {
        double x = 0, y = 0, z = 0;
        for (SimBody b : bodies) {
            x += b.position().x();
            y += b.position().y();
            z += b.position().z();
        }
        int n = Math.max(1, bodies.size());
        return new SimSnapshot(0, bodies, List.of(), new Vec3(x / n, y / n, z / n), new TreeMap<>(Map.of()),
                new TreeMap<>(Map.of()), new TreeSet<>());
    }

    /** The largest extent of {@code bodies}' centres along x, y or z, m (0 for none). */
    static double size(List<SimBody> bodies) {
        double[] lo = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
        double[] hi = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (SimBody b : bodies) {
            double[] p = {b.position().x(), b.position().y(), b.position().z()};
            for (int k = 0; k < 3; k++) {
                lo[k] = Math.min(lo[k], p[k]);
                hi[k] = Math.max(hi[k], p[k]);
            }
        }
        return bodies.isEmpty() ? 0 : Math.max(hi[0] - lo[0], Math.max(hi[1] - lo[1], hi[2] - lo[2]));
    }

    /**
     * The edit that writes configuration {@code config} into a blank document {@code doc} (white
     * space, an XML declaration, comments): after what the document holds, which stays, without
     * a second declaration.
     */
    static org.parpe.core.edit.TextEdit startIn(String doc, String config) {
        String body = config;
        if (doc.stripLeading().startsWith("<?xml") && body.startsWith("<?xml")) {
            int end = body.indexOf("?>");
            body = body.substring(end + 2).stripLeading();
        }
        String kept = doc.strip();
        return kept.isEmpty() ? org.parpe.core.edit.TextEdit.of(0, doc.length(), config)
                : org.parpe.core.edit.TextEdit.of(0, doc.length(), kept + "\n" + body);
    }
}
