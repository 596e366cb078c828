package org.parpe.sim.snapshot;

import org.parpe.sim.geom.Vec3;

/**
 * One contact point found in the last physics sub-step of a tick.
 *
 * @param position where the contact is, world frame, metres
 * @param normal   unit contact normal, world frame
 * @param depth    penetration depth, metres
 * @param partA    the part name of the first piece
 * @param partB    the part name of the second piece, or {@code "ground"}
 */
public record SimContact(Vec3 position, Vec3 normal, double depth, String partA, String partB) {

    /** The name used for the ground plane in {@link #partB()}. */
    public static final String GROUND = "ground";

    /** Whether this contact is with the ground rather than between two pieces of the robot. */
    public boolean withGround() {
        return GROUND.equals(partB);
    }
}
