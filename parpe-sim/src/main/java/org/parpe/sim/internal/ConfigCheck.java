package org.parpe.sim.internal;

import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;
import org.parpe.core.expr.Names;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.diag.SourcePos;
import org.parpe.sim.config.Connection;
import org.parpe.sim.config.PartSpec;
import org.parpe.sim.config.PartType;
import org.parpe.sim.config.RobotConfig;

/** Checks the parts and connections of a configuration before it is placed; reports all problems. */
final class ConfigCheck {
    /** Most plates a hub may have. */
    static final int MAX_HUB_PLATES = 16;

    private final RobotConfig config;
    private final DiagnosticSink diags;
    private final Map<String, Integer> index = new HashMap<>();
    private final List<PartGeometry> geometries = new ArrayList<>();
    private boolean ok = true;

    ConfigCheck(RobotConfig config, DiagnosticSink diags) {
        this.config = config;
        this.diags = diags;
    }

    List<PartGeometry> geometries() {
        return geometries;
    }

    boolean run() {
        checkParts();
        if (config.parts().isEmpty()) {
            error(SourcePos.NONE, Msg.CONFIG_HAS_NO_PARTS, config.name());
            return false;
        }
        for (org.parpe.sim.config.RootPose root : config.roots()) {
            if (!index.containsKey(root.part())) {
                error(root.pos(), Msg.ROOT_PART_NOT_DEFINED, root.part(), Names.suggest(root.part(), index.keySet()));
            }
        }
        Map<String, SourcePos> usedPlates = new HashMap<>();
        for (Connection c : config.connections()) {
            checkConnection(c, usedPlates);
        }
        return ok;
    }

    private void checkParts() {
        Set<Integer> ids = new HashSet<>();
        for (PartSpec p : config.parts()) {
            if (index.putIfAbsent(p.name(), index.size()) != null) {
                error(p.pos(), Msg.PART_NAME_TWICE, p.name());
            }
            if (p.isSegment()) {
                if (p.moduleId() < 0) {
                    error(p.pos(), Msg.SEGMENT_ID_NEGATIVE, p.name(), p.moduleId());
                } else if (!ids.add(p.moduleId())) {
                    error(p.pos(), Msg.MODULE_ID_TWICE, p.moduleId());
                }
                if (!(Math.abs(p.angle()) <= 90)) {
                    error(p.pos(), Msg.INITIAL_ANGLE_RANGE, p.angle());
                }
            }
            if (p.type() == PartType.HUB && (p.plates() < 3 || p.plates() > MAX_HUB_PLATES)) {
                error(p.pos(), Msg.HUB_PLATES, MAX_HUB_PLATES, p.plates());
            }
            geometries.add(p.type() == PartType.HUB && (p.plates() < 3 || p.plates() > MAX_HUB_PLATES)
                    ? PartGeometry.of(PartSpec.hub(p.name(), PartType.HUB.defaultPlates()))
                    : PartGeometry.of(p));
        }
    }

    private void checkConnection(Connection c, Map<String, SourcePos> usedPlates) {
        boolean known = checkEnd(c, c.from(), c.fromPlate(), usedPlates);
        known &= checkEnd(c, c.to(), c.toPlate(), usedPlates);
        if (known && c.from().equals(c.to())) {
            error(c.pos(), Msg.CONNECTED_TO_ITSELF, c.from());
        }
        if (c.quarterTurns() < 0 || c.quarterTurns() > 3) {
            error(c.pos(), Msg.BAD_ORIENTATION_DEGREES, c.quarterTurns() * 90);
        }
    }

    private boolean checkEnd(Connection c, String part, int plate, Map<String, SourcePos> usedPlates) {
        Integer i = index.get(part);
        if (i == null) {
            error(c.pos(), Msg.PART_NOT_DEFINED, part, Names.suggest(part, index.keySet()));
            return false;
        }
        int count = geometries.get(i).plates().size();
        if (plate < 0 || plate >= count) {
            error(c.pos(), Msg.PART_PLATES, part, config.parts().get(i).type().xmlName(), count - 1, plate);
            return false;
        }
        SourcePos first = usedPlates.putIfAbsent(part + "." + plate, c.pos());
        if (first != null) {
            error(c.pos(), Msg.PLATE_ALREADY_CONNECTED, plate, part,
                    first.line() > 0 ? Message.of(Msg.LINE_NOTE, first.line()) : Message.EMPTY);
        }
        return true;
    }

    private void error(SourcePos pos, Msg key, Object... args) {
        diags.error(pos, key, args);
        ok = false;
    }
}
