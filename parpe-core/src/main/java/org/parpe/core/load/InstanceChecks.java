package org.parpe.core.load;

import java.util.List;
import java.util.Map;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.expr.ExprCompiler;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.Group;
import org.parpe.core.model.MainEntry;
import org.parpe.core.model.Robot;
import org.parpe.core.model.StateDef;
import org.parpe.core.sensor.Channel;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;

/**
 * The checks made where an automaton meets a group (PARSL.md §7, §13 rule 13): overlapping
 * unconditional instances, angle-vector lengths, local sensor references and plate actions on
 * modules without a latch (§14). Instances with a
 * concrete group are checked once per behavior; those whose group comes from a macro, once per
 * {@code <main>} entry that invokes the behavior.
 */
final class InstanceChecks {
    private final DiagnosticSink d;
    private final Robot robot;
    private final Map<String, Automaton> automata;
    private final Map<String, List<ExprCompiler.LocalUse>> locals;
    private final GroupOverlap overlap = new GroupOverlap();
    private final Map<String, java.util.Set<Integer>> carried = new java.util.HashMap<>();

    InstanceChecks(DiagnosticSink d, Robot robot, Map<String, Automaton> automata,
                   Map<String, List<ExprCompiler.LocalUse>> locals) {
        this.d = d;
        this.robot = robot;
        this.automata = automata;
        this.locals = locals;
        if (robot != null) {
            robot.sensors().forEach(sd -> carried.put(sd.type(), java.util.Set.copyOf(sd.modules())));
        }
    }

    private boolean carries(int id, String type) {
        return carried.getOrDefault(type, java.util.Set.of()).contains(id);
    }

    /**
     * Checks the instances of a behavior. With {@code args == null} only instances on concrete
     * groups are checked; otherwise those involving macro groups, with these macro values.
     */
    void checkBehavior(String behavior, List<BehaviorResolver.InstanceInfo> infos, Map<String, MainEntry.MacroArg> args) {
        if (robot == null) {
            return;
        }
        Message note = args == null ? Message.EMPTY : Message.of(Msg.IN_THIS_INVOCATION, behavior);
        for (int i = 0; i < infos.size(); i++) {
            BehaviorResolver.InstanceInfo later = infos.get(i);
            Group g = group(later, args);
            if (g == null) {
                continue;
            }
            if ((args == null) == !later.macroGroup()) {
                shape(later, g, note);
            }
            if (later.conditional()) {
                continue;
            }
            for (int j = 0; j < i; j++) {
                BehaviorResolver.InstanceInfo earlier = infos.get(j);
                boolean relevant = args == null ? !later.macroGroup() && !earlier.macroGroup()
                        : later.macroGroup() || earlier.macroGroup();
                Group h = relevant && !earlier.conditional() ? group(earlier, args) : null;
                Integer shared = h == null ? null : overlap.shared(g, h);
                if (shared != null) {
                    d.error(later.model().pos(), Msg.GROUPS_OVERLAP, g.name(), h.name(), shared, note);
                    break;
                }
            }
        }
    }

    private Group group(BehaviorResolver.InstanceInfo info, Map<String, MainEntry.MacroArg> args) {
        String name = info.base();
        if (info.macroGroup()) {
            MainEntry.MacroArg a = args == null ? null : args.get(name);
            if (a == null || a.group() == null) {
                return null;
            }
            name = a.group();
        }
        return robot.group(name).orElse(null);
    }

    private void shape(BehaviorResolver.InstanceInfo info, Group g, Message note) {
        Automaton a = info.model().automaton();
        if (a == null) {
            return;
        }
        int n = g.size();
        for (StateDef s : a.states()) {
            int k = s.angles().size();
            if (k != 1 && k != n) {
                Message what = a.table()
                        ? Message.of(Msg.GAIT_TABLE_ROW, s.name().substring(a.name().length()), a.name())
                        : Msg.named("state", s.name());
                d.error(info.model().pos(), Msg.ANGLE_COUNT, what, k, g.name(),
                        Message.of(n == 1 ? Msg.ONE_MODULE : Msg.N_MODULES, n), n, note);
                return;
            }
        }
        Message latchless = latchless(a, g, info.model().pos());
        if (latchless != null) {
            d.error(info.model().pos(), Msg.WITH_NOTE, latchless, note);
            return;
        }
        for (ExprCompiler.LocalUse u : locals.getOrDefault(a.name(), List.of())) {
            Message problem = local(u, g);
            if (problem != null) {
                d.error(info.model().pos(), Msg.WITH_NOTE, problem, note);
                return;
            }
        }
    }

    /** A problem when a state of {@code a} acts on plates of a module of {@code g} without a latch (PARSL.md §14). */
    private Message latchless(Automaton a, Group g, org.parpe.core.diag.SourcePos at) {
        for (StateDef s : a.states()) {
            if (!s.hasPlateActions()) {
                continue;
            }
            for (int id : g.modules()) {
                if (!robot.actuates(id, "latch")) {
                    // the state's line, and its file only where it is not the instance's (an included file)
                    Message where = s.pos().file().equals(at.file()) ? Message.of(Msg.LINE_N, s.pos().line())
                            : Message.of(Msg.AT_PLACE, s.pos());
                    return Message.of(s.latch().isEmpty() ? Msg.UNLATCHES_WITHOUT_LATCH : Msg.LATCHES_WITHOUT_LATCH,
                            s.name(), where, id, g.name());
                }
            }
        }
        return null;
    }

    private Message local(ExprCompiler.LocalUse u, Group g) {
        Channel c = u.channel();
        if (u.position() >= 0) {
            if (u.position() >= g.size()) {
                return Message.of(Msg.LOCAL_GROUP_TOO_SMALL, u.text(), u.pos(), u.position(), g.name(), g.size());
            }
            int id = g.modules().get(u.position());
            return carries(id, c.sensor()) ? null
                    : Message.of(Msg.LOCAL_MODULE_WITHOUT_SENSOR, u.text(), u.pos(), id, g.name(), c.sensor());
        }
        for (int id : g.modules()) {
            if (!carries(id, c.sensor())) {
                return Message.of(Msg.LOCAL_GROUP_WITHOUT_SENSOR, u.text(), u.pos(), g.name(), c.sensor(), id);
            }
        }
        return null;
    }
}
