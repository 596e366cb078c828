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
import org.parpe.sim.text.SimMsg;

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
        String what = SimMsg.BUILD_START.text(type.xmlName(), name);
        if (draft.read().root() == null) {
            if (!XmlReader.noElement(text)) {
                return BuildEdit.refuse(SimMsg.BUILD_NOT_A_CONFIG.text());
            }
            int end = text.length();
            while (end > 0 && Character.isWhitespace(text.charAt(end - 1))) {
                end--;
            }
            String config = ElementWriter.tag(ROOT).lines("", List.of(part)) + "\n";
            return BuildEdit.of(TextEdit.of(end, text.length() - end, (end == 0 ? "" : "\n") + config), what);
        }
        if (config != null || !draft.problems().isEmpty()) {
            return BuildEdit.refuse((config != null ? SimMsg.BUILD_HAS_PARTS : SimMsg.BUILD_HAS_PROBLEMS).text());
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
                refused = SimMsg.BUILD_TYPE_PLATES.text(type.xmlName(), plates - 1, newPlate);
            } else if (quarterTurns < 0 || quarterTurns > 3) {
                refused = SimMsg.BUILD_QUARTER_TURNS.text(quarterTurns);
            } else if (kit != null && kit.left(config).get(type) <= 0) {
                refused = SimMsg.BUILD_KIT_EMPTY.text(type.noun(), type.count(kit.owned(type)));
            }
        }
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        String name = freeName(type);
        String newPart = ConfigText.part(newPart(name, type, freeId(), hubPlates));
        String connect = ConfigText.connect(part + "." + plate, name + "." + newPlate, quarterTurns);
        return BuildEdit.of(places.insert(newPart, connect), quarterTurns == 0
                ? SimMsg.BUILD_ADD.text(type.xmlName(), name, part + "." + plate)
                : SimMsg.BUILD_ADD_TURNED.text(type.xmlName(), name, part + "." + plate, quarterTurns * 90));
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
            refused = gone.size() == 2 ? SimMsg.BUILD_ROOT_HOLDS_ONE.text(part)
                    : SimMsg.BUILD_ROOT_HOLDS.text(part, gone.size() - 1);
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
        return BuildEdit.of(new TextEdit(out), more == 0 ? SimMsg.BUILD_REMOVE.text(part)
                : more == 1 ? SimMsg.BUILD_REMOVE_WITH_ONE.text(part) : SimMsg.BUILD_REMOVE_WITH.text(part, more));
    }

    BuildEdit turn(String part, int quarterTurns) {
        String refused = needConfig();
        int i = refused == null ? draft.tree().index(part) : -1;
        Connection c = i < 0 ? null : draft.tree().parent(i);
        if (refused == null) {
            if (i < 0) {
                refused = noPart(part);
            } else if (c == null) {
                refused = SimMsg.BUILD_TURN_ROOT.text(part);
            } else if (quarterTurns < 0 || quarterTurns > 3) {
                refused = SimMsg.BUILD_QUARTER_TURNS.text(quarterTurns);
            } else if (c.quarterTurns() == quarterTurns) {
                refused = SimMsg.BUILD_TURNED_ALREADY.text(part, quarterTurns * 90);
            }
        }
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        return BuildEdit.of(places.setOrDrop(c.pos(), "orientation", String.valueOf(quarterTurns * 90), quarterTurns == 0),
                SimMsg.BUILD_TURN.text(part, quarterTurns * 90));
    }

    BuildEdit setModuleId(String part, int id) {
        String refused = segment(part);
        PartSpec p = refused == null ? config.part(part).orElseThrow() : null;
        if (refused == null) {
            PartSpec holder = config.parts().stream().filter(q -> q.isSegment() && q.moduleId() == id).findFirst()
                    .orElse(null);
            if (id < 0) {
                refused = SimMsg.BUILD_ID_NEGATIVE.text(id);
            } else if (holder == p) {
                refused = SimMsg.BUILD_ID_ALREADY.text(part, id);
            } else if (holder != null) {
                refused = SimMsg.BUILD_ID_USED.text(id, holder.name());
            }
        }
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        return BuildEdit.of(ScriptEdits.setAttribute(text, p.pos(), "id", String.valueOf(id)),
                SimMsg.BUILD_SET_ID.text(part, id));
    }

    BuildEdit setAngle(String part, double degrees) {
        String refused = segment(part);
        PartSpec p = refused == null ? config.part(part).orElseThrow() : null;
        if (refused == null && !(Math.abs(degrees) <= 90)) {
            refused = SimMsg.BUILD_ANGLE_RANGE.text(ConfigText.number(degrees));
        } else if (refused == null && p.angle() == degrees) {
            refused = SimMsg.BUILD_ANGLE_ALREADY.text(part, ConfigText.number(degrees));
        }
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        return BuildEdit.of(places.setOrDrop(p.pos(), "angle", ConfigText.number(degrees), degrees == 0),
                SimMsg.BUILD_SET_ANGLE.text(part, ConfigText.number(degrees)));
    }

    BuildEdit setLimp(String part, boolean limp) {
        String refused = segment(part);
        PartSpec p = refused == null ? config.part(part).orElseThrow() : null;
        if (refused == null && p.limp() == limp) {
            refused = (limp ? SimMsg.BUILD_LIMP_ALREADY : SimMsg.BUILD_STIFF_ALREADY).text(part);
        }
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        return BuildEdit.of(places.setOrDrop(p.pos(), "limp", "true", !limp),
                (limp ? SimMsg.BUILD_MAKE_LIMP : SimMsg.BUILD_MAKE_STIFF).text(part));
    }

    BuildEdit makeRoot(String part) {
        String refused = needConfig();
        int i = refused == null ? draft.tree().index(part) : -1;
        RootPose root = i < 0 ? null : draft.tree().rootOf(i);
        if (refused == null) {
            if (i < 0) {
                refused = noPart(part);
            } else if (root == null) {
                refused = SimMsg.BUILD_NOT_CONNECTED.text(part);
            } else if (root.part().equals(part)) {
                refused = SimMsg.BUILD_ROOT_ALREADY.text(part);
            }
        }
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        String what = SimMsg.BUILD_MAKE_ROOT.text(part);
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
                refused = SimMsg.BUILD_POSE_NAMES.text(attribute);
            } else if (!Double.isFinite(value) || attribute.equals("height") && value < 0) {
                refused = attribute.equals("height") ? SimMsg.BUILD_HEIGHT_NUMBER.text(value)
                        : SimMsg.BUILD_POSE_NUMBER.text(attribute, value);
            } else if (now == value) {
                refused = SimMsg.BUILD_POSE_ALREADY.text(attribute, ConfigText.number(value));
            }
        }
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        boolean isDefault = value == (attribute.equals("height") ? RootPose.RESTING : 0);
        String what = SimMsg.BUILD_SET_POSE.text(attribute, ConfigText.number(value));
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
            refused = SimMsg.BUILD_NOT_ASSEMBLED.text();
        } else if (refused == null && a.equals(b)) {
            refused = SimMsg.BUILD_LOOP_SELF.text();
        }
        if (refused != null) {
            return BuildEdit.refuse(refused);
        }
        BuildPlate ca = pa.where();
        BuildPlate cb = pb.where();
        double gap = Geo.sub(ca.centre(), cb.centre()).length();
        double angle = Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, -Geo.dot(ca.normal(), cb.normal())))));
        if (gap > Assembly.loopGap() || angle > Math.toDegrees(Assembly.loopTwist())) {
            return BuildEdit.refuse(SimMsg.BUILD_LOOP_APART.text(fixed("%.1f", gap * 1000), fixed("%.1f", angle),
                    fixed("%.0f", Assembly.loopGap() * 1000), fixed("%.0f", Math.toDegrees(Assembly.loopTwist()))));
        }
        String connect = ConfigText.connect(ca.ref(), cb.ref(), turnsBetween(ca, cb));
        BuildEdit e = BuildEdit.of(places.insert(null, connect), SimMsg.BUILD_CLOSE_LOOP.text(ca.ref(), cb.ref()));
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
            return BuildEdit.refuse((next == 0 ? SimMsg.BUILD_NO_SEGMENT : SimMsg.BUILD_IDS_IN_ORDER).text());
        }
        return BuildEdit.of(new TextEdit(out), SimMsg.BUILD_NUMBER_MODULES.text());
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

    /** {@code value} with {@code format}'s decimals, the same in every language (a measurement, as the file's numbers). */
    private static String fixed(String format, double value) {
        return String.format(Locale.ROOT, format, value);
    }

    private String needConfig() {
        if (config != null) {
            return null;
        }
        return (draft.problems().isEmpty() ? SimMsg.BUILD_NO_PART_YET : SimMsg.BUILD_HAS_PROBLEMS).text();
    }

    private String noPart(String part) {
        return SimMsg.BUILD_NO_PART.text(part);
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
        return p.isSegment() ? null : SimMsg.BUILD_NOT_SEGMENT.text(part, p.type().xmlName());
    }

    /** Null when {@code part.plate} exists and no connection uses it, else why not. */
    private String freePlate(String part, int plate) {
        PartSpec p = config.part(part).orElse(null);
        if (p == null) {
            return noPart(part);
        }
        if (plate < 0 || plate >= p.plates()) {
            return SimMsg.BUILD_PART_PLATES.text(part, p.type().xmlName(), p.plates() - 1, plate);
        }
        for (Connection c : config.connections()) {
            if (c.from().equals(part) && c.fromPlate() == plate || c.to().equals(part) && c.toPlate() == plate) {
                return SimMsg.BUILD_PLATE_TAKEN.text(part + "." + plate, c.from() + "." + c.fromPlate(),
                        c.to() + "." + c.toPlate(), c.pos().line());
            }
        }
        return null;
    }

    private static String checkType(PartType type, int hubPlates) {
        if (type == null) {
            return SimMsg.BUILD_CHOOSE_TYPE.text();
        }
        if (type == PartType.HUB && (hubPlates < 3 || hubPlates > 16)) {
            return SimMsg.BUILD_HUB_PLATES.text(hubPlates);
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
