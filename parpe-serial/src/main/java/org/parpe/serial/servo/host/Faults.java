package org.parpe.serial.servo.host;

import java.util.ArrayList;
import java.util.List;
import org.parpe.serial.servo.Registers;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.dynamixel.Dxl2Codec;

/** Error bytes and error registers of the servo protocols in words, for messages. */
final class Faults {
    /** Dynamixel X Hardware Error Status (address 70), bit by bit (e-Manual, X series, Shutdown(63)). */
    private static final String[] DXL_HARDWARE = {"input voltage out of range", null, "overheating",
        "motor encoder fault", "electrical shock", "overload", null, null};
    /**
     * Dynamixel XL-320 Hardware Error Status (address 50), bit by bit (e-Manual, XL-320,
     * Shutdown(18): bit 0 overload, bit 1 overheating, bit 2 input voltage).
     */
    private static final String[] XL320_HARDWARE = {"overload", "overheating", "input voltage out of range", null,
        null, null, null, null};
    /** Feetech servo status (address 65), bit by bit. */
    private static final String[] FEETECH = {"input voltage out of range", "magnetic sensor fault", "overheating",
        "overcurrent", "goal outside the angle limits", "overload", null, null};
    /** Dynamixel 2.0 status error numbers 1…7. */
    private static final String[] DXL_ERRORS = {"result fail", "instruction error", "CRC error", "data range error",
        "data length error", "data limit error", "access error"};

    private Faults() {
    }

    /** The fault of a servo of {@code model}: its error register's bits and, on Dynamixel, the status error number. */
    static String describe(ServoModel model, int statusError, int bits) {
        ServoProtocol protocol = model.protocol();
        String[] names = model.registers() == Registers.DXL_XL320 ? XL320_HARDWARE
                : protocol == ServoProtocol.DXL2 ? DXL_HARDWARE : FEETECH;
        List<String> words = new ArrayList<>();
        for (int b = 0; b < 8; b++) {
            if ((bits & 1 << b) != 0) {
                words.add(names[b] == null ? "error bit " + b : names[b]);
            }
        }
        int number = statusError & 0x7F;
        if (protocol == ServoProtocol.DXL2 && number >= 1 && number <= DXL_ERRORS.length) {
            words.add(DXL_ERRORS[number - 1]);
        }
        if (words.isEmpty()) {
            words.add(String.format("status error 0x%02X", statusError & 0xFF));
        }
        return String.join(", ", words);
    }

    /** Whether a Dynamixel status error byte has the alert bit (a hardware error). */
    static boolean alert(int statusError) {
        return (statusError & Dxl2Codec.ERROR_ALERT) != 0;
    }
}
