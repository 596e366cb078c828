/**
 * Emulated Dynamixel Protocol 2.0 and Feetech STS/SCS servos on the far end of a serial link
 * (a socat pty in tests), speaking the protocols byte for byte, with the fault injection of
 * {@code parpe emulate}: lost and corrupted packets, reply latency, a pulled cable, and servo
 * faults (overload, overheating, voltage) (public API).
 */
package org.parpe.serial.servo.emu;
