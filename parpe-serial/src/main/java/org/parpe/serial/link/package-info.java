/**
 * Byte links the bus runs over: a serial device through jSerialComm, and an in-memory pipe
 * pair for tests and benchmarks (public API).
 */
package org.parpe.serial.link;
