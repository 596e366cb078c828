package org.parpe.serial.servo;

import java.util.List;

/**
 * Where a servo model keeps what PARPE uses in its control table (addresses in bytes).
 *
 * @param model        model number (2 bytes)
 * @param torque       torque enable (1 byte: 0 off, 1 on)
 * @param goal         goal position
 * @param goalSize     bytes of the goal position
 * @param present      present position
 * @param presentSize  bytes of the present position
 * @param error        hardware error status (Dynamixel) or servo status (Feetech), 1 byte
 * @param watchdog     Dynamixel Bus Watchdog (1 byte, units of 20 ms), or −1 when the model has none
 * @param errorBits    the faults the bits of {@code error} report, in words, bit 0 first (null: unused)
 */
public record Registers(int model, int torque, int goal, int goalSize, int present, int presentSize, int error,
                        int watchdog, List<String> errorBits) {

    /**
     * Dynamixel X series (XL330, XL430, XM430, …), e-Manual control tables; Hardware Error Status
     * (address 70) bit by bit as in e-Manual, X series, Shutdown(63).
     */
    public static final Registers DXL_X = new Registers(0, 64, 116, 4, 132, 4, 70, 98,
            bits("input voltage out of range", null, "overheating", "motor encoder fault", "electrical shock",
                    "overload"));
    /**
     * Dynamixel XL-320 (Protocol 2.0 with its own control table); Hardware Error Status (address
     * 50) as in e-Manual, XL-320, Shutdown(18): bit 0 overload, bit 1 overheating, bit 2 input voltage.
     */
    public static final Registers DXL_XL320 = new Registers(0, 24, 30, 2, 37, 2, 50, -1,
            bits("overload", "overheating", "input voltage out of range"));
    /** Feetech STS and SCS series (memory table of the STS3215 and SCS servos); servo status (address 65). */
    public static final Registers FEETECH = new Registers(3, 40, 42, 2, 56, 2, 65, -1,
            bits("input voltage out of range", "magnetic sensor fault", "overheating", "overcurrent",
                    "goal outside the angle limits", "overload"));

    /** Names of bits 0…7, the missing high ones null. */
    private static List<String> bits(String... names) {
        String[] all = java.util.Arrays.copyOf(names, 8);
        return java.util.Collections.unmodifiableList(java.util.Arrays.asList(all));
    }
}
