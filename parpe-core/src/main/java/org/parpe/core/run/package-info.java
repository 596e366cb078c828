/**
 * The scheduler of PARSL.md §7, §11 and §13 and the interfaces it talks through: a
 * {@link org.parpe.core.run.SensorSource} read at the start of a tick and
 * {@link org.parpe.core.run.JointSink}s written at its end (public API).
 */
package org.parpe.core.run;
