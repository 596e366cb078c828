package org.parpe.sim.geom;

/** What a rigid piece of the simulated robot is. */
public enum PartKind {
    /** The half of a segment that carries its first connection plate (plate 0) and the servo. */
    SEGMENT_BASE,
    /** The half of a segment that carries its second connection plate (plate 1); it turns. */
    SEGMENT_ARM,
    /** A rigid cube with six connection plates. */
    NODE,
    /** A passive foot pad. */
    FOOT,
    /** A passive wheel hub with connection plates round its rim. */
    HUB,
    /** A fixed solid of the world (box, ramp, step, wall, pillar, rubble). */
    SCENERY,
    /** A piece of a movable object of the world (chip, ball, cup, lever arm). */
    OBJECT
}
