/**
 * An emulator of G1-style modules that serves the bus protocol on a serial device: servo motion
 * with a speed limit, limp and hold, a watchdog, sensor readings, and injected faults (drops,
 * corruption, latency, unplugging) for testing the driver with real bytes (public API).
 */
package org.parpe.serial.emu;
