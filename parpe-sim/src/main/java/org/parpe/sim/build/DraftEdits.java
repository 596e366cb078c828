package org.parpe.sim.build;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import org.parpe.core.diag.SourceSpan;
import org.parpe.core.edit.ElementWriter;
import org.parpe.core.edit.Replacement;
import org.parpe.core.edit.ScriptEdits;
import org.parpe.core.edit.TextEdit;
import org.parpe.core.xml.FlatXmlFile;
import org.parpe.core.xml.XmlReader;
import org.parpe.sim.geom.Geo;
import org.parpe.sim.geom.Vec3;
import org.parpe.sim.config.Connection;
import org.parpe.sim.config.Kit;
import org.parpe.sim.config.PartSpec;
import org.parpe.sim.config.PartType;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RootPose;
import org.parpe.sim.internal.Assembly;

/**
 * The edits of a {@link RobotDraft}: what each means for the configuration, and when it is
 * refused and why; {@link DraftPlaces} writes them into the text through the edit layer.
 */
final class DraftEdits {
    private static final String ROOT = "robot-config";
    private static final Set<String> POSE = Set.of("x", "y", "roll", "pitch", "yaw", "height");

    private final RobotDraft draft;
    private final String text;
    private final RobotConfig config;
    private final DraftPlaces places;

    DraftEdits(RobotDraft draft) {
        this.draft = draft;
        this.text = draft.text();
        this.config = draft.config();
        this.places = new DraftPlaces(draft);
    }

    BuildEdit first(PartType type, int hubPlates) {
        String refused = checkType(type, hubPlates);
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        String name = freeName(type);
        String part = ConfigText.part(newPart(name, type, 0, hubPlates));
        String what = "Start with " + type.xmlName() + " " + name;
        if (draft.read().root() == null) {
            if (!XmlReader.noElement(text)) {
                return BuildEdit.refuse("the file is not a robot configuration yet; mend it first (see Problems)");
            }
            int end = text.length();
            while (end > 0 && Character.isWhitespace(text.charAt(end - 1))) {
                end--;
            }
            String config = ElementWriter.tag(ROOT).lines("", List.of(part)) + "\n";
            return BuildEdit.of(TextEdit.of(end, text.length() - end, (end == 0 ? "" : "\n") + config), what);
        }
        if (config != null || !draft.problems().isEmpty()) {
            return BuildEdit.refuse(config != null ? "the robot has parts already; add the next one to a free plate"
                    : "the configuration has problems; mend them first (see Problems)");
        }
        List<FlatXmlFile.Element> all = draft.read().elements();
        SourceSpan last = all.isEmpty() ? null : all.get(all.size() - 1).at().span();
        return BuildEdit.of(ScriptEdits.appendChild(text, draft.read().root().span(), ROOT, last, part), what);
    }

    BuildEdit add(String part, int plate, PartType type, int newPlate, int quarterTurns, int hubPlates, Kit kit) {
        String refused = needConfig();
        refused = refused != null ? refused : freePlate(part, plate);
        refused = refused != null ? refused : checkType(type, hubPlates);
        if (refused == null) {
            int plates = type == PartType.HUB ? hubPlates : type.defaultPlates();
            if (newPlate < 0 || newPlate >= plates) {
                refused = "a " + type.xmlName() + " has plates 0.." + (plates - 1) + ", not " + newPlate;
            } else if (quarterTurns < 0 || quarterTurns > 3) {
                refused = "a part is turned 0, 1, 2 or 3 quarter turns, not " + quarterTurns;
            } else if (kit != null && kit.left(config).get(type) <= 0) {
                refused = "the kit has no " + type.count(1).substring(2) + " left (it has " + type.count(kit.owned(type)) + ")";
            }
        }
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        String name = freeName(type);
        String newPart = ConfigText.part(newPart(name, type, freeId(), hubPlates));
        String connect = ConfigText.connect(part + "." + plate, name + "." + newPlate, quarterTurns);
        return BuildEdit.of(places.insert(newPart, connect), "Add " + type.xmlName() + " " + name + " on " + part + "." + plate
                + (quarterTurns == 0 ? "" : " turned " + quarterTurns * 90 + "°"));
    }

