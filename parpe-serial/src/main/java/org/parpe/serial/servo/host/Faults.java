package org.parpe.serial.servo.host;

import java.util.ArrayList;
import java.util.List;
import org.parpe.serial.servo.ServoModel;

/**
 * Error bytes and error registers of the servo protocols in words, for messages: the bits of
 * the model's error register ({@code Registers.errorBits}) and the packet error the status byte
 * names on its family ({@code PacketCodec.packetError}).
 */
final class Faults {
    private Faults() {
    }

    /** The fault of a servo of {@code model}: its error register's bits and, on Dynamixel, the status error number. */
    static String describe(ServoModel model, int statusError, int bits) {
        List<String> names = model.registers().errorBits();
        List<String> words = new ArrayList<>();
        for (int b = 0; b < 8; b++) {
            if ((bits & 1 << b) != 0) {
                words.add(names.get(b) == null ? "error bit " + b : names.get(b));
            }
        }
        String packet = model.protocol().codec().packetError(statusError);
        if (packet != null) {
            words.add(packet);
        }
        if (words.isEmpty()) {
            words.add(String.format("status error 0x%02X", statusError & 0xFF));
        }
        return String.join(", ", words);
    }
}
