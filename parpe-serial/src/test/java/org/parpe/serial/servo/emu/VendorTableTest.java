package org.parpe.serial.servo.emu;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.parpe.serial.emu.EmulatorListener;
import org.parpe.serial.servo.Registers;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.dynamixel.Dxl2Codec;
import org.parpe.serial.feetech.FeetechCodec;
import org.parpe.serial.servo.wire.Packet;
import org.parpe.serial.servo.wire.PacketCodec;

/**
 * The emulated servos against the makers' documents: registers, errors, instructions and reply
 * timing, each test naming its source. Packets are encoded and decoded by the codecs and executed
 * in process; replies are kept with the time they would leave at.
 */
class VendorTableTest {
    /** A status packet the servos sent, and when. */
    record Reply(int id, int error, byte[] params, long delay, boolean fromRequest, byte[] raw) {
        int le(int off, int size) {
            return PacketCodec.le(params, off, size);
        }
    }

    final List<Reply> replies = new ArrayList<>();
    final List<double[]> goals = new ArrayList<>();
    PacketCodec codec;
    EmulatedServo[] servos;
    ServoResponder responder;

    void servos(String model, int... ids) {
        ServoModel m = ServoModel.named(model);
        goals.clear();
        codec = m.protocol() == ServoProtocol.DXL2 ? new Dxl2Codec() : new FeetechCodec();
        servos = new EmulatedServo[ids.length];
        for (int i = 0; i < ids.length; i++) {
            servos[i] = new EmulatedServo(ids[i], m);
        }
        PacketCodec decoding = codec;
        responder = new ServoResponder(m.protocol(), codec, servos, (packet, len, wait, fromRequest) ->
                decoding.decoder(p -> replies.add(new Reply(p.id, decoding.statusError(p),
                        Arrays.copyOf(p.params, p.length), wait, fromRequest,
                        Arrays.copyOf(p.raw, p.rawLength)))).feed(packet, 0, len),
                new EmulatorListener() {
                    @Override
                    public void onSetpoints(int seq, double[] angles) {
                        goals.add(angles.clone());
                    }
                });
    }

    /** Sends one instruction packet; returns the replies it got. */
    List<Reply> send(int id, int instruction, int... params) {
        byte[] b = new byte[params.length];
        for (int i = 0; i < params.length; i++) {
            b[i] = (byte) params[i];
        }
        byte[] raw = new byte[codec.bufferSize()];
        int n = codec.instruction(raw, id, instruction, b, b.length);
        replies.clear();
        List<Packet> got = new ArrayList<>();
        codec.decoder(p -> {
            Packet copy = new Packet();
            copy.id = p.id;
            copy.code = p.code;
            copy.length = p.length;
            System.arraycopy(p.params, 0, copy.params, 0, p.length);
            got.add(copy);
        }).feed(raw, 0, n);
        responder.execute(got.get(0), System.nanoTime());
        return List.copyOf(replies);
    }

    static String hex(byte[] b) {
        StringBuilder s = new StringBuilder();
        for (byte x : b) {
            s.append(s.length() > 0 ? " " : "").append(String.format("%02X", x & 0xFF));
        }
        return s.toString();
    }

    /** Dynamixel 2.0 Read of {@code len} bytes at {@code addr}. */
    Reply read(int id, int addr, int len) {
        List<Reply> r = send(id, PacketCodec.READ, addr & 0xFF, addr >> 8, len, 0);
        assertEquals(1, r.size(), "one reply to a read");
        return r.get(0);
    }

    /** Dynamixel 2.0 Write; the error number of the reply. */
    int write(int id, int addr, int size, int value) {
        int[] p = new int[2 + size];
        p[0] = addr & 0xFF;
        p[1] = addr >> 8;
        for (int i = 0; i < size; i++) {
            p[2 + i] = value >>> 8 * i & 0xFF;
        }
        List<Reply> r = send(id, PacketCodec.WRITE, p);
        assertEquals(1, r.size(), "one reply to a write");
        return r.get(0).error() & 0x7F;
    }

    /** Servo {@code id} reads {@code {address, size, value}} for each row of a transcribed table. */
    void assertTable(int id, int[][] rows) {
        for (int[] r : rows) {
            assertEquals(r[2], read(id, r[0], r[1]).le(0, r[1]), "address " + r[0]);
        }
    }

