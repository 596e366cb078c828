package org.parpe.serial.servo;

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
 */
public record Registers(int model, int torque, int goal, int goalSize, int present, int presentSize, int error,
                        int watchdog) {

    /** Dynamixel X series (XL330, XL430, XM430, …), e-Manual control tables. */
    public static final Registers DXL_X = new Registers(0, 64, 116, 4, 132, 4, 70, 98);
    /** Dynamixel XL-320 (Protocol 2.0 with its own control table). */
    public static final Registers DXL_XL320 = new Registers(0, 24, 30, 2, 37, 2, 50, -1);
    /** Feetech STS and SCS series (memory table of the STS3215 and SCS servos). */
    public static final Registers FEETECH = new Registers(3, 40, 42, 2, 56, 2, 65, -1);
}
