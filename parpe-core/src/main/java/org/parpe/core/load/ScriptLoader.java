package org.parpe.core.load;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.Scope;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.Group;
import org.parpe.core.model.MainDef;
import org.parpe.core.model.Program;
import org.parpe.core.model.Robot;
import org.parpe.core.run.Channel;
import org.parpe.core.run.SensorTable;
import org.parpe.core.xml.InputFiles;

/**
 * Loads a PARSL program: XML with positions → parse tree → resolution and validation →
 * immutable {@link Program}. One load reports every problem it can find.
 */
public final class ScriptLoader {
    private ScriptLoader() {
    }

    /** Loads {@code file} with the given parameter values (defaults for the others). */
    public static LoadResult load(Path file, Map<String, Double> parameters) {
        String text;
        try {
            text = InputFiles.readText(file);
        } catch (IOException e) {
            DiagnosticList d = new DiagnosticList();
            d.error(new SourcePos(file.toString(), 1, 1), "cannot read file '" + file + "': " + e.getMessage());
            return new LoadResult(null, d.all(), List.of(), List.of(file));
        }
        return loadText(file, text, parameters);
    }

    /**
     * Loads {@code text} as the content of {@code file} (for example an editor's unsaved
     * buffer); includes and robot files are found relative to {@code file}.
     */
    public static LoadResult loadText(Path file, String text, Map<String, Double> parameters) {
        DiagnosticList d = new DiagnosticList();
        Assembly a = new Assembly(d);
        a.addMain(file, text);
        if (d.hasErrors() && a.robot == null && a.sections.isEmpty() && a.main == null) {
            return new LoadResult(null, d.all(), List.of(), a.files);
        }
        NameRegistry names = new NameRegistry();
        Declarations decl = new Declarations(d, names);
        decl.parameters(a.of("parameters"), parameters);
        Scope paramScope = new Scope(Scope.Kind.PARAMETERS_ONLY, decl.values, Map.of(), Map.of(), Set.of(),
                Map.of(), Set.of(), null);
        RobotResolver robots = new RobotResolver(d, names, paramScope);
        Robot robot = robots.resolve(a.robot, a.robotOrder, file,
                a.root == null ? new SourcePos(file.toString(), 1, 1) : a.root.pos());
        decl.controls(a.of("controls"));
        Scopes scopes = new Scopes(decl, robot);
        StateResolver states = new StateResolver(d, scopes.scope(Scope.Kind.MODULE, Map.of(), Set.of()));
        states.states(a.of("states"));
        states.automata(a.of("automata"));
        InstanceChecks checks = new InstanceChecks(d, robot, states.automata, states.locals);
        BehaviorResolver behaviors = new BehaviorResolver(d, names, robot, states.automata, states.broken, checks, scopes::scope);
        behaviors.brokenGroups = robots.broken;
        behaviors.behaviors(a.of("behaviors"));
        MainDef main = a.main == null ? null
                : new MainResolver(d, scopes, behaviors, checks, robot).resolve(a.main, decl.values);
        names.check(d);
        if (robots.file != null) {
            a.files.add(robots.file);
        }
        if (d.hasErrors() || robot == null) {
            return new LoadResult(null, d.all(), decl.parameterErrors, a.files);
        }
        List<Behavior> bs = new ArrayList<>();
        behaviors.behaviors.values().forEach(i -> bs.add(i.model()));
        Program p = new Program(file.toString(), robot, decl.parameters, decl.values, decl.controls, decl.radioWords,
                new ArrayList<>(states.states.values()), new ArrayList<>(states.automata.values()), bs, main);
        return new LoadResult(p, d.all(), decl.parameterErrors, a.files);
    }

    /** Builds the scopes of §13 rule 12 for this program. */
    static final class Scopes {
        private final Declarations decl;
        private final Set<String> groups;
        private final Scope.SensorCatalog sensors;

        Scopes(Declarations decl, Robot robot) {
            this.decl = decl;
            this.groups = robot == null ? Set.of() : Set.copyOf(robot.groups().stream().map(Group::name).toList());
            this.sensors = robot == null ? null : catalog(robot);
        }

        Scope scope(Scope.Kind kind, Map<String, Integer> macros, Set<String> groupMacros) {
            return new Scope(kind, decl.values, decl.controlIndex, decl.radioWords, groups, macros, groupMacros,
                    sensors == null ? Scope.SensorCatalog.NONE : sensors);
        }

        private static Scope.SensorCatalog catalog(Robot robot) {
            SensorTable ids = new SensorTable(robot.moduleIds());
            Map<String, Set<Integer>> carried = new HashMap<>();
            robot.sensors().forEach(s -> carried.put(s.type(), Set.copyOf(s.modules())));
            return new Scope.SensorCatalog() {
                @Override
                public int moduleIndex(int id) {
                    return ids.indexOf(id);
                }

                @Override
                public boolean carries(int id, Channel channel) {
                    return carried.getOrDefault(channel.sensor(), Set.of()).contains(id);
                }
            };
        }
    }

}
