package org.parpe.sim.world;

import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.xml.FlatXmlFile;

/** The scoring elements of a world file; read after the zones and objects they name. */
final class ScoringReader {
    private final WorldReader r;
    private final List<World.Region> zones;
    private final Scenery scenery;
    private World.Goal goal;
    private double pathPerMetre;
    private final List<World.Delivery> deliveries = new ArrayList<>();
    private final List<World.Presses> presses = new ArrayList<>();
    private double maxTilt = Double.NaN;
    private boolean leaveArena;
    private boolean disqualifySeen;

    ScoringReader(WorldReader r, List<World.Region> zones, Scenery scenery) {
        this.r = r;
        this.zones = zones;
        this.scenery = scenery;
    }

    World.Scoring read(List<Map.Entry<FlatXmlFile.Element, String>> elements) {
        for (Map.Entry<FlatXmlFile.Element, String> e : elements) {
            Map<String, String> a = e.getKey().attributes();
            SourcePos at = e.getKey().at();
            switch (e.getValue()) {
                case "goal" -> goal(a, at);
                case "path-score" -> {
                    if (r.known(a, at, "path-score", "points-per-metre")) {
                        pathPerMetre = r.num(a, "points-per-metre", 10, at, 0, 1e6);
                    }
                }
                case "deliver" -> {
                    if (r.known(a, at, "deliver", "zone", "objects", "points")
                            && r.required(a, at, "deliver", "zone", "objects")) {
                        World.Region z = zone(a.get("zone"), at);
                        String prefix = a.get("objects");
                        if (scenery.objects().stream().noneMatch(o -> o.name().startsWith(prefix))) {
                            r.error(at, Msg.NO_OBJECT_PREFIX, prefix);
                        }
                        deliveries.add(new World.Delivery(z, prefix, r.num(a, "points", 10, at, -1e6, 1e6)));
                    }
                }
                case "press" -> press(a, at);
                default -> disqualify(a, at);
            }
        }
        return new World.Scoring(goal, pathPerMetre, deliveries, presses, maxTilt, leaveArena);
    }

    private void goal(Map<String, String> a, SourcePos at) {
        if (goal != null) {
            r.error(at, Msg.ELEMENT_GIVEN_TWICE, "goal");
            return;
        }
        if (r.known(a, at, "goal", "zone", "points", "per-second-left") && r.required(a, at, "goal", "zone")) {
            goal = new World.Goal(zone(a.get("zone"), at), r.num(a, "points", 100, at, -1e6, 1e6),
                    r.num(a, "per-second-left", 0, at, -1e6, 1e6));
        }
    }

    private void press(Map<String, String> a, SourcePos at) {
        if (r.known(a, at, "press", "lever", "points") && r.required(a, at, "press", "lever")) {
            int lever = scenery.lever(a.get("lever"));
            if (lever < 0) {
                r.error(at, Msg.NO_LEVER_CALLED, a.get("lever"), known(scenery.levers().stream()
                        .map(World.Lever::name).toList()));
                return;
            }
            presses.add(new World.Presses(lever, r.num(a, "points", 10, at, -1e6, 1e6)));
        }
    }

    private void disqualify(Map<String, String> a, SourcePos at) {
        if (disqualifySeen) {
            r.error(at, Msg.ELEMENT_GIVEN_TWICE, "disqualify");
            return;
        }
        disqualifySeen = true;
        if (r.known(a, at, "disqualify", "tilt", "leave-arena")) {
            maxTilt = r.num(a, "tilt", Double.NaN, at, 1, 180);
            String leave = a.getOrDefault("leave-arena", "false");
            if (!leave.equals("true") && !leave.equals("false")) {
                r.error(at, Msg.TRUE_OR_FALSE, "leave-arena", leave);
            }
            leaveArena = leave.equals("true");
        }
    }

    /** The zone called {@code name}, or a placeholder after an error. */
    private World.Region zone(String name, SourcePos at) {
        for (World.Region z : zones) {
            if (z.name().equals(name)) {
                return z;
            }
        }
        r.error(at, Msg.NO_ZONE_CALLED, name, known(zones.stream().map(World.Region::name).toList()));
        return new World.Region(name, 0, 0, 0, 0, at);
    }

    private static Message known(List<String> names) {
        return names.isEmpty() ? Message.of(Msg.WORLD_DEFINES_NONE) : Message.of(Msg.EXPECTED_ONE_OF, String.join(", ", names));
    }
}