    BuildEdit remove(String part) {
        String refused = needConfig();
        int i = refused == null ? draft.tree().index(part) : -1;
        if (refused == null && i < 0) {
            refused = noPart(part);
        }
        List<Integer> gone = i < 0 ? List.of() : draft.tree().hangingOn(i);
        RootPose root = i < 0 ? null : draft.tree().rootOf(i);
        if (refused == null && root != null && root.part().equals(part) && gone.size() > 1) {
            refused = "'" + part + "' is the root and " + (gone.size() - 1) + " part" + (gone.size() == 2 ? "" : "s")
                    + " hang on it; make another part the root first";
        }
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        Set<String> names = new java.util.HashSet<>();
        List<Replacement> out = new ArrayList<>();
        for (int k : gone) {
            PartSpec p = config.parts().get(k);
            names.add(p.name());
            out.addAll(places.removed(p.pos().span()));
        }
        for (Connection c : config.connections()) {
            if (names.contains(c.from()) || names.contains(c.to())) {
                out.addAll(places.removed(c.pos().span()));
            }
        }
        for (RootPose r : config.roots()) {
            if (names.contains(r.part()) && r.pos().span() != null) {
                out.addAll(places.removed(r.pos().span()));
            }
        }
        int more = gone.size() - 1;
        return BuildEdit.of(new TextEdit(out), "Remove " + part
                + (more == 0 ? "" : " and " + more + " part" + (more == 1 ? "" : "s") + " on it"));
    }

    BuildEdit turn(String part, int quarterTurns) {
        String refused = needConfig();
        int i = refused == null ? draft.tree().index(part) : -1;
        Connection c = i < 0 ? null : draft.tree().parent(i);
        if (refused == null) {
            if (i < 0) {
                refused = noPart(part);
            } else if (c == null) {
                refused = "'" + part + "' hangs on no plate (it is a root); turn a part that hangs on it";
            } else if (quarterTurns < 0 || quarterTurns > 3) {
                refused = "a part is turned 0, 1, 2 or 3 quarter turns, not " + quarterTurns;
            } else if (c.quarterTurns() == quarterTurns) {
                refused = "'" + part + "' is turned " + quarterTurns * 90 + "° already";
            }
        }
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        return BuildEdit.of(places.setOrDrop(c.pos(), "orientation", String.valueOf(quarterTurns * 90), quarterTurns == 0),
                "Turn " + part + " to " + quarterTurns * 90 + "°");
    }

    BuildEdit setModuleId(String part, int id) {
        String refused = segment(part);
        PartSpec p = refused == null ? config.part(part).orElseThrow() : null;
        if (refused == null) {
            PartSpec holder = config.parts().stream().filter(q -> q.isSegment() && q.moduleId() == id).findFirst()
                    .orElse(null);
            if (id < 0) {
                refused = "a module ID is 0 or more, not " + id;
            } else if (holder == p) {
                refused = "'" + part + "' has ID " + id + " already";
            } else if (holder != null) {
                refused = "ID " + id + " is used by " + holder.name();
            }
        }
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        return BuildEdit.of(ScriptEdits.setAttribute(text, p.pos(), "id", String.valueOf(id)),
                "Set the ID of " + part + " to " + id);
    }

    BuildEdit setAngle(String part, double degrees) {
        String refused = segment(part);
        PartSpec p = refused == null ? config.part(part).orElseThrow() : null;
        if (refused == null && !(Math.abs(degrees) <= 90)) {
            refused = "an initial angle is within -90..90 degrees, not " + ConfigText.number(degrees);
        } else if (refused == null && p.angle() == degrees) {
            refused = "'" + part + "' starts at " + ConfigText.number(degrees) + "° already";
        }
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        return BuildEdit.of(places.setOrDrop(p.pos(), "angle", ConfigText.number(degrees), degrees == 0),
                "Set the angle of " + part + " to " + ConfigText.number(degrees) + "°");
    }

    BuildEdit setLimp(String part, boolean limp) {
        String refused = segment(part);
        PartSpec p = refused == null ? config.part(part).orElseThrow() : null;
        if (refused == null && p.limp() == limp) {
            refused = "'" + part + "' is " + (limp ? "limp" : "not limp") + " already";
        }
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        return BuildEdit.of(places.setOrDrop(p.pos(), "limp", "true", !limp), "Make " + part + (limp ? " limp" : " stiff"));
    }

