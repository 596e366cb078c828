package org.parpe.core.expr;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import net.objecthunter.exp4j.function.Function;
import org.parpe.core.diag.DiagnosticSink;
import org.parpe.core.lang.Vocabulary;
import org.parpe.core.sensor.Channel;
import org.parpe.core.sensor.SensorRef;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;
import org.parpe.core.xml.XText;

/**
 * Resolves the names of one expression against its {@link Scope} (parameters, macros, radio
 * words, controls, logical variables, sensors, functions) into nodes, and gives each operand
 * the exp4j variable name it stands under in the rewritten text.
 */
final class NameResolver {
    final XText src;
    final Scope scope;
    final DiagnosticSink diags;
    final List<Node> nodes = new ArrayList<>();
    final List<ExprCompiler.LocalUse> locals = new ArrayList<>();
    boolean failed;
    boolean perModule;

    NameResolver(XText src, Scope scope, DiagnosticSink diags) {
        this.src = src;
        this.scope = scope;
        this.diags = diags;
    }

    Set<String> variableNames() {
        Set<String> names = new HashSet<>();
        for (int i = 0; i < nodes.size(); i++) {
            names.add("v" + i);
        }
        return names;
    }

    String function(Lexer.Token t, int args, Map<String, Function> functions) {
        String name = t.text();
        int arity = Vocabulary.arity(name);
        if (arity == -1 || !name.equals(name.toLowerCase(Locale.ROOT))) {
            error(t, Msg.UNKNOWN_FUNCTION, name, Names.suggest(name, Vocabulary.functions()));
            return "rand";
        }
        String key = arity == -2 ? "sum" + args : name;
        functions.computeIfAbsent(key, k -> new Function(k, arity == -2 ? args : arity) {
            @Override
            public double apply(double... a) {
                throw new UnsupportedOperationException("PARSL evaluates its own node tree");
            }
        });
        return key;
    }

    String operand(Lexer.Token t) {
        Node n;
        switch (t.type()) {
            case NUMBER: n = number(t); break;
            case STRING: n = word(t); break;
            case DOLLAR: n = dollar(t); break;
            default: n = bare(t); break;
        }
        nodes.add(n == null ? new Nodes.Const(0) : n);
        return "v" + (nodes.size() - 1);
    }

    private Node number(Lexer.Token t) {
        double v = Double.parseDouble(t.text());
        if (!Double.isFinite(v)) {
            error(t, Msg.NUMBER_TOO_LARGE, t.text());
            return null;
        }
        return new Nodes.Const(v);
    }

    private Node word(Lexer.Token t) {
        Integer code = scope.kind() == Scope.Kind.PARAMETERS_ONLY ? null : scope.radioWords().get(t.text());
        if (code == null) {
            error(t, Msg.NOT_A_RADIO_WORD, t.text(), Names.suggest(t.text(), scope.radioWords().keySet()));
            return null;
        }
        return new Nodes.Const(code);
    }

    private Node bare(Lexer.Token t) {
        String name = t.text();
        switch (name) {
            case "pi": return new Nodes.Const(Math.PI);
            case "e": return new Nodes.Const(Math.E);
            case "true": return new Nodes.Const(1);
            case "false": return new Nodes.Const(0);
            default: break;
        }
        if (scope.parameters().containsKey(name)) {
            return new Nodes.Const(scope.parameters().get(name));
        }
        if (scope.macros().containsKey(name)) {
            return new Nodes.MacroRef(scope.macros().get(name));
        }
        if (scope.kind() != Scope.Kind.PARAMETERS_ONLY && scope.radioWords().containsKey(name)) {
            return new Nodes.Const(scope.radioWords().get(name));
        }
        if (scope.groupMacros().contains(name)) {
            error(t, Msg.GROUP_MACRO_IN_EXPRESSION, name);
        } else if (scope.groups().contains(name)) {
            error(t, Msg.GROUP_IN_EXPRESSION, name);
        } else if (scope.controls().containsKey(name)) {
            error(t, Msg.CONTROL_WITHOUT_DOLLAR, name);
        } else if (Vocabulary.arity(name) != -1) {
            error(t, Msg.FUNCTION_NOT_CALLED, name);
        } else {
            List<String> known = new ArrayList<>(scope.parameters().keySet());
            known.addAll(scope.macros().keySet());
            known.addAll(scope.radioWords().keySet());
            known.addAll(Vocabulary.CONSTANTS);
            Message where = scope.kind() == Scope.Kind.PARAMETERS_ONLY ? Message.of(Msg.ONLY_PARAMETERS_HERE) : Message.EMPTY;
            error(t, Msg.UNKNOWN_NAME, name, where, Names.suggest(name, known));
        }
        return null;
    }

