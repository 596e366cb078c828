/**
 * Host drivers of the servo buses: {@link org.parpe.serial.servo.host.ControlTableBus} speaks
 * Dynamixel Protocol 2.0 and Feetech STS/SCS over a byte link, {@link org.parpe.serial.g1.G1Bus}
 * puts the reconstructed G1 bus behind the same {@link org.parpe.serial.servo.ServoBus} interface,
 * and {@link org.parpe.serial.servo.host.ServoBuses} opens the right one (public API).
 */
package org.parpe.serial.servo.host;