    @Test
    void xSeriesRegistersAreTheEManualsInitialValues() {
        // ROBOTIS e-Manual, XL430-W250, "Control Table of EEPROM Area" and "of RAM Area":
        // Model Number 1,060; ID 1 (here the emulated ID); Baud Rate 1; Return Delay Time 250;
        // Operating Mode 3; Max/Min Position Limit 4,095/0; Status Return Level 2.
        servos("xl430-w250", 7);
        // {address, size, value}, as the e-Manual's table gives them (Temperature Limit(31) 72).
        assertTable(7, new int[][] {{0, 2, 1060}, {7, 1, 7}, {8, 1, 1}, {9, 1, 250}, {11, 1, 3}, {48, 4, 4095},
            {52, 4, 0}, {68, 1, 2}, {31, 1, 72}});
        assertTrue(read(7, 144, 2).le(0, 2) > 60, "a Present Input Voltage within the voltage limits");
        assertTrue(read(7, 146, 1).le(0, 1) > 0, "a Present Temperature");
        // Protocol 2.0, Ping: Parameter 3 is the firmware version, the same as Firmware Version(6).
        List<Reply> ping = send(7, PacketCodec.PING);
        assertEquals(read(7, 6, 1).le(0, 1), ping.get(0).le(2, 1));
        assertTrue(ping.get(0).le(2, 1) > 0);
        // The whole table: Indirect Data 56 at 661 is its last address; 662 is beyond it.
        assertEquals(0, read(7, 661, 1).error());
        assertEquals(661, read(7, 632, 2).le(0, 2), "Indirect Address 56 initial value");
        assertEquals(EmulatedServo.ACCESS_ERROR, read(7, 662, 1).error() & 0x7F);
    }

    @Test
    void indirectDataStandsForTheAddressItsIndirectAddressNames() {
        // ROBOTIS e-Manual, X series, Indirect Address and Indirect Data: Indirect Address 1(168)
        // set to 132 makes Indirect Data 1(224) read Present Position's first byte.
        servos("xl430-w250", 1);
        assertEquals(0, write(1, 168, 2, 132));
        assertEquals(read(1, 132, 1).le(0, 1), read(1, 224, 1).le(0, 1));
        assertEquals(0, write(1, 168, 2, 65));
        assertEquals(0, write(1, 224, 1, 1));
        assertEquals(1, read(1, 65, 1).le(0, 1), "LED set through Indirect Data 1");
    }

    @Test
    void xl320RegistersAreItsOwnTable() {
        // ROBOTIS e-Manual, XL-320, Control Table: Model Number 350, Return Delay Time(5) 250,
        // CW/CCW Angle Limit(6, 8) 0/1023, Status Return Level(17) 2, Torque Enable(24).
        servos("xl-320", 2);
        assertTable(2, new int[][] {{0, 2, 350}, {5, 1, 250}, {6, 2, 0}, {8, 2, 1023}, {17, 1, 2}});
        assertEquals(0, write(2, 24, 1, 1));
        assertEquals(EmulatedServo.ACCESS_ERROR, write(2, 8, 2, 600));
        assertEquals(0, write(2, 24, 1, 0));
        assertEquals(0, write(2, 8, 2, 600));
        // Goal Position(30): "CW Angle Limit: the minimum value of Goal Position", CCW the maximum.
        assertEquals(EmulatedServo.DATA_RANGE_ERROR, write(2, 30, 2, 700));
        assertEquals(0, write(2, 30, 2, 600));
    }

    @Test
    void theHostsRegisterAddressesAreTheVendorTablesOwn() {
        // PARPE's host (Registers) and the transcribed vendor tables, written apart, must agree.
        for (ServoModel m : ServoModel.TABLE) {
            if (m.protocol() == ServoProtocol.G1) {
                continue;
            }
            ControlTable t = ControlTable.of(m);
            Registers r = m.registers();
            assertEquals(t.named("Model Number").addr(), r.model(), m.name());
            assertEquals(t.named("Torque Enable").addr(), r.torque(), m.name());
            assertEquals(t.named("Goal Position").addr(), r.goal(), m.name());
            assertEquals(t.named("Goal Position").size(), r.goalSize(), m.name());
            assertEquals(t.named("Present Position").addr(), r.present(), m.name());
            assertEquals(t.named("Present Position").size(), r.presentSize(), m.name());
            assertEquals(t.named(m.protocol() == ServoProtocol.DXL2 ? "Hardware Error Status" : "Status").addr(),
                    r.error(), m.name());
            assertEquals(t.has("Bus Watchdog") ? t.named("Bus Watchdog").addr() : -1, r.watchdog(), m.name());
        }
    }

