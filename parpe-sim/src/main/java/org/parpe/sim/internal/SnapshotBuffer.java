package org.parpe.sim.internal;

import java.util.ArrayList;
import java.util.List;
import java.util.SortedMap;
import java.util.SortedSet;
import java.util.TreeMap;
import java.util.TreeSet;
import org.ode4j.math.DMatrix3C;
import org.ode4j.math.DVector3C;
import org.parpe.sim.Mat3;
import org.parpe.sim.SimBody;
import org.parpe.sim.SimContact;
import org.parpe.sim.SimSnapshot;
import org.parpe.sim.Vec3;

/**
 * Double-buffered world state for snapshots: the engine thread fills the back buffer after
 * every tick without allocating and swaps it in; any thread may build an immutable
 * {@link SimSnapshot} from the front buffer. The last snapshot is cached until the next swap.
 */
public final class SnapshotBuffer {
    private final PhysicsWorld world;
    private final Object lock = new Object();
    private State front;
    private State back;
    private long version;
    private long builtVersion = -1;
    private SimSnapshot built;

    public SnapshotBuffer(PhysicsWorld world) {
        this.world = world;
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
                built = front.build(world.assembly());
                builtVersion = version;
            }
            return built;
        }
    }

    /** One copy of everything a snapshot shows, in flat arrays. */
    private static final class State {
        final double[] pose;
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
            angles = new double[w.hingeCount()];
            targets = new double[w.hingeCount()];
            limp = new boolean[w.hingeCount()];
        }

        void capture(PhysicsWorld w) {
            time = w.time();
            for (int i = 0; i < w.pieceCount(); i++) {
                DVector3C p = w.piecePosition(i);
                DMatrix3C r = w.pieceRotation(i);
                int k = i * 12;
                pose[k] = p.get0();
                pose[k + 1] = p.get1();
                pose[k + 2] = p.get2();
                for (int j = 0; j < 9; j++) {
                    pose[k + 3 + j] = r.get(j / 3, j % 3);
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

        SimSnapshot build(Assembly a) {
            List<SimBody> bodies = new ArrayList<>();
            for (int i = 0; i < a.pieces().size(); i++) {
                Assembly.PlacedPiece p = a.pieces().get(i);
                int k = i * 12;
                Mat3 r = new Mat3(pose[k + 3], pose[k + 4], pose[k + 5], pose[k + 6], pose[k + 7], pose[k + 8],
                        pose[k + 9], pose[k + 10], pose[k + 11]);
                bodies.add(new SimBody(p.part().moduleId(), p.part().name(), p.def().kind(), p.def().shape(),
                        new Vec3(pose[k], pose[k + 1], pose[k + 2]), r));
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
            return new SimSnapshot(time, bodies, cs, new Vec3(com[0], com[1], com[2]), measured, target, limpSet);
        }
    }
}
