package org.ode4j.ode.internal;

import org.ode4j.ode.DContactGeom;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.internal.joints.DxJoint;
import org.ode4j.ode.internal.joints.DxJointContact;

/**
 * PARPE's own class (not a copy of ODE4j's): what one world's QuickStep starts its rows from.
 * ODE's C QuickStep, built with {@code WARM_STARTING}, started each joint's rows from the forces
 * they ended with in the step before; ODE4j's copy has the switch off. PARPE's copy of the solver
 * ({@link DxQuickStep}) does it with this: a joint's rows from the joint's own {@code lambda}
 * (joints persist from step to step), a contact's from the contact of the step before between the
 * same two geoms nearest to it (contacts are new in every step), each times {@link #scale}.
 * Allocation-free once its arrays have grown; one world's, stepped on one thread.
 */
public final class WarmStart {
    /** Rows a contact has at most: normal and two friction directions. */
    private static final int ROWS = 3;

    /**
     * Farthest a contact may have moved since the step before and still be the same contact, m:
     * a foot's corner moves well under a millimetre in a 5 ms step at the gaits' speeds, and the
     * contacts between one pair of pieces (at their corners) are 26 mm or more apart.
     */
    private static final double REACH = 0.003;

    final double scale;
    private DGeom[] geoms = new DGeom[0];
    private double[] at = new double[0];
    private double[] lambdas = new double[0];
    private boolean[] taken = new boolean[0];
    private int count;
    private DGeom[] nextGeoms = new DGeom[0];
    private double[] nextAt = new double[0];
    private double[] nextLambdas = new double[0];
    private int nextCount;

    /** @param scale what part of the last step's forces a row starts from, in (0, 1) */
    public WarmStart(double scale) {
        this.scale = scale;
    }

    /** A new step: the contacts kept in the step before become the ones to start from. */
    public void beginStep() {
        DGeom[] g = geoms;
        geoms = nextGeoms;
        nextGeoms = g;
        double[] a = at;
        at = nextAt;
        nextAt = a;
        double[] l = lambdas;
        lambdas = nextLambdas;
        nextLambdas = l;
        count = nextCount;
        nextCount = 0;
        if (taken.length < count) {
            taken = new boolean[geoms.length];
        }
        java.util.Arrays.fill(taken, 0, count, false);
    }

    /** What the solver does with one joint's rows {@code lambda[from..from+rows)}: {@link #start} or {@link #keep}. */
    @FunctionalInterface
    interface RowAction {
        void apply(WarmStart warm, DxJoint joint, double[] lambda, int from, int rows);
    }

    /**
     * Writes into {@code lambda[from..from+rows)} what {@code joint}'s rows start from: a joint's
     * own forces of the step before, a contact's those of the contact it continues, times {@link #scale}.
     */
    void start(DxJoint joint, double[] lambda, int from, int rows) {
        if (joint instanceof DxJointContact c) {
            startContact(c, lambda, from, rows);
        } else {
            for (int r = 0; r < rows; r++) {
                lambda[from + r] = joint.lambda[r] * scale;
            }
        }
    }

    /** Keeps the forces {@code lambda[from..from+rows)} that {@code joint}'s rows ended this step with. */
    void keep(DxJoint joint, double[] lambda, int from, int rows) {
        if (joint instanceof DxJointContact c) {
            keepContact(c, lambda, from, rows);
        } else {
            System.arraycopy(lambda, from, joint.lambda, 0, rows);
        }
    }

    /**
     * Writes into {@code lambda[from..from+rows)} the forces of the last step's contact that
     * {@code c} continues, times {@link #scale}; leaves them zero if it continues none.
     */
    private void startContact(DxJointContact c, double[] lambda, int from, int rows) {
        DContactGeom g = c.getContact().geom;
        int best = -1;
        double bestD2 = REACH * REACH;
        for (int i = 0; i < count; i++) {
            if (taken[i] || geoms[2 * i] != g.g1 || geoms[2 * i + 1] != g.g2) {
                continue;
            }
            double dx = at[3 * i] - g.pos.get0();
            double dy = at[3 * i + 1] - g.pos.get1();
            double dz = at[3 * i + 2] - g.pos.get2();
            double d2 = dx * dx + dy * dy + dz * dz;
            if (d2 < bestD2) {
                bestD2 = d2;
                best = i;
            }
        }
        if (best < 0) {
            return;
        }
        taken[best] = true;
        for (int r = 0; r < Math.min(rows, ROWS); r++) {
            lambda[from + r] = lambdas[ROWS * best + r] * scale;
        }
    }

    /** Keeps the forces {@code lambda[from..from+rows)} that contact {@code c} ended this step with. */
    private void keepContact(DxJointContact c, double[] lambda, int from, int rows) {
        int i = nextCount++;
        if (2 * nextCount > nextGeoms.length) {
            int room = nextCount + (nextCount >> 2) + 16;
            nextGeoms = java.util.Arrays.copyOf(nextGeoms, 2 * room);
            nextAt = java.util.Arrays.copyOf(nextAt, 3 * room);
            nextLambdas = java.util.Arrays.copyOf(nextLambdas, ROWS * room);
        }
        DContactGeom g = c.getContact().geom;
        nextGeoms[2 * i] = g.g1;
        nextGeoms[2 * i + 1] = g.g2;
        nextAt[3 * i] = g.pos.get0();
        nextAt[3 * i + 1] = g.pos.get1();
        nextAt[3 * i + 2] = g.pos.get2();
        for (int r = 0; r < ROWS; r++) {
            nextLambdas[ROWS * i + r] = r < rows ? lambda[from + r] : 0;
        }
    }
}
