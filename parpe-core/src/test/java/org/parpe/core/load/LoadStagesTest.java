package org.parpe.core.load;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.expr.Scope;

/**
 * The load stages are functions from their inputs to immutable results: each can run on its
 * own, and what one stage found (a group defined with errors) reaches the next through its
 * result, not through a field set by hand.
 */
class LoadStagesTest {
    private static final Path FILE = Path.of("stages.xml");
    private static final String SCRIPT = """
            <program>
              <robot><structure><legs elements="0..1"/><bad elements="x"/></structure></robot>
              <parameters><speed value="2"/></parameters>
              <states><up angles="1"/></states>
              <automata><go states="up"/></automata>
              <behaviors><walk><go group="bad"/><go group="legs"/></walk></behaviors>
              <main><walk/></main>
            </program>
            """;

    @Test
    void eachStageReturnsAnImmutableResultTheNextTakes() {
        DiagnosticList d = new DiagnosticList();
        Includes.Assembled a = Includes.read(FILE, SCRIPT, d, null);
        assertEquals(1, a.of("states").size());
        assertThrows(UnsupportedOperationException.class, () -> a.sections().clear());
        assertThrows(UnsupportedOperationException.class, () -> a.files().clear());

        NameRegistry names = new NameRegistry();
        Declarations.Parameters params = Declarations.parameters(a.of("parameters"), Map.of("speed", 3.0), d, names);
        assertEquals(Map.of("speed", 3.0), params.values());
        assertThrows(UnsupportedOperationException.class, () -> params.values().put("x", 1.0));

        Scope paramScope = new Scope(Scope.Kind.PARAMETERS_ONLY, params.values(), Map.of(), Map.of(), Set.of(),
                Map.of(), Set.of(), null);
        RobotResolver.Resolved robot = RobotResolver.resolve(d, names, paramScope, a.robot(), a.robotOrder(), FILE, null,
                a.root().pos());
        assertNotNull(robot.robot());
        assertEquals(Set.of("bad"), robot.broken());
        assertThrows(UnsupportedOperationException.class, () -> robot.broken().add("legs"));

        Declarations.Controls controls = Declarations.controls(a.of("controls"), d, names);
        ScriptLoader.Scopes scopes = new ScriptLoader.Scopes(params, controls, robot.robot());
        StateResolver.Resolved states = StateResolver.resolve(d, scopes.scope(Scope.Kind.MODULE, Map.of(), Set.of()),
                a.of("states"), a.of("automata"));
        assertEquals(Set.of("up"), states.states().keySet());
        assertThrows(UnsupportedOperationException.class, () -> states.automata().clear());

        int before = d.all().size();
        InstanceChecks checks = new InstanceChecks(d, robot.robot(), states.automata(), states.locals());
        BehaviorResolver.Resolved behaviors = BehaviorResolver.resolve(d, names, robot, states, checks, scopes::scope,
                a.of("behaviors"));
        assertEquals(before, d.all().size(), "the broken group is not reported again where it is used: " + d.all());
        assertTrue(behaviors.behaviors().containsKey("walk"));
        assertThrows(UnsupportedOperationException.class, () -> behaviors.broken().add("x"));
    }

    @Test
    void theLoaderReportsTheBrokenGroupOnceAtItsDefinition() {
        LoadResult r = ScriptLoader.loadText(FILE, SCRIPT, Map.of());
        assertEquals(1, r.errors().size(), r.errors().toString());
        SourcePos at = r.errors().get(0).pos();
        assertEquals(2, at.line());
    }
}
