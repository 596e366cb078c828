package org.parpe.core.diagram;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.parpe.core.expr.EvalContext;
import org.parpe.core.expr.Expression;
import org.parpe.core.load.GroupOverlap;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.BehaviorItem;
import org.parpe.core.model.Conditional;
import org.parpe.core.model.Group;
import org.parpe.core.model.Instance;
import org.parpe.core.model.MainDef;
import org.parpe.core.model.MainEntry;
import org.parpe.core.model.Program;
import org.parpe.core.model.StateDef;
import org.parpe.core.model.Timing;
import org.parpe.core.text.DiagramMsg;

/**
 * Computes the diagrams of a loaded program. Each is a projection of the model; nothing here
 * changes the program or reads a file. The gait diagram is what {@link Gait} records from the
 * engine.
 */
public final class Diagrams {
    private Diagrams() {
    }

    /** The {@code <main>} lane, or empty for a program without {@code <main>}. */
    public static Optional<ProgramLane> program(Program p) {
        return p.mainDef().map(m -> lane(m, p.moduleIds()));
    }

    private static ProgramLane lane(MainDef m, int[] ids) {
        List<ProgramLane.Step> steps = new ArrayList<>();
        for (MainEntry e : m.entries()) {
            List<String> macros = e.macros().stream().map(a -> a.name() + "=" + a.text()).toList();
            steps.add(new ProgramLane.Step(steps.size(), e.behavior(), text(e.time()), text(e.exit()),
                    DockReads.words(e.exit(), ids), macros, e.pos()));
        }
        return new ProgramLane(m.cyclesText() == null ? "1" : m.cyclesText(), steps, m.pos());
    }

    /**
     * The swimlanes of {@code behavior}. Macro groups are resolved with the macro values of the
     * first {@code <main>} entry that invokes the behavior; without one they stay unresolved
     * lanes (and text islands).
     */
    public static Swimlanes swimlanes(Program p, Behavior behavior) {
        MainEntry entry = null;
        int entryIndex = -1;
        if (p.main() != null) {
            for (MainEntry e : p.main().entries()) {
                if (e.behavior().equals(behavior.name())) {
                    entry = e;
                    entryIndex = p.main().entries().indexOf(e);
                    break;
                }
            }
        }
        List<Placed> placed = new ArrayList<>();
        place(behavior.items(), new ArrayList<>(), placed);
        List<TextIsland> islands = new ArrayList<>();
        List<Group> groups = new ArrayList<>();
        List<Boolean> mirrors = new ArrayList<>();
        for (Placed x : placed) {
            MainEntry.GroupRef ref = entry != null ? entry.groupOf(x.instance) : x.instance.groupRef();
            Group g = entry != null ? entry.boundGroup(x.instance) : x.instance.on();
            if (g == null) {
                islands.add(new TextIsland(DiagramMsg.MACRO_WITHOUT_VALUE.text(x.instance.group()),
                        x.instance.pos()));
            }
            groups.add(g);
            mirrors.add(ref.mirror());
        }
        GroupOverlap overlap = new GroupOverlap();
        Map<String, List<Swimlanes.Bar>> bars = new LinkedHashMap<>();
        Map<String, List<Integer>> modules = new LinkedHashMap<>();
        for (int i = 0; i < placed.size(); i++) {
            Placed x = placed.get(i);
            Group g = groups.get(i);
            List<Integer> others = new ArrayList<>();
            int shared = -1;
            for (int j = 0; j < placed.size(); j++) {
                Integer s = j == i || g == null || groups.get(j) == null ? null : overlap.shared(g, groups.get(j));
                if (s != null) {
                    others.add(j);
                    shared = others.size() == 1 ? s : shared;
                }
            }
            Instance in = x.instance;
            String lane = g == null ? in.groupRef().name() : g.name();
            modules.putIfAbsent(lane, g == null ? List.of() : g.modules());
            bars.computeIfAbsent(lane, k -> new ArrayList<>()).add(new Swimlanes.Bar(i, in.name(), mirrors.get(i),
                    text(in.phase()), text(in.offset()), text(in.period()), text(in.start()), text(in.cycles()),
                    x.conditions, others, shared, in.pos()));
        }
        List<Swimlanes.Lane> lanes = new ArrayList<>();
        bars.forEach((name, list) -> lanes.add(new Swimlanes.Lane(name, modules.get(name), list)));
        return new Swimlanes(behavior.name(), entryIndex, lanes, islands, behavior.pos());
    }