    @Test
    void writesAreRefusedAsProtocol20Says() {
        // ROBOTIS e-Manual, Protocol 2.0, Status Packet, Error: 0x07 Access Error (read-only
        // address, undefined address, EEPROM while Torque Enable is 1), 0x05 Data Length Error
        // (2 bytes to a 4-byte item), 0x04 Data Range Error (outside the item's range; Goal
        // Position within Min/Max Position Limit, XL430-W250 control table).
        servos("xl430-w250", 1);
        assertEquals(EmulatedServo.ACCESS_ERROR, write(1, 0, 2, 5), "Model Number is read-only");
        assertEquals(EmulatedServo.ACCESS_ERROR, write(1, 14, 1, 0), "address 14 is not defined");
        assertEquals(EmulatedServo.DATA_LENGTH_ERROR, write(1, 116, 2, 100), "2 bytes of Goal Position(116)");
        assertEquals(EmulatedServo.DATA_RANGE_ERROR, write(1, 116, 4, 5000));
        assertEquals(EmulatedServo.DATA_RANGE_ERROR, write(1, 68, 1, 3), "Status Return Level 0 ~ 2");
        assertEquals(0, write(1, 48, 4, 3000), "Max Position Limit with torque off");
        assertEquals(EmulatedServo.DATA_RANGE_ERROR, write(1, 116, 4, 3500), "goal beyond the new limit");
        assertEquals(0, write(1, 64, 1, 1));
        assertEquals(EmulatedServo.ACCESS_ERROR, write(1, 48, 4, 4095), "EEPROM locked while torque is on");
        assertEquals(3000, read(1, 48, 4).le(0, 4), "nothing written");
        assertEquals(0, write(1, 116, 4, 2500));
    }

    @Test
    void aGoalAfterABusWatchdogTripIsADataRangeError() {
        // ROBOTIS e-Manual, X series, Bus Watchdog(98): after the watchdog trips it reads −1 and
        // "the access to Goal Values will be changed to read-only"; writing one then returns a
        // Data Range Error (example, step 6); writing 0 clears the error (step 7).
        servos("xl430-w250", 1);
        assertEquals(0, write(1, 64, 1, 1));
        assertEquals(0, write(1, 98, 1, 1));
        long t = System.nanoTime();
        servos[0].heard(t);
        assertFalse(servos[0].step(t + 10_000_000L, 0.002, 360), "not after 10 ms of a 20 ms watchdog");
        assertTrue(servos[0].step(t + 30_000_000L, 0.002, 360), "tripped after 30 ms");
        assertEquals(0xFF, read(1, 98, 1).le(0, 1));
        assertEquals(EmulatedServo.DATA_RANGE_ERROR, write(1, 116, 4, 3000));
        assertEquals(0, write(1, 98, 1, 0));
        assertEquals(0, write(1, 116, 4, 3000));
    }

    @Test
    void statusReturnLevelDecidesWhatIsAnswered() {
        // ROBOTIS e-Manual, X series, Status Return Level(68): 0 answers PING only, 1 PING and
        // READ, 2 all instructions.
        servos("xl430-w250", 1);
        send(1, PacketCodec.WRITE, 68, 0, 1);
        assertEquals(1, read(1, 68, 1).le(0, 1));
        assertEquals(0, send(1, PacketCodec.WRITE, 65, 0, 1).size(), "no status to a write at level 1");
        assertEquals(1, send(1, PacketCodec.READ, 65, 0, 1, 0).size());
        send(1, PacketCodec.WRITE, 68, 0, 0);
        assertEquals(0, send(1, PacketCodec.READ, 65, 0, 1, 0).size(), "no status to a read at level 0");
        assertEquals(1, send(1, PacketCodec.PING).size(), "Ping is always answered");
    }

    @Test
    void regWriteWaitsForAction() {
        // ROBOTIS e-Manual, Protocol 2.0, Instruction: 0x04 Reg Write registers, 0x05 Action
        // executes it; Registered Instruction(69) tells whether one waits; Action without Reg
        // Write is an Instruction Error (0x02).
        servos("xl430-w250", 1, 2);
        send(1, PacketCodec.WRITE, 64, 0, 1);
        assertEquals(0, send(1, PacketCodec.REG_WRITE, 116, 0, 0x00, 0x0C, 0, 0).get(0).error());
        assertEquals(2048, read(1, 116, 4).le(0, 4), "not yet");
        assertEquals(1, read(1, 69, 1).le(0, 1));
        assertEquals(0, send(PacketCodec.BROADCAST, PacketCodec.ACTION).size(), "no status to a broadcast");
        assertEquals(3072, read(1, 116, 4).le(0, 4));
        assertEquals(0, read(1, 69, 1).le(0, 1));
        assertEquals(EmulatedServo.INSTRUCTION_ERROR, send(2, PacketCodec.ACTION).get(0).error() & 0x7F);
    }

