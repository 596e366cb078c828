package org.parpe.serial.servo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.parpe.core.diag.SourcePos;
import org.parpe.serial.servo.profile.ServoMapping;

/** Ticks and degrees of the models in the table. */
class ServoModelTest {

    /**
     * Every model of the table is in the documentation's two tables (issue 32, trial changes: a new
     * model is documented): docs/hardware-profile.md with its model number, docs/hardware.md (the
     * models a profile names; G1 modules have none) with its bus and supply.
     */
    @Test
    void everyModelIsDocumented() throws java.io.IOException {
        String profile = java.nio.file.Files.readString(java.nio.file.Path.of("../docs/hardware-profile.md"));
        String hardware = java.nio.file.Files.readString(java.nio.file.Path.of("../docs/hardware.md"));
        java.util.List<String> missing = new java.util.ArrayList<>();
        for (ServoModel m : ServoModel.TABLE) {
            if (!profile.contains(m.name()) || !profile.contains(Integer.toString(m.number()))) {
                missing.add("hardware-profile.md: " + m.name() + " (" + m.number() + ")");
            }
            if (m.protocol() != ServoProtocol.G1 && !hardware.contains("`" + m.name() + "`")) {
                missing.add("hardware.md: " + m.name());
            }
        }
        assertEquals(java.util.List.of(), missing);
    }

    @Test
    void dynamixelXHas4096TicksPerTurnCentredAt2048() {
        ServoModel xl430 = ServoModel.of(ServoProtocol.DXL2, 1060);
        assertEquals("xl430-w250", xl430.name());
        assertEquals(0.0, xl430.degrees(2048, 4), 1e-9);
        assertEquals(90.0, xl430.degrees(3072, 4), 1e-9);
        assertEquals(-180.0, xl430.degrees(0, 4), 1e-9);
        assertEquals(1024, xl430.ticks(-90));
        assertEquals(4095, xl430.ticks(400), "never a goal beyond the servo's range");
        assertEquals(0, xl430.ticks(-400));
        assertEquals(1030, ServoModel.named("XM430-W210").number());
    }

    @Test
    void sts3215UsesBit15AsTheSign() {
        ServoModel sts = ServoModel.named("sts3215");
        assertEquals(777, sts.number());
        assertEquals(-2048 * 360.0 / 4096 - 10 * 360.0 / 4096, sts.degrees(0x8000 | 10, 2), 1e-9);
        assertEquals(0.0, sts.degrees(2048, 2), 1e-9);
        assertEquals(2048 + 512, sts.ticks(45));
    }

    @Test
    void xl320AndScsHave1024Ticks() {
        assertEquals(0.0, ServoModel.of(ServoProtocol.DXL2, 350).degrees(512, 2), 1e-9);
        ServoModel scs = ServoModel.defaultFor(ServoProtocol.SCS);
        // Feetech SCS0009 (sold as Waveshare SC09): "Rotation angle: 300° (0~1023)", "0.293°
        // (300°/1024)" (SC09 servo user guide, Specification). Was 200°: every angle off by ×1.5.
        assertEquals(300.0 / 1024, scs.degreesPerTick(), 1e-12);
        assertEquals(-150.0, scs.minDegrees(), 1e-9);
        assertEquals(512 + 307, scs.ticks(90), "a 90° command lands at 90°, not 135°");
    }

    @Test
    void goalsAreRoundedInwardsOfTheLimits() {
        // XL-320, 300° over 1024 ticks: the nearest tick to 45° is 154 above centre, 45.117°,
        // beyond a 45° limit; the goal must be the tick inside it (44.82°). Failed before: 666.
        ServoModel xl320 = ServoModel.named("xl-320");
        ServoMapping m = new ServoMapping(0, 1, xl320, 0, 1, -45, 45, SourcePos.NONE);
        assertEquals(512 + 153, m.goalTicks(45));
        assertEquals(512 - 153, m.goalTicks(-45));
        ServoMapping reversed = new ServoMapping(0, 1, xl320, 10, -1, -45, 45, SourcePos.NONE);
        for (double joint : new double[] {-45, 45}) {
            double back = reversed.jointAngle(xl320.degrees(reversed.goalTicks(joint), 2));
            assertTrue(back >= -45 && back <= 45, joint + "° sent as " + back + "°");
        }
        assertEquals(512 + 20, m.goalTicks(5.86), "inside the limits the nearest tick");
    }

    @Test
    void unknownModelsAreNull() {
        assertNull(ServoModel.of(ServoProtocol.DXL2, 777));
        assertNull(ServoModel.named("ax-12"));
    }

    @Test
    void g1TicksAreHundredthsOfADegree() {
        ServoModel g1 = ServoModel.defaultFor(ServoProtocol.G1);
        assertEquals(-12.34, g1.degrees(-1234 & 0xFFFF, 2), 1e-9);
        assertEquals(9000, g1.ticks(120));
    }
}
