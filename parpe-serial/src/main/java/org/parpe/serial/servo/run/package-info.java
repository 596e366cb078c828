/**
 * The one run driver for servos on a serial bus, on any protocol: {@link
 * org.parpe.serial.servo.run.ServoTarget} attaches a {@link org.parpe.serial.servo.run.ServoDriver}
 * (a joint sink and sensor source with its own bus thread) to a run, for the servos of a hardware
 * profile or, with {@code --port} alone, the script's G1 modules; the safe start, clamping to the
 * limits, retries and back-off of reads, devices that answer late, a safe stop when the servos or
 * the device go away, emergency stop and servo faults as located diagnostics (public API).
 */
package org.parpe.serial.servo.run;
