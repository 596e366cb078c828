package org.parpe.sim.bridge;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.parpe.sim.geom.Geo;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.internal.Assembly;

/**
 * The plate pairs a script's latches can join, for an export (PARSL.md §14; docs/bridges.md):
 * every pair of free plates (no connection of the configuration uses them) of two different
 * modules that carry the {@code latch} actuator. A free plate's pair is all such plates, not only
 * the ones a run brings together: a snake with latches on its end modules has one pair, its two
 * end plates. Each pair has the four aligned poses of the simulator's latch ({@code Docking}):
 * centres together, faces opposite, "up" directions on one of the four 90° steps.
 */
public final class Latches {
    /** A latchable plate: plate {@code plate} of module {@code moduleId}, on link {@code link}, in its frame. */
    public record Plate(int moduleId, int plate, int link, Vec3 centre, Vec3 normal, Vec3 up) {
        /** The name of its MJCF site and of its column in a gait: {@code plate<ID>_<P>}. */
        public String name() {
            return "plate" + moduleId + "_" + plate;
        }

        /** Its frame in its link's: x the face's normal, y its "up". */
        Mat3 frame() {
            return Geo.columns(normal, up, Geo.cross(normal, up));
        }
    }

    /** Two plates that can latch. */
    public record Pair(Plate a, Plate b) {
        /** The name of the weld that holds the pair latched with b's "up" {@code step} quarter turns from a's. */
        public String weld(int step) {
            return "latch_" + a.name() + "__" + b.name() + "_r" + step * 90;
        }

        /**
         * The orientation of b's link in a's link's frame when plate b lies on plate a with its
         * "up" {@code step} quarter turns about a's normal from a's "up".
         */
        Mat3 rotation(int step) {
            Vec3 n = a.normal();
            Vec3 side = Geo.cross(n, a.up());
            Vec3 up = switch (step) {
                case 0 -> a.up();
                case 1 -> side;
                case 2 -> Geo.scale(a.up(), -1);
                default -> Geo.scale(side, -1);
            };
            Vec3 face = Geo.scale(n, -1);
            return Geo.mul(Geo.columns(face, up, Geo.cross(face, up)), Geo.transpose(b.frame()));
        }

        /** The position of b's link in a's link's frame in that pose. */
        Vec3 position(int step) {
            return Geo.sub(a.centre(), Geo.mul(rotation(step), b.centre()));
        }
    }

    private Latches() {
    }

    /**
     * The latchable pairs of assembly {@code a} for the modules {@code latch}, in ascending module
     * ID and plate; a plate's link is its piece's index, link i of the assembly's {@link RobotModel}.
     */
    public static List<Pair> of(Assembly a, Set<Integer> latch) {
        List<Plate> plates = new ArrayList<>();
        for (Assembly.PlateSite s : a.plates()) {
            if (!s.connected() && s.moduleId() >= 0 && latch.contains(s.moduleId())) {
                plates.add(new Plate(s.moduleId(), s.plate(), s.piece(), s.centre(), s.normal(), s.up()));
            }
        }
        plates.sort((x, y) -> x.moduleId() != y.moduleId() ? Integer.compare(x.moduleId(), y.moduleId())
                : Integer.compare(x.plate(), y.plate()));
        List<Pair> out = new ArrayList<>();
        for (int i = 0; i < plates.size(); i++) {
            for (int k = i + 1; k < plates.size(); k++) {
                if (plates.get(i).moduleId() != plates.get(k).moduleId()) {
                    out.add(new Pair(plates.get(i), plates.get(k)));
                }
            }
        }
        return out;
    }
}
