package org.parpe.serial.servo.profile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.core.diag.Diagnostic;
import org.parpe.serial.bus.SafeMode;
import org.parpe.serial.servo.ServoProtocol;

/** Hardware profiles: what a good one gives, and every problem located at FILE:LINE:COL. */
class ProfileReaderTest {
    @TempDir
    Path dir;
    final List<Diagnostic> diags = new ArrayList<>();

    HardwareProfile read(String xml) throws Exception {
        Path f = dir.resolve("robot.xml");
        Files.writeString(f, xml);
        return ProfileReader.read(f, diags::add);
    }

    List<String> messages() {
        return diags.stream().map(d -> d.format().replace(dir.resolve("robot.xml").toString(), "F")).toList();
    }

    @Test
    void aGoodProfile() throws Exception {
        HardwareProfile p = read("""
                <hardware protocol="dxl2" port="/dev/ttyUSB0" baud="1000000" on-fault="limp">
                  <servo module="0" id="1" model="xm430-w210" zero="12.5" direction="-1" min="-45" max="60"/>
                  <servo module="1" id="2"/>
                </hardware>
                """);
        assertNotNull(p, messages().toString());
        assertEquals(ServoProtocol.DXL2, p.protocol());
        assertEquals("/dev/ttyUSB0", p.port());
        assertEquals(1_000_000, p.baud());
        assertEquals(SafeMode.LIMP, p.onFault());
        assertEquals(HardwareProfile.DEFAULT_WATCHDOG_MS, p.watchdogMs());
        ServoMapping m = p.forModule(0);
        assertEquals(1030, m.model().number());
        assertEquals(-45, m.clamp(-120));
        assertEquals(12.5 - 30, m.servoAngle(30), 1e-9);
        assertEquals(30, m.jointAngle(m.servoAngle(30)), 1e-9);
        assertEquals("xl430-w250", p.forModule(1).model().name());
        assertEquals(-90, p.forModule(1).min());
    }

    @Test
    void writtenProfilesReadBackEqual() throws Exception {
        HardwareProfile p = read("""
                <hardware protocol="sts" watchdog="0">
                  <servo module="3" id="7" zero="-4.25" direction="-1" min="-80" max="75.5"/>
                </hardware>
                """);
        HardwareProfile q = read(ProfileWriter.toXml(p, "written by a test"));
        assertNotNull(q, messages().toString());
        ServoMapping a = p.servos().get(0);
        ServoMapping b = q.servos().get(0);
        assertEquals(List.of(a.module(), a.servo(), a.model(), a.zero(), a.direction(), a.min(), a.max()),
                List.of(b.module(), b.servo(), b.model(), b.zero(), b.direction(), b.min(), b.max()));
        assertEquals(-4.25, b.zero());
        assertEquals(1_000_000, q.baud());
        assertNull(q.port());
    }

    @Test
    void everyProblemIsReportedWithItsPlace() throws Exception {
        assertNull(read("""
                <hardware protocol="dxl2" speed="3">
                  <servo module="0" id="1" model="sts3215"/>
                  <servo module="1" id="300"/>
                  <servo module="2" id="2" direction="2"/>
                  <servo module="2" id="3"/>
                  <servo module="4" id="3"/>
                  <servo id="5"/>
                  <servo module="6" id="6" min="10" max="5"/>
                  <servo module="7" id="8" model="xl-320" zero="100"/>
                  <motor/>
                </hardware>
                """));
        assertEquals(List.of(
                "F:1:1: error: <hardware> has no attribute 'speed'; it takes baud, on-fault, port, protocol, watchdog",
                "F:2:3: error: unknown dxl2 servo model 'sts3215'; expected one of xl430-w250, 2xl430-w250, xl330-m077, "
                        + "xl330-m288, xm430-w350, xm430-w210, xc430-w150, xl-320",
                "F:3:3: error: id must be in 0..252, got 300",
                "F:4:3: error: direction must be in -1..1, got 2",
                "F:5:3: error: module 2 is mapped twice; first at F:4:3",
                "F:6:3: error: servo ID 3 drives two modules (2 at F:5:3 and 4)",
                "F:7:3: error: <servo> needs the attribute 'module'",
                "F:8:3: error: min must be below max, got min 10 and max 5",
                "F:9:3: error: joint angle 90° is servo angle 190°, outside the xl-320's range -150..149.71°; "
                        + "narrow min/max or change zero",
                "F:10:3: error: unknown element <motor> in <hardware>; expected <servo>"),
                sorted(messages()));
    }

