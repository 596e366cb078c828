package org.parpe.gui.diagram;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.function.IntFunction;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.Severity;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.diagram.BehaviorEdits;
import org.parpe.core.diagram.DiagramEdits;
import org.parpe.core.edit.ScriptEdits;
import org.parpe.core.diagram.Diagrams;
import org.parpe.core.diagram.Gait;
import org.parpe.core.diagram.GaitDiagram;
import org.parpe.core.diagram.GaitTableExpansion;
import org.parpe.core.diagram.Layouts;
import org.parpe.core.diagram.NodePlaces;
import org.parpe.core.diagram.PhaseWheel;
import org.parpe.core.diagram.ProgramLane;
import org.parpe.core.diagram.Ring;
import org.parpe.core.diagram.Scene;
import org.parpe.core.edit.SectionEdits;
import org.parpe.core.diagram.Swimlanes;
import org.parpe.core.edit.TextEdit;
import org.parpe.core.diagram.Workbench;
import org.parpe.core.load.LoadResult;
import org.parpe.core.model.Automaton;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.Group;
import org.parpe.core.model.Instance;
import org.parpe.core.model.Program;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.ScriptRuntimeError;
import org.parpe.gui.editor.ScriptDocument;
import org.parpe.gui.text.PanelMsg;

/**
 * One view of one text: the script loaded from exactly that text, the view's {@link Scene}, the
 * subjects the view can show (behaviors, automata or instances) and, for each node that can be
 * edited here, its fields, each turning a new value into a {@link TextEdit} of that same text
 * through {@link DiagramEdits}. Made off the UI thread; holds no widget.
 *
 * @param text     the text the projection was made from
 * @param file     the file it was loaded as
 * @param view     the view
 * @param subjects what the view can show, by label (empty for program and gait)
 * @param subject  the label of the one shown, or {@code null}
 * @param scene    the drawing, or {@code null} when there is none (see {@code message})
 * @param targets  the editable nodes
 * @param message  why there is no drawing, or what the drawing leaves out; empty if nothing
 * @param wheel    the phase wheel drawn (its handle can be dragged), or {@code null}
 * @param ring     the ring drawn (the live overlay marks its states), or {@code null}
 * @param index    the shapes of the drawing the live overlay marks, by the engine's indices
 * @param lanes    the swimlanes drawn (the live overlay marks the bars driving modules), or {@code null}
 * @param gait     the gait diagram drawn (the live overlay marks the time and each module's state now), or {@code null}
 * @param free     the workbench of free nodes under the drawing ({@link FreeNodes}), or {@code null}
 */
