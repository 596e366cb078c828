/**
 * The simulator's geometry (public API): vectors {@link org.parpe.sim.geom.Vec3}, rotations
 * {@link org.parpe.sim.geom.Mat3}, the vector maths of {@link org.parpe.sim.geom.Geo}, and what a
 * body is: its {@link org.parpe.sim.geom.BodyShape} and {@link org.parpe.sim.geom.PartKind}. The
 * bottom of parpe-sim: it uses no other package of it.
 */
package org.parpe.sim.geom;
