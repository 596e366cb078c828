package org.parpe.serial.servo.wire;

/** Receives the packets a {@link PacketDecoder} recognises. */
@FunctionalInterface
public interface PacketHandler {

    /** One valid packet; {@code p} is reused by the decoder after the call returns. */
    void onPacket(Packet p);
}
