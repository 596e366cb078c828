package org.parpe.sim.internal;

import java.util.ArrayList;
import java.util.List;
import java.util.SortedMap;
import java.util.SortedSet;
import java.util.TreeMap;
import java.util.TreeSet;
import org.ode4j.math.DMatrix3C;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DGeom;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.PartKind;
import org.parpe.sim.snapshot.SimBody;
import org.parpe.sim.snapshot.SimContact;
import org.parpe.sim.snapshot.SimSnapshot;
import org.parpe.sim.geom.Vec3;

/**
 * Double-buffered world state for snapshots: the engine thread fills the back buffer after
 * every tick without allocating and swaps it in; any thread may build an immutable
 * {@link SimSnapshot} from the front buffer. The last snapshot is cached until the next swap.
 */
public final class SnapshotBuffer {
    private final PhysicsWorld world;
    /** The world's fixed solids, the same in every snapshot. */
    private final List<SimBody> fixedScenery;
    private final Object lock = new Object();
    private State front;
    private State back;
    private long version;
    private long builtVersion = -1;
    private SimSnapshot built;

    public SnapshotBuffer(PhysicsWorld world) {
        this.world = world;
        fixedScenery = fixedScenery(world);
        front = new State(world);
        back = new State(world);
        back.capture(world);
        publish();
    }

    /** Copies the world into the back buffer and makes it current (engine thread). */
    public void publish() {
        back.capture(world);
        synchronized (lock) {
            State t = front;
            front = back;
            back = t;
            version++;
        }
    }

    /** The latest published state as an immutable snapshot (any thread). */
    public SimSnapshot snapshot() {
        synchronized (lock) {
            if (builtVersion != version) {
                built = front.build(world, fixedScenery);
                builtVersion = version;
            }
            return built;
        }
    }

    private static List<SimBody> fixedScenery(PhysicsWorld w) {
        List<SimBody> out = new ArrayList<>();
        if (w.scene() != null) {
            for (org.parpe.sim.world.World.Solid s : w.scene().solids()) {
                out.add(new SimBody(-1, s.kind(), PartKind.SCENERY, s.shape(), s.position(), s.rotation()));
            }
        }
        return List.copyOf(out);
    }

    /** One copy of everything a snapshot shows, in flat arrays. */
    private static final class State {
        final double[] pose;
        final double[] objectPose;
        final double[] angles;
        final double[] targets;
        final boolean[] limp;
        final double[] com = new double[3];
        final double[] contacts = new double[Contacts.KEPT * 7];
        final int[] contactPieces = new int[Contacts.KEPT * 2];
        int contactCount;
        double time;

        State(PhysicsWorld w) {
            pose = new double[w.pieceCount() * 12];
            int objectPieces = 0;
            for (int i = 0; i < w.objectCount(); i++) {
                objectPieces += w.objectGeoms(i).length;
            }
            objectPose = new double[objectPieces * 12];
            angles = new double[w.hingeCount()];
            targets = new double[w.hingeCount()];
            limp = new boolean[w.hingeCount()];
        }

        void capture(PhysicsWorld w) {
            time = w.time();
            for (int i = 0; i < w.pieceCount(); i++) {
                copyPose(w.piecePosition(i), w.pieceRotation(i), pose, i * 12);
            }
            int k = 0;
            for (int i = 0; i < w.objectCount(); i++) {
                for (DGeom g : w.objectGeoms(i)) {
                    copyPose(g.getPosition(), g.getRotation(), objectPose, k);
                    k += 12;
                }
            }
            for (int h = 0; h < angles.length; h++) {
                angles[h] = w.angle(h);
                targets[h] = w.target(h);
                limp[h] = w.limp(h);
            }
            w.centerOfMass(com);
            Contacts c = w.contacts();
            contactCount = c.keptCount;
            System.arraycopy(c.kept, 0, contacts, 0, contactCount * 7);
            System.arraycopy(c.keptPieces, 0, contactPieces, 0, contactCount * 2);
        }

        private static void copyPose(DVector3C p, DMatrix3C r, double[] out, int k) {
            out[k] = p.get0();
            out[k + 1] = p.get1();
            out[k + 2] = p.get2();
            out[k + 3] = r.get00();
            out[k + 4] = r.get01();
            out[k + 5] = r.get02();
            out[k + 6] = r.get10();
            out[k + 7] = r.get11();
            out[k + 8] = r.get12();
            out[k + 9] = r.get20();
            out[k + 10] = r.get21();
            out[k + 11] = r.get22();
        }

        private static Vec3 position(double[] pose, int k) {
            return new Vec3(pose[k], pose[k + 1], pose[k + 2]);
        }

        private static Mat3 rotation(double[] pose, int k) {
            return new Mat3(pose[k + 3], pose[k + 4], pose[k + 5], pose[k + 6], pose[k + 7], pose[k + 8],
                    pose[k + 9], pose[k + 10], pose[k + 11]);
        }

        SimSnapshot build(PhysicsWorld w, List<SimBody> fixed) {
            Assembly a = w.assembly();
            List<SimBody> bodies = new ArrayList<>();
            for (int i = 0; i < a.pieces().size(); i++) {
                Assembly.PlacedPiece p = a.pieces().get(i);
                bodies.add(new SimBody(p.part().moduleId(), p.part().name(), p.def().kind(), p.def().shape(),
                        position(pose, i * 12), rotation(pose, i * 12)));
            }
            List<SimContact> cs = new ArrayList<>();
            for (int i = 0; i < contactCount; i++) {
                int k = i * 7;
                int pb = contactPieces[i * 2 + 1];
                cs.add(new SimContact(new Vec3(contacts[k], contacts[k + 1], contacts[k + 2]),
                        new Vec3(contacts[k + 3], contacts[k + 4], contacts[k + 5]), contacts[k + 6],
                        a.pieces().get(contactPieces[i * 2]).part().name(),
                        pb < 0 ? SimContact.GROUND : a.pieces().get(pb).part().name()));
            }
            SortedMap<Integer, Double> measured = new TreeMap<>();
            SortedMap<Integer, Double> target = new TreeMap<>();
            SortedSet<Integer> limpSet = new TreeSet<>();
            for (int h = 0; h < angles.length; h++) {
                int id = a.hinges().get(h).moduleId();
                measured.put(id, Math.toDegrees(angles[h]));
                target.put(id, Math.toDegrees(targets[h]));
                if (limp[h]) {
                    limpSet.add(id);
                }
            }
            List<SimBody> scenery = new ArrayList<>(fixed);
            int k = 0;
            for (int i = 0; i < w.objectCount(); i++) {
                org.parpe.sim.world.World.MovableObject o = w.scene().objects().get(i);
                for (org.parpe.sim.world.World.Piece p : o.pieces()) {
                    scenery.add(new SimBody(-1, o.name(), PartKind.OBJECT, p.shape(), position(objectPose, k),
                            rotation(objectPose, k)));
                    k += 12;
                }
            }
            return new SimSnapshot(time, bodies, cs, new Vec3(com[0], com[1], com[2]), measured, target, limpSet,
                    scenery);
        }
    }
}
