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
import org.parpe.core.sensor.Channel;
import org.parpe.core.sensor.SensorTable;
import org.parpe.core.xml.InputFiles;
import org.parpe.core.xml.XText;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;

/**
 * Loads a PARSL program: XML with positions → parse tree → resolution and validation →
 * immutable {@link Program}. One load reports every problem it can find.
 */
public final class ScriptLoader {
    private ScriptLoader() {
    }

    /** Loads {@code file} with the given parameter values (defaults for the others). */
    public static LoadResult load(Path file, Map<String, Double> parameters) {
        return load(file, parameters, null);
    }

    /**
     * Loads {@code file} with the given parameter values, reading no file outside the folder
     * {@code confinedTo} (null: anywhere): an include or robot file outside it is a located error
     * naming the rule. {@code parpe grade} loads students' scripts so.
     */
    public static LoadResult load(Path file, Map<String, Double> parameters, Path confinedTo) {
        String text;
        try {
            Message outside = Includes.outside(file, confinedTo);
            if (outside != null) {
                return unreadable(file, outside);
            }
            text = InputFiles.readText(file);
        } catch (IOException e) {
            return unreadable(file, Message.verbatim(String.valueOf(e.getMessage())));
        }
        return bind(read(file, text, confinedTo), parameters);
    }

    private static LoadResult unreadable(Path file, Message why) {
        DiagnosticList d = new DiagnosticList();
        d.error(new SourcePos(file.toString(), 1, 1), Msg.CANNOT_READ_FILE, file, why);
        return new LoadResult(null, d.all(), List.of(), List.of(file));
    }

    /**
     * Loads {@code text} as the content of {@code file} (for example an editor's unsaved
     * buffer); includes and robot files are found relative to {@code file}.
     */
    public static LoadResult loadText(Path file, String text, Map<String, Double> parameters) {
        return bind(read(file, text), parameters);
    }

    /**
     * Reads {@code text} as the content of {@code file}, with its includes and robot file, for
     * {@link #bind} to load with any parameter values: the only step that reads files.
     */
    public static ParsedScript read(Path file, String text) {
        return read(file, text, null);
    }

    /** {@link #read(Path, String)} reading no file outside the folder {@code confinedTo} (null: anywhere). */
    public static ParsedScript read(Path file, String text, Path confinedTo) {
        DiagnosticList d = new DiagnosticList();
        Includes.Assembled a = Includes.read(file, text, d, confinedTo);
        XText robotRef = a.robot() == null ? null : Attrs.optional(a.robot(), "file");
        Path robotPath = robotRef == null ? null : Includes.resolve(file, robotRef.value().trim());
        Message outside = robotPath == null ? null : Includes.outside(robotPath, confinedTo);
        RobotResolver.FileRead robotFile = robotRef == null ? null
                : outside != null ? new RobotResolver.FileRead(robotPath, null, outside, List.of())
                : RobotResolver.FileRead.of(robotPath);
        return new ParsedScript(file, a, d.all(), robotFile);
    }

    /**
     * Loads {@code script} with the given parameter values (defaults for the others), reading no
     * file: the same result as {@link #loadText} on the files as they were read.
     */
    public static LoadResult bind(ParsedScript script, Map<String, Double> parameters) {
        Path file = script.file;
        Includes.Assembled a = script.assembled;
        DiagnosticList d = new DiagnosticList();
        script.readDiagnostics.forEach(d::report);
        if (d.hasErrors() && a.nothing()) {
            return new LoadResult(null, d.all(), List.of(), a.files());
        }
        NameRegistry names = new NameRegistry();
        Declarations.Parameters params = Declarations.parameters(a.of("parameters"), parameters, d, names);
        Scope paramScope = new Scope(Scope.Kind.PARAMETERS_ONLY, params.values(), Map.of(), Map.of(), Set.of(),
                Map.of(), Set.of(), null);
        RobotResolver.Resolved robot = RobotResolver.resolve(d, names, paramScope, a.robot(), a.robotOrder(), file,
                script.robotFile, a.root() == null ? new SourcePos(file.toString(), 1, 1) : a.root().pos());
        Declarations.Controls controls = Declarations.controls(a.of("controls"), d, names);
        Scopes scopes = new Scopes(params, controls, robot.robot());
        StateResolver.Resolved states = StateResolver.resolve(d, scopes.scope(Scope.Kind.MODULE, Map.of(), Set.of()),
                a.of("states"), a.of("automata"));
        InstanceChecks checks = new InstanceChecks(d, robot.robot(), states.automata(), states.locals());
        BehaviorResolver.Resolved behaviors = BehaviorResolver.resolve(d, names, robot, states, checks, scopes::scope,
                a.of("behaviors"));
        MainDef main = a.main() == null ? null
                : new MainResolver(d, scopes, behaviors, checks, robot.robot(), states.automata()).resolve(a.main(), params.values());
        names.check(d);
        List<Path> files = new ArrayList<>(a.files());
        if (robot.file() != null) {
            files.add(robot.file());
        }
        if (d.hasErrors() || robot.robot() == null) {
            return new LoadResult(null, d.all(), params.errors(), files);
        }
        List<Behavior> bs = new ArrayList<>();
        behaviors.behaviors().values().forEach(i -> bs.add(i.model()));
        Program p = new Program(file.toString(), robot.robot(), params.list(), params.values(), controls.list(),
                controls.radioWords(), new ArrayList<>(states.states().values()),
                new ArrayList<>(states.automata().values()), bs, main);
        return new LoadResult(p, d.all(), params.errors(), files);
    }

    /** Builds the scopes of §13 rule 12 for this program. */
    static final class Scopes {
        private final Declarations.Parameters params;
        private final Declarations.Controls controls;
        private final Set<String> groups;
        private final Scope.SensorCatalog sensors;

        Scopes(Declarations.Parameters params, Declarations.Controls controls, Robot robot) {
            this.params = params;
            this.controls = controls;
            this.groups = robot == null ? Set.of() : Set.copyOf(robot.groups().stream().map(Group::name).toList());
            this.sensors = robot == null ? null : catalog(robot);
        }

        Scope scope(Scope.Kind kind, Map<String, Integer> macros, Set<String> groupMacros) {
            return new Scope(kind, params.values(), controls.index(), controls.radioWords(), groups, macros, groupMacros,
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
