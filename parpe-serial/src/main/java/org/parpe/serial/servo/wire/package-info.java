/**
 * Byte-level packets of the commercial servo buses: Dynamixel Protocol 2.0
 * ({@link org.parpe.serial.dynamixel.Dxl2Codec}: header {@code FF FF FD 00}, CRC-16 with
 * polynomial 0x8005, byte stuffing) and Feetech STS/SCS
 * ({@link org.parpe.serial.feetech.FeetechCodec}: header {@code FF FF}, one's-complement
 * checksum), behind one {@link org.parpe.serial.servo.wire.PacketCodec} so that the host driver and
 * the emulator are written once (public API).
 */
package org.parpe.serial.servo.wire;