    @Test
    void numbersAreThePlainDecimalsOfScripts() throws Exception {
        assertNull(read("""
                <hardware protocol="dxl2">
                  <servo module="0" id="1" zero="1d"/>
                  <servo module="1" id="0x2"/>
                  <servo module="2" id="3" zero="\u0663"/>
                </hardware>
                """));
        assertEquals(List.of(
                "F:2:3: error: zero must be a number, got '1d'",
                "F:3:3: error: id must be a whole number, got '0x2'",
                "F:4:3: error: zero must be a number, got '\u0663'"),
                sorted(messages()));
    }

    static List<String> sorted(List<String> l) {
        return l.stream().sorted(java.util.Comparator.comparingInt(s -> Integer.parseInt(s.split(":")[1]))).toList();
    }

    @Test
    void notAProfile() throws Exception {
        assertNull(read("<program name=\"x\"/>"));
        assertEquals(List.of("F:1:1: error: <program> is not a hardware profile but a PARSL script; expected a "
                + "<hardware protocol=\"…\"> element with <servo> elements"), messages());
        diags.clear();
        assertNull(read("<hardware protocol=\"can\"><servo module=\"0\" id=\"1\"/>"));
        assertEquals(1, diags.size());
        assertEquals(true, messages().get(0).startsWith("F:1:"), messages().toString());
    }

    @Test
    void dynamixelId253IsRefused() throws Exception {
        // e-Manual, Protocol 2.0, Packet ID: "Range: 0 ~ 252"; 253 (0xFD) is not used, it would
        // look like a header byte. Feetech IDs go to 253 (254 is their broadcast).
        assertNull(read("<hardware protocol=\"dxl2\">\n  <servo module=\"0\" id=\"253\"/>\n</hardware>\n"));
        assertEquals(List.of("F:2:3: error: id must be in 0..252, got 253"), messages());
        diags.clear();
        assertNotNull(read("<hardware protocol=\"sts\">\n  <servo module=\"0\" id=\"253\"/>\n</hardware>\n"),
                messages().toString());
    }

    @Test
    void badIdsDoNotCascadeIntoDuplicates() throws Exception {
        // Before, each bad ID fell back to 0 and clashed with every earlier one: 2 000 bad lines
        // gave about 2 million errors.
        StringBuilder xml = new StringBuilder("<hardware protocol=\"dxl2\">\n");
        for (int i = 0; i < 2000; i++) {
            xml.append("  <servo module=\"").append(i).append("\" id=\"999\"/>\n");
        }
        assertNull(read(xml.append("</hardware>\n").toString()));
        assertEquals(2000, diags.size());
        assertEquals("F:2:3: error: id must be in 0..252, got 999", messages().get(0));
    }

    @Test
    void withAnUnknownProtocolTheServosAreStillChecked() throws Exception {
        assertNull(read("""
                <hardware protocol="can">
                  <servo module="0" id="1" min="10" max="5"/>
                  <servo module="0" id="2"/>
                </hardware>
                """));
        assertEquals(List.of(
                "F:1:1: error: unknown protocol 'can'; expected one of g1, dxl2, sts, scs",
                "F:2:3: error: min must be below max, got min 10 and max 5",
                "F:3:3: error: module 0 is mapped twice; first at F:2:3"), sorted(messages()));
    }

    @Test
    void anAttributeOfAnotherNamespaceDoesNotOverrideProtocol() throws Exception {
        assertNull(read("""
                <hardware xmlns:x="urn:elsewhere" protocol="sts" x:protocol="dxl2">
                  <servo module="0" id="1"/>
                </hardware>
                """));
        assertEquals(List.of("F:1:1: error: <hardware> has no attribute 'x:protocol'; it takes baud, on-fault, port, "
                + "protocol, watchdog"), messages());
    }
}