record Projection(String text, Path file, View view, List<String> subjects, String subject, Scene scene,
                  Map<SourcePos, Target> targets, String message, PhaseWheel wheel, Ring ring,
                  ShapeIndex index, Swimlanes lanes, GaitDiagram gait, Free free) {

    /** A projection without a workbench. */
    Projection(String text, Path file, View view, List<String> subjects, String subject, Scene scene,
               Map<SourcePos, Target> targets, String message, PhaseWheel wheel, Ring ring,
               ShapeIndex index, Swimlanes lanes, GaitDiagram gait) {
        this(text, file, view, subjects, subject, scene, targets, message, wheel, ring, index, lanes, gait, null);
    }

    /** A projection without a gait diagram. */
    Projection(String text, Path file, View view, List<String> subjects, String subject, Scene scene,
               Map<SourcePos, Target> targets, String message, PhaseWheel wheel, Ring ring,
               ShapeIndex index, Swimlanes lanes) {
        this(text, file, view, subjects, subject, scene, targets, message, wheel, ring, index, lanes, null);
    }

    /** A projection without a wheel or ring. */
    Projection(String text, Path file, View view, List<String> subjects, String subject, Scene scene,
               Map<SourcePos, Target> targets, String message) {
        this(text, file, view, subjects, subject, scene, targets, message, null, null, ShapeIndex.NONE, null);
    }

    /**
     * This projection with its ring or wheel laid out again with text {@code textScale} times as
     * large ({@link Layouts#ring(Ring, double)}), and its index with it; the drawings of the other
     * views stay as they are.
     */
    Projection withTextScale(double textScale) {
        Scene s = ring != null ? Layouts.ring(ring, textScale) : wheel != null && scene != null ? Layouts.wheel(wheel, textScale)
                : scene;
        return s == scene ? this : new Projection(text, file, view, subjects, subject, s, targets, message, wheel, ring,
                index.laidOut(ring, wheel, textScale), lanes, gait, free);
    }

    /** The views, in the chooser's order. */
    enum View {
        PROGRAM(PanelMsg.VIEW_PROGRAM), LANES(PanelMsg.VIEW_LANES), RING(PanelMsg.VIEW_RING), PHASE(PanelMsg.VIEW_PHASE), GAIT(PanelMsg.VIEW_GAIT);

        final PanelMsg label;

        View(PanelMsg label) {
            this.label = label;
        }
    }

    /** Seconds the gait diagram runs the engine for, and its tick (as {@code parpe diagram}'s defaults). */
    static final double GAIT_SECONDS = 6;
    static final double GAIT_TICK = 0.01;

    /**
     * A node that can be edited: what it is, and its fields.
     *
     * @param title  what the node is, for the edit row
     * @param fields its fields, in order
     * @param index  its place among the nodes it can be moved between (a {@code <main>} entry's), or −1
     * @param moveTo the text edit that moves it to another place, or {@code null} when it cannot move
     */
    record Target(String title, List<Field> fields, int index, IntFunction<TextEdit> moveTo,
                  List<Action> actions) {

        /** A node that moves and has no actions. */
        Target(String title, List<Field> fields, int index, IntFunction<TextEdit> moveTo) {
            this(title, fields, index, moveTo, List.of());
        }

        /** A node that does not move. */
        Target(String title, List<Field> fields) {
            this(title, fields, -1, null);
        }

        /** This node with {@code more} actions. */
        Target with(List<Action> more) {
            List<Action> all = new ArrayList<>(actions);
            all.addAll(more);
            return new Target(title, fields, index, moveTo, all);
        }
    }

    /**
     * A button of a node's edit row ({@link EditRow}): its inputs are fields of their own, and
     * the button turns their values into one text edit (may throw IllegalArgumentException).
     *
     * @param name   the button's label
     * @param inputs the names of its input fields, in order (none: the button acts at once)
     * @param values what each input field shows at first (a whole number gets − and + buttons)
     * @param edit   the text edit for the inputs' values
     */
    record Action(String name, List<String> inputs, List<String> values, Function<List<String>, TextEdit> edit) {

        /** An action whose inputs start empty. */
        Action(String name, List<String> inputs, Function<List<String>, TextEdit> edit) {
            this(name, inputs, Collections.nCopies(inputs.size(), ""), edit);
        }
    }

    /**
     * The node whose edit row shows while nothing is selected: the ring's automaton, the
     * lanes' behavior, (the program view's first target) {@code <main>} itself, or, in an empty
     * file, the start of a robot.
     */
    SourcePos home() {
        if (ring != null) {
            return ring.pos();
        }
        if (lanes != null) {
            return lanes.pos();
        }
        return (view == View.PROGRAM || scene == null) && !targets.isEmpty() ? targets.keySet().iterator().next() : null;
    }

    /**
     * One value of a node.
     *
     * @param name  the attribute or quantity
     * @param value its text as written ({@code ""} when absent)
     * @param edit  the text edit that sets it to a new value (may throw IllegalArgumentException)
     */
    record Field(String name, String value, Function<String, TextEdit> edit) {
    }

    /**
     * The free nodes of a view under its drawing, and what dropping one on the drawing writes.
     *
     * @param view   the name their places are kept under ({@link NodePlaces})
     * @param bench  the drawing with the workbench, and the nodes where they are drawn
     * @param drop   the text edit of dropping the node named so at scene height {@code y} on
     *               node {@code on} of the drawing (or none), or {@code null} when that is no drop
     * @param hint   what a drop on the drawing does, for the message line
     */
    record Free(String view, Workbench.Bench bench, Drop drop, String hint) {
    }

    /** Dropping a free node on the drawing above its workbench. */
    @FunctionalInterface
    interface Drop {
        /** The edit of dropping {@code name} at scene height {@code y} on {@code on} (may be null), or {@code null}: no drop. */
        TextEdit at(String name, double y, SourcePos on);
    }

    /** Projects view {@code view} of the text {@code loaded} on {@code subject} (null: the default), free nodes at {@code places}. */
    static Projection of(ScriptDocument.Loaded loaded, View view, String subject, NodePlaces places) {
        String text = loaded.text();
        Path file = loaded.file();
        if (SectionEdits.blank(text)) {
            return start(text, file, view);
        }
        LoadResult r = loaded.result();
        Program p = r.program();
        if (p == null) {
            String first = r.diagnostics().stream().filter(d -> d.severity() == Severity.ERROR).findFirst()
                    .map(Diagnostic::format).orElse("");
            return new Projection(text, file, view, List.of(), null, null, Map.of(),
                    PanelMsg.DIAGRAM_DOES_NOT_LOAD.text(first));
        }
        Map<SourcePos, Target> targets = new LinkedHashMap<>();
        try {
            return switch (view) {
                case PROGRAM -> program(text, file, p, targets, places);
                case LANES -> lanes(text, file, p, subject, targets, places);
                case RING -> ring(text, file, p, subject, targets);
                case PHASE -> phase(text, file, p, subject, targets);
                case GAIT -> gait(text, file, p, targets);
            };
        } catch (ScriptRuntimeError e) {
            return new Projection(text, file, view, List.of(), null, null, Map.of(), e.diagnostic().format());
        }
    }

    /** Modules a robot started in an empty file has until the student clicks + or − (the template's 8). */
    static final String START_MODULES = "8";

    /**
     * An empty file (issue 24, item 5): no drawing and no error, but the start of a robot, a
     * chain of modules in one group ({@link SectionEdits#startRobot}), in the edit row.
     */
    private static Projection start(String text, Path file, View view) {
        Map<SourcePos, Target> targets = new LinkedHashMap<>();
        targets.put(new SourcePos(file.toString(), 1, 1), new Target(PanelMsg.DIAGRAM_START_TITLE.text(), List.of(), -1, null,
                List.of(new Action(START.text(), List.of("modules", "group"), List.of(START_MODULES, "body"),
                        v -> SectionEdits.startRobot(text, v.get(1), modules(v.get(0)))))));
        return new Projection(text, file, view, List.of(), null, null, targets, PanelMsg.DIAGRAM_FILE_EMPTY.text(START.text()));
    }

    /** The button that starts a robot in an empty file. */
    static final PanelMsg START = PanelMsg.DIAGRAM_START_ROBOT;

    private static int modules(String n) {
        try {
            return Integer.parseInt(n.trim());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(PanelMsg.DIAGRAM_MODULES_WHOLE.text(n));
        }
    }

    private static Projection gait(String text, Path file, Program p, Map<SourcePos, Target> targets) {
        GaitDiagram g = Gait.record(p, new RunOptions(GAIT_TICK, 0, List.of()), GAIT_SECONDS);
        return new Projection(text, file, View.GAIT, List.of(), null, Layouts.gait(g), targets, "", null, null,
                ShapeIndex.gait(g), null, g);
    }

    static boolean mine(SourcePos pos, Path file) {
        return pos != null && pos.span() != null && pos.file().equals(file.toString());
    }

    private static Projection program(String text, Path file, Program p, Map<SourcePos, Target> targets, NodePlaces places) {
        var lane = Diagrams.program(p);
        if (lane.isEmpty()) {
            return new Projection(text, file, View.PROGRAM, List.of(), null, null, targets,
                    PanelMsg.DIAGRAM_NO_MAIN.text());
        }
        var main = p.mainDef().orElseThrow();
        if (mine(main.pos(), file)) {
            targets.put(main.pos(), new Target(PanelMsg.DIAGRAM_MAIN_TITLE.text(), List.of(), -1, null, List.of(
                    new Action(PanelMsg.DIAGRAM_ADD_BEHAVIOR.text(), List.of("behavior", "automaton", "group", "time"),
                            v -> BehaviorEdits.addBehavior(text, p, v.get(0), v.get(1), v.get(2), v.get(3))))));
        }
        for (ProgramLane.Step s : lane.get().steps()) {
            if (mine(s.pos(), file)) {
                targets.put(s.pos(), new Target(PanelMsg.DIAGRAM_ENTRY_TITLE.text(PanelMsg.ordinal(s.index()), s.behavior()), List.of(
                        new Field("time", s.time() == null ? "" : s.time(),
                                v -> ScriptEdits.setAttribute(text, s.pos(), "time", v))), s.index(),
                        to -> DiagramEdits.moveEntry(text, main, s.index(), to),
                        List.of(new Action(PanelMsg.DIAGRAM_REMOVE_ENTRY.text(), List.of(), v -> BehaviorEdits.removeEntry(text, main, s.index())))));
            }
        }
        Scene drawn = Layouts.program(lane.get());
        Drop drop = (name, y, on) -> null;
        if (mine(main.pos(), file)) {
            drop = (name, y, on) -> y < drawn.height() ? BehaviorEdits.addEntry(text, p, name) : null;
        }
        Free free = free(FreeNodes.PROGRAM, drawn, PanelMsg.DIAGRAM_BENCH_BEHAVIORS.text(), Workbench.freeBehaviors(p), places, drop,
                PanelMsg.DIAGRAM_RELEASE_ON_LANE.text());
        return new Projection(text, file, View.PROGRAM, List.of(), null, free.bench().scene(), targets, "", null, null,
                ShapeIndex.NONE, null, null, free);
    }

    /** The workbench of {@code nodes} under {@code above}, the nodes at {@code places} of {@code view}. */
    private static Free free(String view, Scene above, String title, List<Workbench.Node> nodes, NodePlaces places, Drop drop,
                             String hint) {
        return new Free(view, Workbench.of(above, title, nodes, places.of(view)), drop, hint);
    }

    private static Projection lanes(String text, Path file, Program p, String subject, Map<SourcePos, Target> targets,
                                    NodePlaces places) {
        List<String> names = p.behaviors().stream().map(Behavior::name).toList();
        if (names.isEmpty()) {
            return new Projection(text, file, View.LANES, names, null, null, targets, PanelMsg.DIAGRAM_NO_BEHAVIORS.text());
        }
        String chosen = names.contains(subject) ? subject
                : p.main() != null && !p.main().entries().isEmpty() ? p.main().entries().get(0).behavior() : names.get(0);
        Behavior behavior = p.behavior(chosen).orElseThrow();
        Swimlanes s = Diagrams.swimlanes(p, behavior);
        if (mine(behavior.pos(), file)) {
            targets.put(behavior.pos(), new Target(PanelMsg.DIAGRAM_BEHAVIOR_TITLE.text(chosen), List.of(), -1, null,
                    List.of(new Action(PanelMsg.DIAGRAM_ADD_INSTANCE.text(), List.of("automaton", "group"),
                            v -> BehaviorEdits.addInstance(text, behavior, v.get(0), v.get(1))))));
        }
        for (Swimlanes.Lane l : s.lanes()) {
            for (Swimlanes.Bar b : l.bars()) {
                if (mine(b.pos(), file)) {
                    Instance in = behavior.instances().get(b.index());
                    Group g = Diagrams.groupOf(p, behavior, in).orElse(null);
                    targets.put(b.pos(), instanceTarget(text, file,
                            PanelMsg.DIAGRAM_INSTANCE_TITLE.text(b.index(), b.automaton(), (b.mirrored() ? "!" : "") + l.group()), b.pos(), b.phase(), b.offset(), b.period(), g)
                            .with(expand(text, p, in, g)));
                }
            }
        }
        Map<SourcePos, String> laneOf = new LinkedHashMap<>();
        s.lanes().forEach(l -> l.bars().forEach(b -> laneOf.put(b.pos(), l.group())));
        Drop drop = (name, y, on) -> null;
        if (mine(behavior.pos(), file)) {
            drop = (name, y, on) -> laneOf.containsKey(on) ? BehaviorEdits.addInstance(text, behavior, name, laneOf.get(on)) : null;
        }
        Free free = free(FreeNodes.LANES, Layouts.lanes(s), PanelMsg.DIAGRAM_BENCH_AUTOMATA.text(), Workbench.freeAutomata(p), places,
                drop, PanelMsg.DIAGRAM_RELEASE_ON_BAR.text(chosen));
        return new Projection(text, file, View.LANES, names, chosen, free.bench().scene(), targets,
                islands(s.islands().size()), null, null, ShapeIndex.lanes(s, free.bench().scene()), s, null, free);
    }

    /** The action that writes a gait table, which the pane then opens in the grid editor. */
    static final PanelMsg EXPAND = PanelMsg.DIAGRAM_EXPAND;

    /**
     * "Expand to gait table" for instance {@code in} on group {@code g}, or "Make phase
     * automaton" when it plays a gait table (see {@link GaitTableExpansion}).
     */
    private static List<Action> expand(String text, Program p, Instance in, Group g) {
        if (g == null) {
            return List.of();
        }
        if (in.automaton().table()) {
            return List.of(new Action(PanelMsg.DIAGRAM_MAKE_PHASE_AUTOMATON.text(), List.of("automaton"),
                    v -> GaitTableExpansion.writeCycle(text, p, in, g, v.get(0))));
        }
        return List.of(new Action(EXPAND.text(), List.of("table"),
                v -> GaitTableExpansion.write(text, p, in, g, v.get(0))));
    }

    /** An instance: its phase, offset and period, and the elements of its group when that is defined in this file. */
    private static Target instanceTarget(String text, Path file, String title, SourcePos pos, String phase, String offset,
                                         String period, Group g) {
        List<Field> fields = new ArrayList<>(List.of(
                new Field("phase", phase == null ? "" : phase, v -> ScriptEdits.setAttribute(text, pos, "phase", v)),
                new Field("offset", offset == null ? "" : offset, v -> ScriptEdits.setAttribute(text, pos, "offset", v)),
                new Field("period", period == null ? "" : period, v -> ScriptEdits.setAttribute(text, pos, "period", v))));
        if (g != null && !g.implicit() && mine(g.pos(), file)) {
            fields.add(new Field("elements", g.elements(), v -> ScriptEdits.setAttribute(text, g.pos(), "elements", v)));
        }
        return new Target(title, fields);
    }

    private static Projection ring(String text, Path file, Program p, String subject, Map<SourcePos, Target> targets) {
        List<String> names = p.automata().stream().map(Automaton::name).toList();
        if (names.isEmpty()) {
            return new Projection(text, file, View.RING, names, null, null, targets, PanelMsg.DIAGRAM_NO_AUTOMATA.text());
        }
        String chosen = names.contains(subject) ? subject : names.get(0);
        final Automaton a = p.automaton(chosen).orElseThrow();
        Ring r = Diagrams.ring(p, a);
        if (mine(a.pos(), file)) {
            if (!a.table()) {
                targets.put(a.pos(), new Target(PanelMsg.DIAGRAM_AUTOMATON_TITLE.text(a.name()), List.of(
                        new Field("add state", "", v -> DiagramEdits.addState(text, p, a, v, "1")))));
            }
            for (Ring.Arc arc : r.arcs()) {
                targets.putIfAbsent(arc.pos(), a.table() ? new Target(PanelMsg.DIAGRAM_ROW_TITLE.text(PanelMsg.ordinal(arc.index()), a.name()), List.of(
                        new Field("duration", arc.duration(), v -> DiagramEdits.retime(text, a, arc.index(), v))))
                        : StateTargets.of(text, file, a, arc));
            }
        }
        return new Projection(text, file, View.RING, names, chosen, Layouts.ring(r), targets, islands(r.islands().size()),
                null, r, ShapeIndex.ring(p, a, r), null);
    }

    private static Projection phase(String text, Path file, Program p, String subject, Map<SourcePos, Target> targets) {
        Map<String, Instance> all = new LinkedHashMap<>();
        Map<String, Behavior> of = new LinkedHashMap<>();
        for (Behavior b : p.behaviors()) {
            List<Instance> list = b.instances();
            for (int i = 0; i < list.size(); i++) {
                String label = PanelMsg.DIAGRAM_PHASE_SUBJECT.text(b.name(), PanelMsg.ordinal(i), list.get(i).name(), list.get(i).group());
                all.put(label, list.get(i));
                of.put(label, b);
            }
        }
        List<String> labels = new ArrayList<>(all.keySet());
        if (labels.isEmpty()) {
            return new Projection(text, file, View.PHASE, labels, null, null, targets, PanelMsg.DIAGRAM_NO_INSTANCES.text());
        }
        String chosen = all.containsKey(subject) ? subject : labels.get(0);
        Instance in = all.get(chosen);
        Group g = Diagrams.groupOf(p, of.get(chosen), in).orElse(null);
        if (g == null) {
            return new Projection(text, file, View.PHASE, labels, chosen, null, targets, PanelMsg.DIAGRAM_GROUP_MACRO.text(chosen));
        }
        PhaseWheel w = Diagrams.wheel(in, g);
        Scene sc = Layouts.wheel(w);
        if (mine(in.pos(), file)) {
            targets.put(in.pos(), instanceTarget(text, file, chosen, in.pos(), in.phase() == null ? null : in.phase().text(),
                    in.offset() == null ? null : in.offset().text(), in.period() == null ? null : in.period().text(), g));
        }
        return new Projection(text, file, View.PHASE, labels, chosen, sc, targets, islands(w.islands().size()), w, null,
                ShapeIndex.wheel(), null);
    }

    private static String islands(int n) {
        return n == 0 ? "" : (n == 1 ? PanelMsg.DIAGRAM_ONE_ISLAND : PanelMsg.DIAGRAM_N_ISLANDS).text(n);
    }
}