    BuildEdit makeRoot(String part) {
        String refused = needConfig();
        int i = refused == null ? draft.tree().index(part) : -1;
        RootPose root = i < 0 ? null : draft.tree().rootOf(i);
        if (refused == null) {
            if (i < 0) {
                refused = noPart(part);
            } else if (root == null) {
                refused = "'" + part + "' is not connected to a root; connect it first";
            } else if (root.part().equals(part)) {
                refused = "'" + part + "' is the root already";
            }
        }
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        String what = "Make " + part + " the root";
        if (root.pos().span() != null) {
            return BuildEdit.of(ScriptEdits.setAttribute(text, root.pos(), "part", part), what);
        }
        return BuildEdit.of(places.appendLast(ElementWriter.tag("root").attr("part", part).empty()), what);
    }

    BuildEdit setRootPose(String attribute, double value) {
        String refused = needConfig();
        RootPose root = refused == null ? config.root() : null;
        double now = 0;
        if (refused == null) {
            now = switch (attribute) {
                case "x" -> root.x();
                case "y" -> root.y();
                case "roll" -> root.roll();
                case "pitch" -> root.pitch();
                case "yaw" -> root.yaw();
                case "height" -> root.height();
                default -> Double.NaN;
            };
            if (!POSE.contains(attribute)) {
                refused = "a root pose has x, y, roll, pitch, yaw and height, not '" + attribute + "'";
            } else if (!Double.isFinite(value) || attribute.equals("height") && value < 0) {
                refused = attribute + " must be a number" + (attribute.equals("height") ? " >= 0" : "") + ", not " + value;
            } else if (now == value) {
                refused = "the root's " + attribute + " is " + ConfigText.number(value) + " already";
            }
        }
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        boolean isDefault = value == (attribute.equals("height") ? RootPose.RESTING : 0);
        String what = "Set the root's " + attribute + " to " + ConfigText.number(value);
        if (root.pos().span() != null) {
            return BuildEdit.of(places.setOrDrop(root.pos(), attribute, ConfigText.number(value), isDefault), what);
        }
        return BuildEdit.of(places.appendLast(ElementWriter.tag("root").attr("part", root.part())
                .attr(attribute, ConfigText.number(value)).empty()), what);
    }

