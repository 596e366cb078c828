package org.parpe.serial.servo.host;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.parpe.serial.servo.ServoModel;

/** Hardware error bits in words, per model family. */
class FaultsTest {
    @Test
    void xl320BitsAreItsOwnNotTheXSeries() {
        // ROBOTIS e-Manual, XL-320, Shutdown(18): bit 0 Overload, bit 1 OverHeating, bit 2 Input
        // Voltage. They used to be read with X-series meanings (bit 0 "input voltage", bit 2
        // "overheating").
        ServoModel xl320 = ServoModel.named("xl-320");
        assertEquals("overload", Faults.describe(xl320, 0x80, 0x01));
        assertEquals("overheating", Faults.describe(xl320, 0x80, 0x02));
        assertEquals("input voltage out of range", Faults.describe(xl320, 0x80, 0x04));
        // e-Manual, X series, Shutdown(63): bit 0 Input Voltage, bit 2 Overheating, bit 5 Overload.
        ServoModel xl430 = ServoModel.named("xl430-w250");
        assertEquals("input voltage out of range", Faults.describe(xl430, 0x80, 0x01));
        assertEquals("overheating, overload", Faults.describe(xl430, 0x80, 0x24));
    }
}
