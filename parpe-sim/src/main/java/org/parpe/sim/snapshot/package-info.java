/**
 * What the simulator publishes for the IDE and the grader to read (public API): the immutable
 * {@link org.parpe.sim.snapshot.SimSnapshot} of one tick, its bodies
 * ({@link org.parpe.sim.snapshot.SimBody}) and contacts ({@link org.parpe.sim.snapshot.SimContact}).
 * Built by the simulator's internals, which is why it sits below them; no SWT or AWT types.
 */
package org.parpe.sim.snapshot;
