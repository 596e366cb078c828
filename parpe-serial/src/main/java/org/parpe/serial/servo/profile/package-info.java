/**
 * Hardware profiles (docs/hardware-profile.md): which servo bus a robot has and, per PARSL module,
 * which servo drives it, with zero offset, direction, angle limits and model. Read with every
 * problem located at {@code FILE:LINE:COL} ({@link org.parpe.serial.servo.profile.ProfileReader}),
 * written by {@code parpe scan} and {@code parpe calibrate} ({@link org.parpe.serial.servo.profile.ProfileWriter})
 * (public API).
 */
package org.parpe.serial.servo.profile;
