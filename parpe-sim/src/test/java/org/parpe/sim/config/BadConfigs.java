package org.parpe.sim.config;

import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.run.TargetException;
import org.parpe.sim.SimTarget;

/**
 * Issue 33's bad robot configurations, written once for the tests that read them as a run does
 * ({@link RobotProblemsTest}, {@link ConfigFileTest}) and as the builder opens them
 * ({@code DraftProblemsTest}), which must find the same problems.
 */
public final class BadConfigs {
    /** Three segments bent 90 degrees the same way curl the fourth back into the node (line 6: part 'd'). */
    public static final String OVERLAP = """
            <robot-config>
              <part name="body" type="node"/>
              <part name="a" type="segment" id="0" angle="90"/>
              <part name="b" type="segment" id="1" angle="90"/>
              <part name="c" type="segment" id="2" angle="90"/>
              <part name="d" type="segment" id="3"/>
              <connect from="body.0" to="a.0"/>
              <connect from="a.1" to="b.0"/>
              <connect from="b.1" to="c.0"/>
              <connect from="c.1" to="d.0"/>
            </robot-config>
            """;

    /** Plate 1 of part 'a' connected twice (lines 5 and 6). */
    public static final String PLATE_TWICE = """
            <robot-config>
              <part name="a" type="segment" id="0"/>
              <part name="b" type="segment" id="1"/>
              <part name="c" type="segment" id="2"/>
              <connect from="a.1" to="b.0"/>
              <connect from="a.1" to="c.0"/>
            </robot-config>
            """;

    /** A loop of four segments, one bent 80 degrees instead of 90: its plates stay 10 degrees apart. */
    public static final String OPEN_LOOP = """
            <robot-config>
              <part name="a" type="segment" id="0" angle="90"/>
              <part name="b" type="segment" id="1" angle="90"/>
              <part name="c" type="segment" id="2" angle="90"/>
              <part name="d" type="segment" id="3" angle="80"/>
              <connect from="a.1" to="b.0"/>
              <connect from="b.1" to="c.0"/>
              <connect from="c.1" to="d.0"/>
              <connect from="d.1" to="a.0"/>
            </robot-config>
            """;

    /** A part of a type that does not exist (line 2: part 'w'). */
    public static final String UNKNOWN_TYPE = "<robot-config>\n  <part name=\"w\" type=\"wheel\"/>\n</robot-config>\n";

    private BadConfigs() {
    }

    /** A chain of 10 000 segments; {@code folded}: every other one bent 90 degrees the same way, onto itself. */
    public static String chain(boolean folded) {
        StringBuilder x = new StringBuilder("<robot-config>\n");
        int n = 10_000;
        for (int i = 0; i < n; i++) {
            x.append("  <part name=\"s").append(i).append("\" type=\"segment\" id=\"").append(i)
                    .append(i % 2 == 1 && folded ? "\" angle=\"90\"/>\n" : "\"/>\n");
        }
        for (int i = 0; i + 1 < n; i++) {
            x.append("  <connect from=\"s").append(i).append(".1\" to=\"s").append(i + 1).append(".0\"/>\n");
        }
        return x.append("</robot-config>\n").toString();
    }

    /** 4 096 random bytes, always the same ones: a binary file given as a configuration. */
    public static byte[] noise() {
        byte[] noise = new byte[4096];
        new Random(33).nextBytes(noise);
        return noise;
    }

    /** A configuration whose DOCTYPE declares an external entity reading {@code secret} into a part's name. */
    public static String externalEntity(Path secret) {
        return "<?xml version=\"1.0\"?>\n<!DOCTYPE robot-config [<!ENTITY x SYSTEM \"" + secret.toUri()
                + "\">]>\n<robot-config>\n  <part name=\"&x;\" type=\"segment\" id=\"0\"/>\n</robot-config>\n";
    }

    /** Writes {@code text} to {@code name} in {@code dir}; returns the file. */
    public static Path write(Path dir, String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text);
    }

    /** The problems a run reports for the configuration {@code file}, read, generated and assembled as a run does; it must refuse it. */
    public static List<Diagnostic> runErrors(Path file) {
        return assertThrows(TargetException.class, () -> SimTarget.blueprint(file.toString(), new int[0])).diagnostics();
    }
}
