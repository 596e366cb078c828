package org.parpe.sim.snapshot;

import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.PartKind;
import org.parpe.sim.geom.Vec3;

/**
 * One rigid piece of the robot at the time of a snapshot.
 *
 * @param moduleId the logical ID of the segment this piece belongs to, or −1 for a passive piece
 * @param part     the name of the part in the robot configuration
 * @param kind     what the piece is
 * @param shape    its shape in its local frame
 * @param position its centre, world frame, metres
 * @param rotation its orientation (columns are the local axes in world coordinates)
 */
public record SimBody(int moduleId, String part, PartKind kind, BodyShape shape,
                      Vec3 position, Mat3 rotation) {
}
