/**
 * {@code parpe export}: writes a PARSL script as portable C (the runtime and the generated
 * tables, plus a host trace program) or as an Arduino sketch folder driving PWM, Dynamixel 2.0
 * or Feetech STS servos, and reports the memory it needs on the board.
 */
package org.parpe.cli.export;
