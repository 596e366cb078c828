package org.parpe.serial.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** Opening devices that are no serial port: the message says so. */
class SerialLinkTest {
    @Test
    void aDeviceThatIsNoSerialPortIsNamedSo() {
        // /dev/null is a character device but no terminal: it used to read "error 25; is another
        // program using it?".
        assumeTrue(Files.exists(Path.of("/dev/null")) && !System.getProperty("os.name").startsWith("Windows"));
        LinkException e = assertThrows(LinkException.class, () -> SerialLink.open("/dev/null", 57_600));
        assertEquals("/dev/null is not a serial device (error 25: it does not take serial port settings)",
                e.getMessage());
    }
}
