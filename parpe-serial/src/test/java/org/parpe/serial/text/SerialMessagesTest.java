package org.parpe.serial.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.parpe.core.text.BundleCheck;
import org.parpe.core.text.ProseLiterals;

/**
 * The translators' check of the servo buses' own messages (docs/cli.md, "Translating PARPE"):
 * {@code mvn -B -o -pl parpe-serial -am test -Dtest=SerialMessagesTest -Dsurefire.failIfNoSpecifiedTests=false}.
 */
class SerialMessagesTest {
    /** Literals that read as prose but are no text for the user in a language, by reason. */
    private static final java.util.Set<String> ALLOWED = java.util.Set.of(
            // a thread's name, for thread dumps
            "servo bus ",
            // faults of PARPE's own (IllegalArgumentException from code, never from a user's input)
            " is not a control-table protocol; use G1Bus", "a setpoint frame covers 1..", " modules, got ",
            // the PARSL comment a pose recording writes into its file (RecordingWriter): part of the file,
            // which a script shared in class keeps whatever the language of whoever recorded it
            " poses of group ", " holds one row per pose; row times are the intervals between captures.\n",
            " plays it ", "over and over", "; include this file to play rec_", " on other groups. -->\n");

    /** Files that hold no words for the user in a language, by reason. */
    private static final java.util.Set<String> NOT_WORDS = java.util.Set.of(
            // the exported sketch's C code and comments (a file format)
            "org/parpe/serial/export/ArduinoSketch.java", "org/parpe/serial/export/ServoTables.java",
            "org/parpe/serial/export/SketchConstants.java", "org/parpe/serial/export/ProgramExport.java",
            // the vendors' names of control-table items, error bits and status errors, as their manuals
            // write them (ROBOTIS e-Manual, Feetech memory table), which a user compares with the manual
            "org/parpe/serial/servo/emu/EmulatedServo.java", "org/parpe/serial/servo/emu/ControlTable.java",
            "org/parpe/serial/servo/emu/ServoResponder.java", "org/parpe/serial/servo/emu/ServoEmulator.java",
            "org/parpe/serial/servo/Registers.java", "org/parpe/serial/servo/host/Faults.java",
            "org/parpe/serial/dynamixel/Dxl2Codec.java", "org/parpe/serial/feetech/FeetechCodec.java");

    @Test
    void everyBundleHasEveryKeyNoOtherAndTheEnglishPlaceholders() {
        List<String> problems = BundleCheck.problems(SerialMsg.BUNDLE, List.of(SerialMsg.values()));
        assertEquals(List.of(), problems, "fix the bundles of org.parpe.serial.text.SerialMsg:\n" + String.join("\n", problems));
    }

    @Test
    void everyKeyIsUsedByTheCode() throws IOException {
        StringBuilder code = new StringBuilder();
        try (Stream<Path> s = Files.walk(Path.of("src/main/java"))) {
            for (Path p : (Iterable<Path>) s.filter(p -> p.toString().endsWith(".java")
                    && !p.endsWith("text/SerialMsg.java"))::iterator) {
                code.append(Files.readString(p));
            }
        }
        List<String> unused = BundleCheck.unusedIn(code, List.of(SerialMsg.values()), "SerialMsg.");
        assertEquals(List.of(), unused, "keys no code uses: remove them from SerialMsg and every bundle");
    }

    /** A serial device that is not there is told in the user's language (before, always in English). */
    @Test
    void aMissingSerialDeviceIsToldInGerman() {
        org.parpe.core.text.Lang.use(java.util.Locale.GERMAN);
        try {
            Exception e = org.junit.jupiter.api.Assertions.assertThrows(org.parpe.serial.link.LinkException.class,
                    () -> org.parpe.serial.link.SerialLink.open("/dev/parpe-no-such-port", 115200));
            assertEquals("das serielle Gerät /dev/parpe-no-such-port gibt es nicht", e.getMessage());
        } finally {
            org.parpe.core.text.Lang.use(java.util.Locale.ENGLISH);
        }
    }

    /** A warning keeps its words apart from the device's, so both are in the user's language. */
    @Test
    void aWarningAndItsDeviceAreInTheSameLanguage() {
        org.parpe.core.text.Message m = org.parpe.core.text.Message.of(SerialMsg.DID_NOT_ANSWER_READS,
                org.parpe.core.text.Message.of(SerialMsg.WHO_SERVO, 3, 0), 3);
        assertEquals("servo 3 (module 0) did not answer 3 reads; reading it less often", m.format(java.util.Locale.ENGLISH));
        assertEquals("Servo 3 (Modul 0) hat auf 3 Abfragen nicht geantwortet; es wird seltener abgefragt",
                m.format(java.util.Locale.GERMAN));
    }

    /**
     * The bus options' checks, the emulators' log lines and {@code parpe scan}'s ID check are told
     * in the user's language (before, always in English): a baud rate of 0, the device the
     * emulator serves going away, an ID beyond Dynamixel 2.0's 252 (ROBOTIS e-Manual, Protocol
     * 2.0, "Packet ID": 0–252).
     */
    @Test
    void busOptionsEmulatorLinesAndTheScannersIdCheckAreToldInGerman() throws Exception {
        org.parpe.core.text.Lang.use(java.util.Locale.GERMAN);
        java.util.concurrent.BlockingQueue<String> events = new java.util.concurrent.LinkedBlockingQueue<>();
        org.parpe.serial.link.PipeLink[] cable = org.parpe.serial.link.PipeLink.pair("kabel");
        try {
            assertEquals("die Baudrate muss in 1..10000000 liegen, ist aber 0", assertThrows(IllegalArgumentException.class,
                    () -> org.parpe.serial.bus.BusConfig.defaults().withBaud(0)).getMessage());
            assertEquals("--ids: dxl2-Servo-IDs sind 0..252, angegeben ist aber 253", assertThrows(IllegalArgumentException.class,
                    () -> org.parpe.serial.servo.host.ServoScanner.checkIds(org.parpe.serial.servo.ServoProtocol.DXL2,
                            new int[] {1, 253})).getMessage());
            boolean[] opened = {false};
            org.parpe.serial.link.LinkOpener once = () -> {
                if (opened[0]) {
                    throw new java.io.IOException("not back");
                }
                opened[0] = true;
                return cable[1];
            };
            try (var emulator = org.parpe.serial.g1.emu.BusEmulator.start(once, org.parpe.serial.emu.EmulatorOptions.of(1),
                    new org.parpe.serial.emu.EmulatorListener() {
                        @Override
                        public void onEvent(String message) {
                            events.add(message);
                        }
                    })) {
                cable[0].close();
                assertEquals("emulator: kabel-b ist geschlossen; es wird gewartet, bis es wieder da ist",
                        events.poll(10, java.util.concurrent.TimeUnit.SECONDS));
            }
        } finally {
            org.parpe.core.text.Lang.use(java.util.Locale.ENGLISH);
        }
    }

    /**
     * Issue 38: "a test fails on any user-visible string literal ... in messages outside the
     * bundles". Every literal of the main code that reads as prose is a text outside the bundles
     * unless {@link #ALLOWED} or {@link #NOT_WORDS} gives its reason.
     */
    @Test
    void noProseLiteralOutsideTheBundles() throws IOException {
        List<String> found = ProseLiterals.inTree(Path.of("src/main/java"), NOT_WORDS::contains,
                ALLOWED::contains);
        assertEquals(List.of(), found, "text for the user outside the bundles: give it a key in SerialMsg\n" + String.join("\n", found));
    }
}
