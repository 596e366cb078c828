/**
 * The host side of the bus, shared by every protocol: the G1 request/reply transactions with
 * timeouts and retries ({@link org.parpe.serial.g1.BusMaster}), the bus thread with its
 * reconnection, silence report and emergency stop ({@link org.parpe.serial.bus.BusThread}), the
 * bus settings and what a run target adds to a run ({@link org.parpe.serial.bus.HostPlant})
 * (public API). The run driver itself is {@link org.parpe.serial.servo.run.ServoDriver}.
 */
package org.parpe.serial.bus;
