/**
 * The PARPE module bus protocol (docs/hardware-protocol.md): frame layout, command codes, the
 * CRC, an allocation-free encoder and a streaming decoder that resynchronises on garbage
 * (public API).
 */
package org.parpe.serial.protocol;