    @Test
    void bulkWriteWritesEachServoItsOwnItem() {
        // ROBOTIS e-Manual, Protocol 2.0, Bulk Write (0x93): ID, address, length and data per device.
        servos("xl430-w250", 1, 2);
        assertEquals(0, send(PacketCodec.BROADCAST, PacketCodec.BULK_WRITE,
                1, 65, 0, 1, 0, 1,
                2, 9, 0, 1, 0, 0).size());
        assertEquals(1, read(1, 65, 1).le(0, 1), "LED of servo 1");
        assertEquals(0, read(2, 9, 1).le(0, 1), "Return Delay Time of servo 2");
    }

    @Test
    void repliesLeaveAfterTheReturnDelayTimeAndABroadcastPingInIdSlots() {
        // ROBOTIS e-Manual, X series, Return Delay Time(9): the status packet follows the
        // instruction after 250 × 2 µs = 500 µs by default. Protocol 2.0, Ping: to a broadcast Ping
        // all devices answer "according to their arranged order": ID k in slot k.
        servos("xl430-w250", 200, 3);
        List<Reply> ping = send(PacketCodec.BROADCAST, PacketCodec.PING);
        assertEquals(List.of(3, 200), ping.stream().map(Reply::id).toList());
        assertEquals(500_000 + 3 * ServoResponder.SLOT_NANOS, ping.get(0).delay());
        assertEquals(500_000 + 200 * ServoResponder.SLOT_NANOS, ping.get(1).delay());
        assertTrue(ping.get(1).fromRequest());
        // Sync Read: each answers its Return Delay Time after the one before.
        List<Reply> sync = send(PacketCodec.BROADCAST, PacketCodec.SYNC_READ, 132, 0, 4, 0, 200, 3);
        assertEquals(List.of(200, 3), sync.stream().map(Reply::id).toList());
        assertTrue(sync.get(0).fromRequest() && !sync.get(1).fromRequest());
        assertEquals(500_000, sync.get(1).delay());
        send(3, PacketCodec.WRITE, 9, 0, 0);
        assertEquals(0, read(3, 132, 4).delay(), "Return Delay Time 0");
    }

    @Test
    void fastSyncReadIsAnsweredByOnePacketAsInTheManual() {
        // ROBOTIS e-Manual, "DYNAMIXEL Protocol 2.0", Fast Sync Read (0x8A), example: XM430-W210s
        // with IDs 3, 7 and 4 at Present Position 166, 2 079 and 1 023 answer the request for
        // Present Position (132, 4 bytes) with this one status packet from ID 0xFE.
        servos("xm430-w210", 3, 7, 4);
        ServoModel m = ServoModel.named("xm430-w210");
        servos[0].backDrive(m.tickDegrees(166));
        servos[1].backDrive(m.tickDegrees(2079));
        servos[2].backDrive(m.tickDegrees(1023));
        List<Reply> r = send(PacketCodec.BROADCAST, PacketCodec.FAST_SYNC_READ, 0x84, 0, 4, 0, 3, 7, 4);
        assertEquals(1, r.size(), "one status packet for all three");
        assertEquals("FF FF FD 00 FE 19 00 55 00 03 A6 00 00 00 84 08 00 07 1F 08 00 00 16 CA 00 04 FF 03 00 00 D1 9E",
                hex(r.get(0).raw()));
        assertEquals(500_000, r.get(0).delay(), "after the first servo's Return Delay Time");
        assertTrue(r.get(0).fromRequest());
        // A servo named but absent breaks the chain: the packet never completes.
        assertEquals(0, send(PacketCodec.BROADCAST, PacketCodec.FAST_SYNC_READ, 0x84, 0, 4, 0, 3, 9, 4).size());
    }

    @Test
    void aServoWithoutFastSyncReadAnswersItWithAnInstructionError() {
        // ROBOTIS e-Manual, Protocol 2.0, Status Packet, Error 0x02 Instruction Error: "Undefined
        // Instruction has been used". The XL-320 has no Fast Sync Read (DynamixelSDK's
        // fast_sync_read example: X series except XL-320); an X series servo below firmware v45
        // has none either.
        servos("xl-320", 1, 2);
        List<Reply> r = send(PacketCodec.BROADCAST, PacketCodec.FAST_SYNC_READ, 37, 0, 2, 0, 1, 2);
        assertEquals(List.of(1, 2), r.stream().map(Reply::id).toList());
        assertTrue(r.stream().allMatch(x -> (x.error() & 0x7F) == EmulatedServo.INSTRUCTION_ERROR));
        servos("xm430-w350", 1);
        servos[0].table[ControlTable.X_SERIES.named("Firmware Version").addr()] = 44;
        r = send(PacketCodec.BROADCAST, PacketCodec.FAST_SYNC_READ, 0x84, 0, 4, 0, 1);
        assertEquals(1, r.size());
        assertEquals(EmulatedServo.INSTRUCTION_ERROR, r.get(0).error() & 0x7F);
        assertEquals(1, r.get(0).id());
    }

