package org.parpe.sim.internal;

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
            error(SourcePos.NONE, "configuration '" + config.name() + "' has no parts");
            return false;
        }
        for (org.parpe.sim.config.RootPose root : config.roots()) {
            if (!index.containsKey(root.part())) {
                error(root.pos(), "root part '" + root.part() + "' is not defined"
                        + Names.suggest(root.part(), index.keySet()));
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
                error(p.pos(), "part name '" + p.name() + "' is used twice");
            }
            if (p.isSegment()) {
                if (p.moduleId() < 0) {
                    error(p.pos(), "segment '" + p.name() + "' needs a module id >= 0, got " + p.moduleId());
                } else if (!ids.add(p.moduleId())) {
                    error(p.pos(), "module id " + p.moduleId() + " is used by two segments");
                }
                if (!(Math.abs(p.angle()) <= 90)) {
                    error(p.pos(), "initial angle must be within -90..90 degrees, got " + p.angle());
                }
            }
            if (p.type() == PartType.HUB && (p.plates() < 3 || p.plates() > MAX_HUB_PLATES)) {
                error(p.pos(), "a hub has 3.." + MAX_HUB_PLATES + " plates, got " + p.plates());
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
            error(c.pos(), "part '" + c.from() + "' is connected to itself");
        }
        if (c.quarterTurns() < 0 || c.quarterTurns() > 3) {
            error(c.pos(), "orientation must be 0, 90, 180 or 270 degrees, got " + c.quarterTurns() * 90);
        }
    }

    private boolean checkEnd(Connection c, String part, int plate, Map<String, SourcePos> usedPlates) {
        Integer i = index.get(part);
        if (i == null) {
            error(c.pos(), "part '" + part + "' is not defined" + Names.suggest(part, index.keySet()));
            return false;
        }
        int count = geometries.get(i).plates().size();
        if (plate < 0 || plate >= count) {
            error(c.pos(), "part '" + part + "' (" + config.parts().get(i).type().xmlName() + ") has plates 0.."
                    + (count - 1) + ", got " + plate);
            return false;
        }
        SourcePos first = usedPlates.putIfAbsent(part + "." + plate, c.pos());
        if (first != null) {
            error(c.pos(), "plate " + plate + " of part '" + part + "' is already connected"
                    + (first.line() > 0 ? " (line " + first.line() + ")" : "") + "; a plate takes one connection");
        }
        return true;
    }

    private void error(SourcePos pos, String message) {
        diags.error(pos, message);
        ok = false;
    }
}
