package org.parpe.sim.config;

import java.util.Locale;
import org.parpe.core.text.Message;
import org.parpe.sim.text.SimMsg;

/**
 * The kinds of PolyBot G1 part a configuration can use. Sizes and masses are documented in
 * {@code docs/simulator.md} and fixed in {@link org.parpe.sim.internal.G1}.
 */
public enum PartType {
    /** An active segment: one hinge between two plates (plate 0 on the servo half, plate 1 on the turning half). */
    SEGMENT(2),
    /** A rigid cube with six plates: 0 +x, 1 −x, 2 +y, 3 −y, 4 +z, 5 −z. */
    NODE(6),
    /** A passive foot pad with one plate (0). */
    FOOT(1),
    /** A passive wheel hub, a disc with {@code plates} plates round its rim (default 8). */
    HUB(8);

    private final int defaultPlates;

    PartType(int defaultPlates) {
        this.defaultPlates = defaultPlates;
    }

    /** The number of plates of a part of this type unless the configuration says otherwise (hubs only). */
    public int defaultPlates() {
        return defaultPlates;
    }

    /** The name used in configuration files ({@code segment}, {@code node}, {@code foot}, {@code hub}). */
    public String xmlName() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The part's name in the user's language, for messages ("segment", "Nabe"); files use {@link #xmlName}. */
    public Message noun() {
        return Message.of(switch (this) {
            case SEGMENT -> SimMsg.PART_SEGMENT;
            case NODE -> SimMsg.PART_NODE;
            case FOOT -> SimMsg.PART_FOOT;
            case HUB -> SimMsg.PART_HUB;
        });
    }

    /** {@code n} parts of this type in the user's words: "1 segment", "12 segments", "2 feet", "2 Füße". */
    public Message count(long n) {
        if (n == 1) {
            return Message.of(SimMsg.PART_ONE, noun());
        }
        return Message.of(switch (this) {
            case SEGMENT -> SimMsg.PART_SEGMENTS;
            case NODE -> SimMsg.PART_NODES;
            case FOOT -> SimMsg.PART_FEET;
            case HUB -> SimMsg.PART_HUBS;
        }, n);
    }

    /** The type called {@code name} in configuration files, or {@code null}. */
    public static PartType ofXmlName(String name) {
        for (PartType t : values()) {
            if (t.xmlName().equals(name)) {
                return t;
            }
        }
        return null;
    }
}
