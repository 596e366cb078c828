/**
 * The G1 module bus (docs/hardware-protocol.md), PARPE's reconstruction of the PolyBot G1
 * protocol: frame layout, command codes, an allocation-free encoder and a streaming decoder that
 * resynchronises on garbage, the request/reply transactions with timeouts and retries
 * ({@link org.parpe.serial.g1.BusMaster}), and {@link org.parpe.serial.g1.G1Bus}, which puts it
 * behind the {@link org.parpe.serial.servo.ServoBus} every protocol has (public API).
 */
package org.parpe.serial.g1;
