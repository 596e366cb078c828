/**
 * The host side of the bus: request/reply transactions with timeouts and retries
 * ({@link org.parpe.serial.bus.BusMaster}) and the run driver that is both a joint sink and a
 * sensor source, with clamping, a watchdog-backed safe stop, reconnection and emergency stop
 * ({@link org.parpe.serial.bus.HardwareBus}) (public API).
 */
package org.parpe.serial.bus;
