package org.parpe.sim.build;

import org.parpe.sim.geom.Vec3;

/**
 * A connection plate of a robot being built, where it is at the robot's rest pose: what a
 * builder draws as a target to click.
 *
 * @param part   the name of the part that carries it
 * @param plate  its number on the part (a segment's 0 and 1, a node's 0 to 5, a foot's 0, a hub's 0 to n−1)
 * @param centre its centre, world frame, metres
 * @param normal its outward unit normal, world frame
 * @param up     its unit "up" direction (what a connection's orientation turns), world frame
 */
public record BuildPlate(String part, int plate, Vec3 centre, Vec3 normal, Vec3 up) {

    /** The plate as a connection names it: {@code part.plate}. */
    public String ref() {
        return part + "." + plate;
    }
}
