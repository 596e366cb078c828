package org.parpe.sim.build;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.List;
import org.parpe.core.edit.ElementWriter;
import org.parpe.sim.config.Connection;
import org.parpe.sim.config.PartSpec;
import org.parpe.sim.config.PartType;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RootPose;

/**
 * A configuration written out as the text of a configuration file (the format of
 * {@code docs/simulator.md}, laid out as the examples are), for "Make editable": parts, then
 * connections, then roots; attributes at their defaults left out; numbers written so that they
 * read back to the same double.
 */
final class ConfigText {
    private ConfigText() {
    }

    /** The text of {@code c}, made by generator {@code spec} (named in a comment). */
    static String of(RobotConfig c, String spec) {
        List<String> lines = new ArrayList<>();
        for (PartSpec p : c.parts()) {
            lines.add(part(p));
        }
        for (Connection k : c.connections()) {
            lines.add(connect(k.from() + "." + k.fromPlate(), k.to() + "." + k.toPlate(), k.quarterTurns()));
        }
        for (RootPose r : c.roots()) {
            ElementWriter e = ElementWriter.tag("root").attr("part", r.part());
            attr(e, "x", r.x(), 0);
            attr(e, "y", r.y(), 0);
            attr(e, "roll", r.roll(), 0);
            attr(e, "pitch", r.pitch(), 0);
            attr(e, "yaw", r.yaw(), 0);
            attr(e, "height", r.height(), RootPose.RESTING);
            lines.add(e.empty());
        }
        return "<?xml version=\"1.0\" ?>\n<!-- Made editable from the generator " + ElementWriter.text(spec)
                .replace("--", "- -") + ". -->\n" + ElementWriter.tag("robot-config").lines("", lines) + "\n";
    }

    /** A {@code <part>}: name and type, a segment's id, angle and limp, a hub's plates, each left out at its default. */
    static String part(PartSpec p) {
        ElementWriter e = ElementWriter.tag("part").attr("name", p.name()).attr("type", p.type().xmlName());
        if (p.isSegment()) {
            e.attr("id", String.valueOf(p.moduleId()));
            attr(e, "angle", p.angle(), 0);
            if (p.limp()) {
                e.attr("limp", "true");
            }
        }
        if (p.type() == PartType.HUB && p.plates() != PartType.HUB.defaultPlates()) {
            e.attr("plates", String.valueOf(p.plates()));
        }
        return e.empty();
    }

    /** A {@code <connect>} of plates {@code from} and {@code to} ("part.plate"), the orientation left out at 0. */
    static String connect(String from, String to, int quarterTurns) {
        ElementWriter e = ElementWriter.tag("connect").attr("from", from).attr("to", to);
        if (quarterTurns != 0) {
            e.attr("orientation", String.valueOf(quarterTurns * 90));
        }
        return e.empty();
    }

    private static void attr(ElementWriter e, String name, double value, double fallback) {
        if (value != fallback) {
            e.attr(name, number(value));
        }
    }

    /** {@code d} in plain decimals that read back to {@code d}: "90", "-20", "0.0125". */
    static String number(double d) {
        if (d == Math.rint(d) && Math.abs(d) < 1e15) {
            return String.valueOf((long) d);
        }
        return BigDecimal.valueOf(d).stripTrailingZeros().toPlainString();
    }
}