    private record Placed(Instance instance, List<String> conditions) {
    }

    private static void place(List<BehaviorItem> items, List<String> conds, List<Placed> out) {
        for (BehaviorItem item : items) {
            if (item instanceof Conditional c) {
                conds.add(c.condition().text());
                place(c.items(), conds, out);
                conds.remove(conds.size() - 1);
            } else {
                out.add(new Placed((Instance) item, List.copyOf(conds)));
            }
        }
    }

    /**
     * The ring of {@code a}. Arc lengths follow the durations that are constants (parameters
     * are fixed in a loaded program); a duration that depends on the run (a control, a module's
     * own values) gets the mean of the others' share, and a text island says so. Each state
     * carries its pose on the group the automaton is first played on ({@link #pose}).
     */
    public static Ring ring(Program p, Automaton a) {
        Played on = playedOn(p, a);
        Group group = on == null ? null : on.group();
        int n = a.states().size();
        double[] seconds = new double[n];
        double known = 0;
        int count = 0;
        List<TextIsland> islands = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Timing t = a.times().get(i);
            seconds[i] = constant(t.duration());
            if (Double.isNaN(seconds[i])) {
                islands.add(new TextIsland(DiagramMsg.DURATION_WHILE_RUNNING.text(t.duration().text(), a.states().get(i).name()),
                        t.duration().pos()));
            } else {
                known += Math.max(0, seconds[i]);
                count++;
            }
        }
        double mean = count == 0 ? 1 : known / count;
        double total = 0;
        double[] len = new double[n];
        for (int i = 0; i < n; i++) {
            len[i] = Double.isNaN(seconds[i]) ? mean : Math.max(0, seconds[i]);
            total += len[i];
        }
        List<Ring.Arc> arcs = new ArrayList<>();
        double at = 0;
        for (int i = 0; i < n; i++) {
            double share = total > 0 ? len[i] / total : 1.0 / n;
            Timing t = a.times().get(i);
            List<String> angles = a.states().get(i).angles().stream().map(Expression::text).toList();
            List<Double> pose = group == null ? List.of() : pose(p, a.states().get(i), group, on.mirror());
            arcs.add(new Ring.Arc(i, a.states().get(i).name(), t.duration().text(), text(t.exit()), angles, pose,
                    seconds[i], plates(a.states().get(i)), DockReads.words(t.exit(), p.moduleIds()), at, i == n - 1 ? 1.0 : at + share, a.states().get(i).pos()));
            at += share;
        }
        return new Ring(a.name(), a.table(), group == null ? null : (on.mirror() ? "!" : "") + group.name(),
                group == null ? 0 : group.size(), arcs, islands, a.pos());
    }

    /** What entering {@code s} does to the connection plates, in words ("latches plates 0, 1; releases plate 1"), or "". */
    static String plates(StateDef s) {
        List<String> parts = new ArrayList<>();
        if (!s.latch().isEmpty()) {
            parts.add(DiagramMsg.LATCHES.text(plateWords(s.latch())));
        }
        if (!s.unlatch().isEmpty()) {
            parts.add(DiagramMsg.RELEASES.text(plateWords(s.unlatch())));
        }
        return String.join("; ", parts);
    }

    /** {@code plate 0} or {@code plates 0, 1}. */
    static String plateWords(List<Integer> plates) {
        String numbers = String.join(", ", plates.stream().map(String::valueOf).toList());
        return (plates.size() == 1 ? DiagramMsg.PLATE : DiagramMsg.PLATES).text(numbers);
    }

    /** The group an automaton is played on, as bound at load, and whether mirrored. */
    private record Played(Group group, boolean mirror) {
    }

    /** The group of the first instance of {@code a} (behaviors in order), or {@code null}. */
    private static Played playedOn(Program p, Automaton a) {
        for (Behavior b : p.behaviors()) {
            for (Instance in : b.instances()) {
                if (in.name().equals(a.name())) {
                    MainEntry entry = p.main() == null ? null : p.main().entries().stream()
                            .filter(e -> e.behavior().equals(b.name())).findFirst().orElse(null);
                    return new Played(entry != null ? entry.boundGroup(in) : in.on(),
                            (entry != null ? entry.groupOf(in) : in.groupRef()).mirror());
                }
            }
        }
        return null;
    }

    /** At most this many modules of a group are posed on the ring (the rest is "…"). */
    public static final int POSE_MODULES = 12;

    /**
     * The target angles in degrees of {@code s} for the first {@link #POSE_MODULES} modules of
     * {@code g} (negated on a mirrored group, as the engine does), evaluated as the engine
     * evaluates them at the start of a run: controls at their declared values, {@code $index},
     * {@code $count} and {@code $id} of each module. Empty when an angle is known only while
     * running (time, sensors, macros, random numbers) or the state does not fit the group.
     */
    static List<Double> pose(Program p, org.parpe.core.model.StateDef s, Group g, boolean mirror) {
        int n = g.size();
        int k = s.angles().size();
        if (k != 1 && k != n) {
            return List.of();
        }
        EvalContext ctx = new EvalContext();
        ctx.controls = p.controls().stream().mapToDouble(org.parpe.core.model.Control::value).toArray();
        ctx.count = n;
        List<Double> out = new ArrayList<>();
        for (int i = 0; i < Math.min(n, POSE_MODULES); i++) {
            Expression e = s.angles().get(k == 1 ? 0 : i);
            if (!StaticValue.known(e)) {
                return List.of();
            }
            ctx.index = i;
            ctx.id = g.modules().get(i);
            try {
                double v = e.eval(ctx);
                out.add(mirror ? -v : v);
            } catch (org.parpe.core.expr.EvalException x) {
                return List.of();
            }
        }
        return out;
    }

    /**
     * The phase wheel of {@code instance} on its group ({@code group}, resolved by the caller
     * for macro groups). A phase or offset that is not a constant counts as 0, with a text island.
     */
    public static PhaseWheel wheel(Instance instance, Group group) {
        List<TextIsland> islands = new ArrayList<>();
        double phase = cycles(instance.phase(), "phase", islands);
        double offset = cycles(instance.offset(), "offset", islands);
        List<PhaseWheel.Tick> ticks = new ArrayList<>();
        for (int i = 0; i < group.size(); i++) {
            double d = offset + i * phase;
            ticks.add(new PhaseWheel.Tick(i, group.modules().get(i), d - Math.floor(d)));
        }
        return new PhaseWheel(instance.name(), instance.group(), phase, offset, ticks, islands, instance.pos());
    }

    /**
     * The group {@code instance} of {@code behavior} runs on: a macro group resolved with the
     * macro values of the first {@code <main>} entry that invokes the behavior; empty when no
     * entry gives the macro a value.
     */
    public static Optional<Group> groupOf(Program p, Behavior behavior, Instance instance) {
        MainEntry entry = p.main() == null ? null
                : p.main().entries().stream().filter(e -> e.behavior().equals(behavior.name())).findFirst().orElse(null);
        return Optional.ofNullable(entry != null ? entry.boundGroup(instance) : instance.on());
    }

    private static double cycles(Expression e, String what, List<TextIsland> islands) {
        if (e == null) {
            return 0;
        }
        double v = constant(e);
        if (Double.isNaN(v)) {
            islands.add(new TextIsland(DiagramMsg.CYCLES_WHILE_RUNNING.text(what, e.text()), e.pos()));
            return 0;
        }
        return v;
    }

    /** The value of a constant expression, or NaN when it depends on the run. */
    static double constant(Expression e) {
        return e != null && e.isConstant() ? e.eval(new EvalContext()) : Double.NaN;
    }

    private static String text(Expression e) {
        return e == null ? null : e.text();
    }
}