    private Node dollar(Lexer.Token t) {
        String name = t.text();
        if (Vocabulary.LOGICAL_VARIABLES.contains(name)) {
            if (!scope.sees(name)) {
                error(t, Msg.VARIABLE_NOT_HERE, name, logicalWhere(name));
                return null;
            }
            int which = Vocabulary.LOGICAL_VARIABLES.indexOf(name);
            perModule |= which == Nodes.Var.INDEX || which == Nodes.Var.ID || which == Nodes.Var.PHASE
                    || which == Nodes.Var.CYCLE;
            return Nodes.Var.of(which);
        }
        if (scope.controls().containsKey(name)) {
            return new Nodes.ControlRef(scope.controls().get(name));
        }
        SensorRef ref = SensorRef.parse(name);
        if (ref != null) {
            return ref.local() ? localSensor(t, ref) : globalSensor(t, ref);
        }
        if (scope.parameters().containsKey(name) || scope.macros().containsKey(name)) {
            String kind = scope.parameters().containsKey(name) ? "parameter" : "macro";
            error(t, Msg.NAME_WITH_DOLLAR, Msg.named(kind, name), name);
            return null;
        }
        List<String> known = new ArrayList<>();
        scope.controls().keySet().forEach(c -> known.add(c));
        known.addAll(Vocabulary.LOGICAL_VARIABLES);
        error(t, Msg.UNKNOWN_DOLLAR_NAME, name, Names.suggest(name, known, "$"));
        return null;
    }

    private Channel channel(Lexer.Token t, SensorRef ref) {
        if (!Vocabulary.SENSOR_TYPES.contains(ref.sensor())) {
            error(t, Msg.NOT_IMPLEMENTED, Msg.named("sensor", ref.sensor()), String.join(", ", Vocabulary.SENSOR_TYPES));
            return null;
        }
        Channel c = ref.channel();
        if (c == null) {
            error(t, Channel.argumentHint(ref.sensor()));
        }
        return c;
    }

    private Node globalSensor(Lexer.Token t, SensorRef ref) {
        if (scope.sensors() == null) {
            error(t, Msg.SENSORS_NOT_HERE);
            return null;
        }
        Channel c = channel(t, ref);
        if (c == null) {
            return null;
        }
        int id = ref.moduleId();
        int index = id < 0 ? -1 : scope.sensors().moduleIndex(id);
        if (index < 0) {
            error(t, Msg.MODULE_NOT_IN_ROBOT, ref.module());
            return null;
        }
        if (!scope.sensors().carries(id, c)) {
            error(t, Msg.MODULE_WITHOUT_SENSOR, id, c.sensor());
            return null;
        }
        return new Nodes.GlobalSensor(Nodes.slot(index, c.ordinal()));
    }

    private Node localSensor(Lexer.Token t, SensorRef ref) {
        if (scope.kind() != Scope.Kind.MODULE) {
            error(t, Msg.LOCAL_SENSOR_NOT_HERE, ref.module());
            return null;
        }
        Channel c = channel(t, ref);
        if (c == null) {
            return null;
        }
        String which = ref.module();
        int position = which.equals("self") ? Nodes.LocalSensor.SELF : which.equals("prev") ? Nodes.LocalSensor.PREV
                : which.equals("next") ? Nodes.LocalSensor.NEXT : which.length() > 7 ? Integer.MAX_VALUE : Integer.parseInt(which);
        perModule = true;
        locals.add(new ExprCompiler.LocalUse(position, c, src.posAt(t.start()), "$" + t.text()));
        return new Nodes.LocalSensor(position, c.ordinal());
    }

    private static Message logicalWhere(String name) {
        switch (name) {
            case "count": return Message.of(Msg.COUNT_WHERE);
            case "time": case "btime": return Message.of(Msg.ONLY_PARAMETERS_HERE);
            default: return Message.of(Msg.VARIABLE_WHERE, name);
        }
    }

    private void error(Lexer.Token t, Msg key, Object... args) {
        diags.error(src.posAt(t.start()), key, args);
        failed = true;
    }
}
