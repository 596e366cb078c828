/**
 * Worlds of the simulator (public API): the immutable {@link org.parpe.sim.world.World} read from
 * a world file by {@link org.parpe.sim.world.WorldReader} (static solids, seeded rubble, movable
 * objects, a lever, zones, checkpoints, the start pose, the time limit and how a run is scored),
 * and the {@link org.parpe.sim.world.WorldScore} of a run. No physics types here: the simulator
 * builds its bodies from these records.
 */
package org.parpe.sim.world;
