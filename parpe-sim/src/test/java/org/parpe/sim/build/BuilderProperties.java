package org.parpe.sim.build;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;
import net.jqwik.api.Example;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.parpe.core.diag.SourceSpan;
import org.parpe.core.edit.Replacement;
import org.parpe.sim.config.Connection;
import org.parpe.sim.config.PartSpec;
import org.parpe.sim.config.PartType;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RootPose;

/**
 * Issue 33's properties over every example configuration and every generator's robot made
 * editable: opening a file in the builder changes no byte, and a random builder edit changes
 * only the element(s) it names (or inserts after the last part and connection) and the text
 * reads back to the configuration the edit means, worked out here on the model, not by the
 * builder's code. (The exact text of fixed hand edits is in {@link RobotDraftTest}.)
 */
class BuilderProperties {
    private static final List<String> GENERATORS = List.of("snake:n=12", "snake:n=7,axes=alternate", "loop", "wheel",
            "centipede", "humanoid");

    /** Every example configuration, then every generator's robot made editable: {file, text}. */
    static List<String[]> sources() {
        List<String[]> out = new ArrayList<>();
        try (Stream<Path> files = Files.list(Path.of("../examples/configs"))) {
            for (Path f : files.filter(f -> f.toString().endsWith(".xml")).sorted().toList()) {
                out.add(new String[] {f.toString(), Files.readString(f)});
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        for (String g : GENERATORS) {
            out.add(new String[] {g + ".xml", RobotDraft.fromGenerator(g + ".xml", g).text()});
        }
        return out;
    }

    @Example
    void openingAConfigurationChangesNoByte() {
        List<String[]> all = sources();
        assertEquals(6 + GENERATORS.size(), all.size(), "the examples and the generators");
        for (String[] s : all) {
            RobotDraft d = RobotDraft.of(s[0], s[1]);
            assertTrue(d.problems().isEmpty(), s[0] + ": " + d.problems());
            assertEquals(s[1], d.text(), s[0]);
            assertFalse(d.bodies().isEmpty(), s[0]);
        }
    }

    @Property(tries = 400)
    void aBuilderEditChangesOnlyWhatItNamesAndReadsAsItsMeaning(
            @ForAll @IntRange(min = 0, max = 11) int source, @ForAll @IntRange(min = 0, max = 6) int op,
            @ForAll @IntRange(min = 0, max = 1000) int partPick, @ForAll @IntRange(min = 0, max = 15) int plate,
            @ForAll @IntRange(min = 0, max = 3) int turns, @ForAll @IntRange(min = -90, max = 90) int angle,
            @ForAll boolean limp, @ForAll @IntRange(min = 0, max = 3) int typePick, @ForAll @IntRange(min = 0, max = 60) int id) {
        String[] s = sources().get(source);
        RobotDraft d = RobotDraft.of(s[0], s[1]);
        RobotConfig c = d.config();
        PartSpec part = c.parts().get(partPick % c.parts().size());
        if (op == 4 && !d.freePlates().isEmpty()) {
            // a part goes on a free plate: pick one, else the edit is only ever refused as "taken"
            BuildPlate free = d.freePlates().get(partPick % d.freePlates().size());
            part = c.part(free.part()).orElseThrow();
            plate = free.plate();
        }
        String name = part.name();
        PartType type = PartType.values()[typePick];
        int newPlate = type == PartType.HUB ? plate % 6 : plate % type.defaultPlates();
        BuildEdit e = switch (op) {
            case 0 -> d.turn(name, turns);
            case 1 -> d.setModuleId(name, id);
            case 2 -> d.setAngle(name, angle);
            case 3 -> d.setLimp(name, limp);
            case 4 -> d.add(name, plate % part.plates(), type, newPlate, turns, 6, null);
            case 5 -> d.remove(name);
            default -> d.makeRoot(name);
        };
        net.jqwik.api.statistics.Statistics.collect(List.of("turn", "id", "angle", "limp", "add", "remove", "root").get(op),
                e.refused() ? "refused" : "made");
        if (e.refused()) {
            assertFalse(e.refusal().isBlank());
            return;
        }
        assertFalse(e.description().isBlank());
        RobotConfig after = RobotDraft.of(s[0], e.edit().apply(s[1])).config();
        switch (op) {
            case 0 -> turned(c, after, e, name, turns);
            case 1 -> changedPart(c, after, e, new PartSpec(name, part.type(), id, part.angle(), part.plates(), part.limp(), null));
            case 2 -> changedPart(c, after, e, new PartSpec(name, part.type(), part.moduleId(), angle, part.plates(),
                    part.limp(), null));
            case 3 -> changedPart(c, after, e, new PartSpec(name, part.type(), part.moduleId(), part.angle(), part.plates(),
                    limp, null));
            case 4 -> added(c, after, e, name, plate % part.plates(), type, newPlate, turns, s[1]);
            case 5 -> removed(c, after, e, name, s[1]);
            default -> rooted(c, after, e, name);
        }
    }

    // --- what each edit means, on the model ---

    private static void turned(RobotConfig c, RobotConfig after, BuildEdit e, String part, int turns) {
        assertEquals(parts(c), parts(after));
        List<Connection> changed = new ArrayList<>();
        for (int i = 0; i < c.connections().size(); i++) {
            Connection was = c.connections().get(i);
            Connection now = after.connections().get(i);
            assertEquals(List.of(was.from(), was.fromPlate(), was.to(), was.toPlate()),
                    List.of(now.from(), now.fromPlate(), now.to(), now.toPlate()));
            if (was.quarterTurns() != now.quarterTurns()) {
                assertEquals(turns, now.quarterTurns());
                changed.add(was);
            }
        }
        assertEquals(1, changed.size(), "one connection turned");
        assertTrue(changed.get(0).from().equals(part) || changed.get(0).to().equals(part), "the one that holds " + part);
        within(e, changed.get(0).pos().span());
    }

    private static void changedPart(RobotConfig c, RobotConfig after, BuildEdit e, PartSpec now) {
        List<List<Object>> want = new ArrayList<>(parts(c));
        int at = c.parts().indexOf(c.part(now.name()).orElseThrow());
        want.set(at, part(now));
        assertEquals(want, parts(after));
        assertEquals(connections(c), connections(after));
        assertEquals(roots(c), roots(after));
        within(e, c.parts().get(at).pos().span());
    }

    private static void added(RobotConfig c, RobotConfig after, BuildEdit e, String on, int plate, PartType type,
                              int newPlate, int turns, String text) {
        assertEquals(c.parts().size() + 1, after.parts().size());
        PartSpec made = after.parts().get(after.parts().size() - 1);
        assertTrue(c.part(made.name()).isEmpty(), "a fresh name: " + made.name());
        Set<Integer> ids = new HashSet<>();
        c.parts().stream().filter(PartSpec::isSegment).forEach(p -> ids.add(p.moduleId()));
        int lowest = 0;
        while (ids.contains(lowest)) {
            lowest++;
        }
        List<List<Object>> want = new ArrayList<>(parts(c));
        want.add(part(new PartSpec(made.name(), type, type == PartType.SEGMENT ? lowest : -1, 0,
                type == PartType.HUB ? 6 : type.defaultPlates(), false, null)));
        assertEquals(want, parts(after));
        List<List<Object>> links = new ArrayList<>(connections(c));
        links.add(List.of(on, plate, made.name(), newPlate, turns));
        assertEquals(links, connections(after));
        assertEquals(roots(c), roots(after));
        int lastPart = c.parts().get(c.parts().size() - 1).pos().span().end();
        int lastConnect = c.connections().isEmpty() ? lastPart
                : c.connections().get(c.connections().size() - 1).pos().span().end();
        for (Replacement r : e.edit().replacements()) {
            assertEquals(0, r.length(), "only inserted");
            assertTrue(r.offset() == lastPart || r.offset() == lastConnect, "after the last part or connection: " + r);
        }
        assertTrue(text.length() < e.edit().apply(text).length());
    }

    private static void removed(RobotConfig c, RobotConfig after, BuildEdit e, String part, String text) {
        Set<String> gone = cut(c, part);
        List<List<Object>> want = parts(c).stream().filter(p -> !gone.contains((String) p.get(0))).toList();
        assertEquals(want, after == null ? List.of() : parts(after));
        if (after != null) {
            assertEquals(connections(c).stream().filter(k -> !gone.contains((String) k.get(0))
                    && !gone.contains((String) k.get(2))).toList(), connections(after));
        }
        Set<Integer> starts = new HashSet<>();
        c.parts().stream().filter(p -> gone.contains(p.name())).forEach(p -> starts.add(p.pos().span().start()));
        c.connections().stream().filter(k -> gone.contains(k.from()) || gone.contains(k.to()))
                .forEach(k -> starts.add(k.pos().span().start()));
        c.roots().stream().filter(r -> gone.contains(r.part()) && r.pos().span() != null)
                .forEach(r -> starts.add(r.pos().span().start()));
        for (Replacement r : e.edit().replacements()) {
            String cut = text.substring(r.offset(), r.end()).strip();
            assertTrue(r.text().isEmpty() && cut.endsWith("/>") && starts.remove(text.indexOf(cut, r.offset())),
                    "a whole element of a removed part: " + cut);
        }
        assertTrue(starts.isEmpty(), "every element of the removed parts: " + starts);
    }

    private static void rooted(RobotConfig c, RobotConfig after, BuildEdit e, String part) {
        assertEquals(parts(c), parts(after));
        assertEquals(connections(c), connections(after));
        List<List<Object>> was = roots(c);
        List<List<Object>> now = roots(after);
        assertEquals(was.size(), now.size());
        int changed = 0;
        for (int i = 0; i < was.size(); i++) {
            if (!was.get(i).equals(now.get(i))) {
                changed++;
                assertEquals(part, now.get(i).get(0));
                assertEquals(was.get(i).subList(1, 7), now.get(i).subList(1, 7), "the pose stays");
                if (c.roots().get(i).pos().span() != null) {
                    within(e, c.roots().get(i).pos().span());
                }
            }
        }
        assertEquals(1, changed);
    }

    /** The parts {@code part}'s robot no longer holds when it is taken away, and it. */
    private static Set<String> cut(RobotConfig c, String part) {
        Set<String> robot = reach(c, null, c.roots().stream().filter(r -> reach(c, null, r.part()).contains(part))
                .findFirst().orElseThrow().part());
        String root = c.roots().stream().filter(r -> robot.contains(r.part())).findFirst().orElseThrow().part();
        Set<String> kept = root.equals(part) ? Set.of() : reach(c, part, root);
        Set<String> gone = new HashSet<>(robot);
        gone.removeAll(kept);
        return gone;
    }

    /** The parts reached from {@code from} along connections without passing {@code without}. */
    private static Set<String> reach(RobotConfig c, String without, String from) {
        Set<String> seen = new HashSet<>(List.of(from));
        Deque<String> queue = new ArrayDeque<>(List.of(from));
        while (!queue.isEmpty()) {
            String p = queue.poll();
            for (Connection k : c.connections()) {
                String other = k.from().equals(p) ? k.to() : k.to().equals(p) ? k.from() : null;
                if (other != null && !other.equals(without) && seen.add(other)) {
                    queue.add(other);
                }
            }
        }
        return seen;
    }

    /** Every replacement of {@code e} inside the start tag of the element at {@code s}. */
    private static void within(BuildEdit e, SourceSpan s) {
        assertNotNull(s);
        for (Replacement r : e.edit().replacements()) {
            assertTrue(r.offset() > s.start() && r.end() <= s.tagEnd(), r + " inside " + s);
        }
    }

    private static List<Object> part(PartSpec p) {
        return List.of(p.name(), p.type(), p.moduleId(), p.angle(), p.plates(), p.limp());
    }

    private static List<List<Object>> parts(RobotConfig c) {
        return c.parts().stream().map(BuilderProperties::part).toList();
    }

    private static List<List<Object>> connections(RobotConfig c) {
        return c.connections().stream().map(k -> List.<Object>of(k.from(), k.fromPlate(), k.to(), k.toPlate(),
                k.quarterTurns())).toList();
    }

    private static List<List<Object>> roots(RobotConfig c) {
        return c.roots().stream().map(BuilderProperties::root).toList();
    }

    private static List<Object> root(RootPose r) {
        return List.of(r.part(), r.x(), r.y(), r.roll(), r.pitch(), r.yaw(), r.height());
    }
}
