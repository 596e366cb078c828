package org.parpe.sim.config;

import java.util.Locale;

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

    /** {@code n} parts of this type in words: "1 segment", "12 segments", "2 feet". */
    public String count(long n) {
        String word = this == FOOT ? (n == 1 ? "foot" : "feet") : xmlName() + (n == 1 ? "" : "s");
        return n + " " + word;
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
