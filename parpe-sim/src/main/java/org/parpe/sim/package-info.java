/**
 * The PolyBot physics simulator (public API): {@link org.parpe.sim.Simulator}, a plant that the
 * scheduler drives as a joint sink and reads as a sensor source, and the immutable
 * {@link org.parpe.sim.snapshot.SimSnapshot} it publishes for the IDE. No SWT or AWT types here.
 */
package org.parpe.sim;
