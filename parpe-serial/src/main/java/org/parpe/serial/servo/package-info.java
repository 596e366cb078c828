/**
 * Servo buses PARPE can drive: the protocols ({@link org.parpe.serial.servo.ServoProtocol}: the
 * reconstructed G1 bus, Dynamixel Protocol 2.0, Feetech STS and SCS), the table of servo models
 * with their units ({@link org.parpe.serial.servo.ServoModel}, the one place where raw ticks
 * become degrees) and the interface of a bus ({@link org.parpe.serial.servo.ServoBus}) (public API).
 */
package org.parpe.serial.servo;
