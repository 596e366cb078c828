/**
 * The Dynamixel family: Protocol 2.0 packets ({@link org.parpe.serial.dynamixel.Dxl2Codec}:
 * header {@code FF FF FD 00}, CRC-16 with polynomial 0x8005, byte stuffing; ROBOTIS e-Manual,
 * Protocol 2.0) behind the {@link org.parpe.serial.servo.wire.PacketCodec} the control-table
 * host and emulator are written against (public API).
 */
package org.parpe.serial.dynamixel;
