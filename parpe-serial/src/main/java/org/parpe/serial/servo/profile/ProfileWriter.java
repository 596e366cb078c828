package org.parpe.serial.servo.profile;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import org.parpe.core.io.AtomicFiles;

/** Writes a hardware profile (atomically: a crash never leaves half a file). */
public final class ProfileWriter {
    private ProfileWriter() {
    }

    /** The profile as XML; {@code comment} (one line, may be null) goes on top. */
    public static String toXml(HardwareProfile p, String comment) {
        StringBuilder b = new StringBuilder("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        if (comment != null) {
            b.append("<!-- ").append(comment.replace("--", "- -")).append(" -->\n");
        }
        b.append("<hardware protocol=\"").append(p.protocol().key()).append('"');
        if (p.port() != null) {
            b.append(" port=\"").append(escape(p.port())).append('"');
        }
        b.append(" baud=\"").append(p.baud()).append("\" on-fault=\"").append(p.onFault().name().toLowerCase(Locale.ROOT))
                .append("\" watchdog=\"").append(p.watchdogMs()).append("\">\n");
        for (ServoMapping m : p.servos()) {
            b.append(String.format(Locale.ROOT, "  <servo module=\"%d\" id=\"%d\" model=\"%s\" zero=\"%s\" direction=\"%d\""
                    + " min=\"%s\" max=\"%s\"/>\n", m.module(), m.servo(), m.model().name(), num(m.zero()),
                    m.direction(), num(m.min()), num(m.max())));
        }
        return b.append("</hardware>\n").toString();
    }

    /**
     * Writes {@code p} to {@code file} by the output rules ({@link AtomicFiles}): whole or not at
     * all, through a symbolic link to its target, keeping the file's permissions, and never over
     * anything but a regular file.
     */
    public static void write(HardwareProfile p, Path file, String comment) throws IOException {
        AtomicFiles.write(file, toXml(p, comment));
    }

    private static String num(double d) {
        return d == Math.rint(d) ? String.valueOf((long) d) : String.format(Locale.ROOT, "%.2f", d);
    }

    private static String escape(String s) {
        return s.replace("&", "&amp;").replace("\"", "&quot;").replace("<", "&lt;");
    }
}
