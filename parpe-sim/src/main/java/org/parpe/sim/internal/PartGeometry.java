package org.parpe.sim.internal;

import java.util.ArrayList;
import java.util.List;
import org.parpe.sim.geom.BodyShape;
import org.parpe.sim.geom.Geo;
import org.parpe.sim.geom.Mat3;
import org.parpe.sim.geom.PartKind;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.config.PartSpec;

/**
 * The rigid pieces and connection plates of one part, in the part's own frame. A segment's
 * frame has its origin on the hinge axis, x from plate 0 to plate 1 and z along the joint axis
 * (PARSL.md §10); its second half turns about z by the joint angle.
 */
public final class PartGeometry {

    /**
     * A rigid piece in the part frame at joint angle 0.
     *
     * @param kind   what it is
     * @param shape  its shape
     * @param centre its centre in the part frame
     * @param mass   kg
     * @param turns  whether it turns with the joint angle (a segment's second half)
     */
    public record Piece(PartKind kind, BodyShape shape, Vec3 centre, double mass, boolean turns) {
    }

    /**
     * A connection plate in the part frame at joint angle 0.
     *
     * @param piece  index of the piece that carries it
     * @param centre plate centre
     * @param normal outward unit normal
     * @param up     unit "up" direction in the plate (orientation 0 lines these up)
     */
    public record Plate(int piece, Vec3 centre, Vec3 normal, Vec3 up) {
    }

    private final List<Piece> pieces;
    private final List<Plate> plates;

    private PartGeometry(List<Piece> pieces, List<Plate> plates) {
        this.pieces = List.copyOf(pieces);
        this.plates = List.copyOf(plates);
    }

    public List<Piece> pieces() {
        return pieces;
    }

    public List<Plate> plates() {
        return plates;
    }

    /** The geometry of {@code part}. */
    public static PartGeometry of(PartSpec part) {
        return switch (part.type()) {
            case SEGMENT -> segment();
            case NODE -> node();
            case FOOT -> foot();
            case HUB -> hub(part.plates());
        };
    }

    private static PartGeometry segment() {
        double inner = G1.SEGMENT.hingeClearance();
        double outer = G1.SEGMENT.length() / 2;
        double hx = (outer - inner) / 2;
        double cx = (outer + inner) / 2;
        BodyShape box = new BodyShape.Box(hx, G1.HALF, G1.HALF);
        Vec3 up = new Vec3(0, 0, 1);
        return new PartGeometry(
                List.of(new Piece(PartKind.SEGMENT_BASE, box, new Vec3(-cx, 0, 0), G1.SEGMENT.baseMass(), false),
                        new Piece(PartKind.SEGMENT_ARM, box, new Vec3(cx, 0, 0), G1.SEGMENT.armMass(), true)),
                List.of(new Plate(0, new Vec3(-outer, 0, 0), new Vec3(-1, 0, 0), up),
                        new Plate(1, new Vec3(outer, 0, 0), new Vec3(1, 0, 0), up)));
    }

    private static PartGeometry node() {
        double h = G1.NODE.length() / 2;
        BodyShape box = new BodyShape.Box(h, h, h);
        Vec3 z = new Vec3(0, 0, 1);
        Vec3 x = new Vec3(1, 0, 0);
        List<Plate> plates = List.of(
                new Plate(0, new Vec3(h, 0, 0), new Vec3(1, 0, 0), z),
                new Plate(0, new Vec3(-h, 0, 0), new Vec3(-1, 0, 0), z),
                new Plate(0, new Vec3(0, h, 0), new Vec3(0, 1, 0), z),
                new Plate(0, new Vec3(0, -h, 0), new Vec3(0, -1, 0), z),
                new Plate(0, new Vec3(0, 0, h), new Vec3(0, 0, 1), x),
                new Plate(0, new Vec3(0, 0, -h), new Vec3(0, 0, -1), x));
        return new PartGeometry(List.of(new Piece(PartKind.NODE, box, Vec3.ZERO, G1.NODE.mass(), false)), plates);
    }

    private static PartGeometry foot() {
        double hx = G1.FOOT.length() / 2;
        BodyShape box = new BodyShape.Box(hx, G1.HALF, G1.FOOT.width() / 2);
        return new PartGeometry(List.of(new Piece(PartKind.FOOT, box, Vec3.ZERO, G1.FOOT.mass(), false)),
                List.of(new Plate(0, new Vec3(-hx, 0, 0), new Vec3(-1, 0, 0), new Vec3(0, 0, 1))));
    }

    private static PartGeometry hub(int count) {
        double r = G1.hubRadius(count);
        BodyShape disc = new BodyShape.Cylinder(r, G1.HUB.length());
        List<Plate> plates = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            double a = 2 * Math.PI * i / count;
            Vec3 n = new Vec3(Math.cos(a), Math.sin(a), 0);
            plates.add(new Plate(0, Geo.scale(n, r), n, new Vec3(0, 0, 1)));
        }
        return new PartGeometry(List.of(new Piece(PartKind.HUB, disc, Vec3.ZERO, G1.HUB.mass(), false)), plates);
    }

    /** The rotation of a piece relative to the part frame at joint angle {@code angle} (radians). */
    public static Mat3 pieceRotation(Piece piece, double angle) {
        return piece.turns() ? Geo.rotZ(angle) : Mat3.IDENTITY;
    }
}
