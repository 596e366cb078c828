/**
 * The Feetech family, STS and SCS: packets ({@link org.parpe.serial.feetech.FeetechCodec}:
 * header {@code FF FF}, one's-complement checksum) behind the
 * {@link org.parpe.serial.servo.wire.PacketCodec} the control-table host and emulator are written
 * against (public API).
 */
package org.parpe.serial.feetech;
