/**
 * Gait sweeps and optimisation on the simulator, for the command line and the IDE alike:
 * {@link org.parpe.sim.sweep.SweepSpec} says what to vary, {@link org.parpe.sim.sweep.Sweep}
 * runs every combination on fresh simulated robots in parallel and streams
 * {@link org.parpe.sim.sweep.SweepRow}s in combination order, and
 * {@link org.parpe.sim.sweep.Optimizer} searches a script's bounded parameters with CMA-ES
 * (Apache Commons Math). Progress reaches a {@link org.parpe.sim.sweep.SweepListener} from the
 * worker threads; a {@link org.parpe.sim.sweep.Cancellation} stops work at the next tick.
 * Nothing here prints to a terminal or touches a widget.
 */
package org.parpe.sim.sweep;
