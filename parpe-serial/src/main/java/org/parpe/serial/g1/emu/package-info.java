/**
 * An emulator of G1-style modules that serves the G1 bus on a serial device: servo motion with a
 * speed limit, limp and hold, a watchdog, sensor readings, over the shared
 * {@link org.parpe.serial.emu.ServedLine} and its injected faults (public API).
 */
package org.parpe.serial.g1.emu;