    @Test
    void feetechStsEepromRegistersAreTheMemoryTablesInitialValues() {
        // FEETECH magnetic-encoder STS servo memory table ("STS Servo - Memory Table Analysis",
        // 2.2 EPROM Configuration, little-endian): ID(5) 1, Baud Rate(6) 0 (1 000 000),
        // Response Status Level(8) 1, Minimum Angle Limit(9) 0, Maximum Angle Limit(11) 4095,
        // Maximum Temperature Limit(13) 70.
        servos("sts3215", 1);
        int[][] rows = {{5, 1, 1}, {6, 1, 0}, {8, 1, 1}, {9, 2, 0}, {11, 2, 4095}, {13, 1, 70}};
        for (int[] r : rows) {
            List<Reply> got = send(1, PacketCodec.READ, r[0], r[1]);
            assertEquals(1, got.size(), "one reply to a read of address " + r[0]);
            assertEquals(r[2], got.get(0).le(0, r[1]), "address " + r[0]);
        }
    }

    @Test
    void feetechStsGoalBit15IsItsSignAndTheLimitsKeepANegativeGoal() {
        // Feetech SCServo/FTServo SDK, SMS_STS.cpp, WritePosEx: a negative position goes out as its
        // magnitude with bit 15 set (scs_toscs(pos, 15)), read back by scs_tohost(pos, 15). STS
        // memory table: Goal Position(42) ranges Min Position Limit(9) ~ Max Position Limit(11).
        // So −100 (0x8064) is below the minimum, 0, and must not read as 32 868, above the maximum.
        servos("sts3215", 1);
        send(1, PacketCodec.WRITE, 40, 1);
        send(1, PacketCodec.WRITE, 42, 0x64, 0x80);
        assertEquals(0, send(1, PacketCodec.READ, 42, 2).get(0).le(0, 2), "goal kept at Min Position Limit");
        assertEquals(ServoModel.named("sts3215").minDegrees(), servos[0].goalDegrees(), 1e-9);
        // Bit 15 clear: an ordinary goal inside the limits is kept as written.
        send(1, PacketCodec.WRITE, 42, 0x64, 0x00);
        assertEquals(100, send(1, PacketCodec.READ, 42, 2).get(0).le(0, 2));
    }

    @Test
    void feetechStsAnswersABroadcastPingAndScsHasNoSyncRead() {
        // Feetech's SCServo library: SMS_STS servos have Sync Read; SCSCL (SCS series) has none,
        // so an SCS servo must not answer one.
        servos("sts3215", 1, 2);
        assertEquals(List.of(1, 2), send(PacketCodec.BROADCAST, PacketCodec.PING).stream().map(Reply::id).toList());
        assertEquals(2, send(PacketCodec.BROADCAST, PacketCodec.SYNC_READ, 56, 2, 1, 2).size());
        servos("scs0009", 1, 2);
        assertEquals(0, send(PacketCodec.BROADCAST, PacketCodec.SYNC_READ, 56, 2, 1, 2).size());
        assertEquals(1, send(1, PacketCodec.READ, 56, 2).size());
    }

    @Test
    void syncWriteGoalsAreReadInTheServosByteOrderFromAnyStartAddress() {
        // Feetech SCS memory table: Goal Position(42) is big-endian on SCS. A Sync Write that starts
        // at Acceleration(41) (as Feetech's SyncWritePosEx does on STS) still sets the goal.
        servos("scs0009", 1);
        send(PacketCodec.BROADCAST, PacketCodec.SYNC_WRITE, 42, 2, 1, 0x02, 0x00 + 0x33);
        assertEquals((0x233 - 512) * 300.0 / 1024, goals.get(0)[0], 1e-9);
        servos("sts3215", 1);
        send(PacketCodec.BROADCAST, PacketCodec.SYNC_WRITE, 41, 7, 1, 0, 0x00, 0x0C, 0, 0, 0, 0);
        assertEquals(1, goals.size());
        assertEquals(90.0, goals.get(0)[0], 1e-9);
    }
}
