/**
 * How the simulator works inside (not API): G1 part geometry, placing parts from their
 * connections, the ODE4j world, servos, contacts and snapshot buffers. Only this package
 * touches {@code org.ode4j}.
 */
package org.parpe.sim.internal;
