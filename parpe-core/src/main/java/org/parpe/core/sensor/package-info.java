/**
 * Sensor readings as expressions read them (PARSL.md §2, §10): the {@link org.parpe.core.sensor.Channel}s
 * a module can carry and the per-tick {@link org.parpe.core.sensor.SensorTable} (public API).
 * Depends on no other package of PARPE, so that both the expressions and the scheduler can use it.
 */
package org.parpe.core.sensor;
