package org.parpe.core.load;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.parpe.core.model.Behavior;
import org.parpe.core.model.Instance;
import org.parpe.core.model.MainEntry;
import org.parpe.core.model.Program;

/**
 * Issue 19 item 2: the loaded model holds resolved references, so the scheduler ({@code EntryPlan})
 * and the C export ({@code CProgram}) read them instead of looking the script up by name again
 * and reading {@code !} once more. Each binding points at the very objects the script declares.
 */
class ResolvedModelTest {
    private static final String SCRIPT = """
            <program>
              <robot><structure><left elements="0, 1"/><right elements="2, 3"/></structure></robot>
              <states><up angles="10"/><down angles="-10"/></states>
              <automata><swing states="up, down"/><hold states="down"/></automata>
              <behaviors>
                <step macros="side">
                  <swing group="!side"/>
                  <if cond="$time > 1"><hold group=" ! right "/></if>
                </step>
              </behaviors>
              <main><step side="left"/><step side="!left"/></main>
            </program>
            """;

    private static Program load() {
        LoadResult r = ScriptLoader.loadText(Path.of("resolved.xml"), SCRIPT, Map.of());
        assertTrue(r.diagnostics().isEmpty(), () -> r.diagnostics().toString());
        return r.program();
    }

    @Test
    void anEntryHoldsItsBehaviorAndEveryInstanceWithTheDeclaredObjects() {
        Program p = load();
        MainEntry first = p.main().entries().get(0);
        Behavior step = p.behaviors().get(0);
        assertSame(step, first.definition());
        List<Instance> instances = step.instances();
        assertEquals(2, first.bindings().size());

        MainEntry.Binding swing = first.bindings().get(0);
        assertSame(instances.get(0), swing.instance());
        assertSame(p.automata().get(0), swing.automaton());
        assertSame(p.robot().group("left").orElseThrow(), swing.group());
        assertTrue(swing.mirrored(), "the instance's ! with an unmirrored macro value");
        assertTrue(swing.conditions().isEmpty());

        MainEntry.Binding hold = first.bindings().get(1);
        assertSame(p.automata().get(1), hold.automaton());
        assertSame(p.robot().group("right").orElseThrow(), hold.group());
        assertTrue(hold.mirrored());
        assertEquals(1, hold.conditions().size());
        assertSame(((org.parpe.core.model.Conditional) step.items().get(1)), hold.conditions().get(0));
    }

    @Test
    void twoMirrorSignsCancelAndKeepTheirSourcePositions() {
        Program p = load();
        MainEntry second = p.main().entries().get(1);
        MainEntry.Binding swing = second.bindings().get(0);
        assertFalse(swing.mirrored(), "!side with side=\"!left\"");
        assertSame(p.robot().group("left").orElseThrow(), swing.group());
        assertEquals(7, swing.instance().pos().line());
        assertEquals("!side", swing.instance().group());
    }

    @Test
    void theMirrorSignIsReadByOneMethodThatEveryReaderOfAGroupAttributeCalls() {
        Program p = load();
        Instance hold = p.behaviors().get(0).instances().get(1);
        assertEquals(new MainEntry.GroupRef("right", true), hold.groupRef());
        assertEquals(MainEntry.GroupRef.parse(hold.group()), hold.groupRef());
        assertEquals(new MainEntry.GroupRef("left", true),
                p.main().entries().get(0).groupOf(p.behaviors().get(0).instances().get(0)));
    }
}