    BuildEdit closeLoop(String a, int plateA, String b, int plateB) {
        String refused = needConfig();
        refused = refused != null ? refused : freePlate(a, plateA);
        refused = refused != null ? refused : freePlate(b, plateB);
        RobotDraft.Plate pa = draft.plate(a, plateA);
        RobotDraft.Plate pb = draft.plate(b, plateB);
        if (refused == null && (pa == null || pb == null)) {
            refused = "the robot does not assemble; mend it first (see Problems)";
        } else if (refused == null && a.equals(b)) {
            refused = "a part cannot be connected to itself";
        }
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        BuildPlate ca = pa.where();
        BuildPlate cb = pb.where();
        double gap = Geo.sub(ca.centre(), cb.centre()).length();
        double angle = Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, -Geo.dot(ca.normal(), cb.normal())))));
        if (gap > Assembly.loopGap() || angle > Math.toDegrees(Assembly.loopTwist())) {
            return BuildEdit.refuse(String.format(Locale.ROOT, "plates %.1f mm and %.1f degrees apart; they must meet"
                    + " within %.0f mm and %.0f degrees", gap * 1000, angle, Assembly.loopGap() * 1000,
                    Math.toDegrees(Assembly.loopTwist())));
        }
        String connect = ConfigText.connect(ca.ref(), cb.ref(), turnsBetween(ca, cb));
        BuildEdit e = BuildEdit.of(places.insert(null, connect), "Close the loop " + ca.ref() + " – " + cb.ref());
        RobotDraft after = draft.apply(e);
        if (after.problems().size() > draft.problems().size()) {
            return BuildEdit.refuse(after.problems().get(after.problems().size() - 1).message());
        }
        return e;
    }

    BuildEdit assignIds() {
        String refused = needConfig();
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        List<Integer> order = new ArrayList<>(draft.tree().chain());
        for (int i = 0; i < config.parts().size(); i++) {
            if (draft.tree().robot(i) < 0) {
                order.add(i);
            }
        }
        List<Replacement> out = new ArrayList<>();
        int next = 0;
        for (int i : order) {
            PartSpec p = config.parts().get(i);
            if (p.isSegment()) {
                int id = next++;
                if (p.moduleId() != id) {
                    out.addAll(ScriptEdits.setAttribute(text, p.pos(), "id", String.valueOf(id)).replacements());
                }
            }
        }
        if (out.isEmpty()) {
            return BuildEdit.refuse(next == 0 ? "the robot has no segment" : "the IDs are in chain order already");
        }
        return BuildEdit.of(new TextEdit(out), "Number the modules in chain order");
    }

    // --- helpers ---

    /** The orientation that turns plate {@code a}'s "up" onto plate {@code b}'s, about {@code a}'s normal. */
    private static int turnsBetween(BuildPlate a, BuildPlate b) {
        int best = 0;
        double bestDot = Double.NEGATIVE_INFINITY;
        for (int q = 0; q < 4; q++) {
            Vec3 up = Geo.mul(Geo.axisAngle(a.normal(), q * Math.PI / 2), a.up());
            double d = Geo.dot(up, b.up());
            if (d > bestDot) {
                bestDot = d;
                best = q;
            }
        }
        return best;
    }

    private String needConfig() {
        if (config != null) {
            return null;
        }
        return draft.problems().isEmpty() ? "the configuration has no part yet; start with a first part"
                : "the configuration has problems; mend them first (see Problems)";
    }

    private String noPart(String part) {
        return "there is no part '" + part + "'";
    }

    /** Null when {@code part} is a segment of a configuration without errors, else why not. */
    private String segment(String part) {
        String refused = needConfig();
        if (refused != null) {
            return refused;
        }
        PartSpec p = config.part(part).orElse(null);
        if (p == null) {
            return noPart(part);
        }
        return p.isSegment() ? null : "'" + part + "' is a " + p.type().xmlName() + "; only segments have module IDs,"
                + " angles and limp";
    }

    /** Null when {@code part.plate} exists and no connection uses it, else why not. */
    private String freePlate(String part, int plate) {
        PartSpec p = config.part(part).orElse(null);
        if (p == null) {
            return noPart(part);
        }
        if (plate < 0 || plate >= p.plates()) {
            return "'" + part + "' (" + p.type().xmlName() + ") has plates 0.." + (p.plates() - 1) + ", not " + plate;
        }
        for (Connection c : config.connections()) {
            if (c.from().equals(part) && c.fromPlate() == plate || c.to().equals(part) && c.toPlate() == plate) {
                return "plate " + part + "." + plate + " is taken (" + c.from() + "." + c.fromPlate() + " to " + c.to()
                        + "." + c.toPlate() + ", line " + c.pos().line() + ")";
            }
        }
        return null;
    }

    private static String checkType(PartType type, int hubPlates) {
        if (type == null) {
            return "choose a part type: segment, node, foot or hub";
        }
        if (type == PartType.HUB && (hubPlates < 3 || hubPlates > 16)) {
            return "a hub has 3..16 plates, not " + hubPlates;
        }
        return null;
    }

    private static PartSpec newPart(String name, PartType type, int id, int hubPlates) {
        return new PartSpec(name, type, type == PartType.SEGMENT ? id : -1, 0,
                type == PartType.HUB ? hubPlates : type.defaultPlates(), false, org.parpe.core.diag.SourcePos.NONE);
    }

    /** The first of {@code s0, s1…} ({@code node0…}, {@code foot0…}, {@code hub0…}) no element of the file names. */
    private String freeName(PartType type) {
        String prefix = type == PartType.SEGMENT ? "s" : type.xmlName();
        Set<String> taken = new java.util.HashSet<>();
        for (FlatXmlFile.Element e : draft.read().elements()) {
            if (e.attributes().containsKey("name")) {
                taken.add(e.attributes().get("name"));
            }
        }
        int n = 0;
        while (taken.contains(prefix + n)) {
            n++;
        }
        return prefix + n;
    }

    /** The lowest module ID no segment has. */
    private int freeId() {
        Set<Integer> taken = new java.util.HashSet<>();
        if (config != null) {
            config.parts().stream().filter(PartSpec::isSegment).forEach(p -> taken.add(p.moduleId()));
        }
        int id = 0;
        while (taken.contains(id)) {
            id++;
        }
        return id;
    }
}
