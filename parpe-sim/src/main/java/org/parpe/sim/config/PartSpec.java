package org.parpe.sim.config;

import org.parpe.core.diag.SourcePos;

/**
 * One part of a configuration.
 *
 * @param name     unique name, used by connections
 * @param type     what the part is
 * @param moduleId logical module ID (≥ 0) for a segment, −1 for every other part
 * @param angle    a segment's initial joint angle, degrees (0 for other parts)
 * @param plates   number of connection plates (only hubs may differ from the type's default)
 * @param limp     whether the segment's servo starts limp (back-drivable)
 * @param pos      where the part is defined
 */
public record PartSpec(String name, PartType type, int moduleId, double angle, int plates,
                       boolean limp, SourcePos pos) {

    /** A segment with logical ID {@code id} and an initial angle. */
    public static PartSpec segment(String name, int id, double angle) {
        return new PartSpec(name, PartType.SEGMENT, id, angle, 2, false, SourcePos.NONE);
    }

    /** A passive part (node, foot) with its default plates. */
    public static PartSpec passive(String name, PartType type) {
        return new PartSpec(name, type, -1, 0, type.defaultPlates(), false, SourcePos.NONE);
    }

    /** A hub with {@code plates} plates round its rim. */
    public static PartSpec hub(String name, int plates) {
        return new PartSpec(name, PartType.HUB, -1, 0, plates, false, SourcePos.NONE);
    }

    /** Whether this part is an active segment. */
    public boolean isSegment() {
        return type == PartType.SEGMENT;
    }
}
