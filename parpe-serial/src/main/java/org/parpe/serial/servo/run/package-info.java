/**
 * Servos of a hardware profile as a run target: {@link org.parpe.serial.servo.run.ServoTarget}
 * attaches a {@link org.parpe.serial.servo.run.ServoDriver} (a joint sink and sensor source with
 * its own bus thread) to a run, on any protocol; clamping to the profile's limits, a safe stop
 * when the servos or the device go away, emergency stop and servo faults as located diagnostics
 * (public API).
 */
package org.parpe.serial.servo.run;
