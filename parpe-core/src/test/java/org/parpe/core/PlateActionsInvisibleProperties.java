package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.LongRange;

/**
 * Issue 35's acceptance: docking is invisible to a plain run (no simulator, PARSL.md §14). A
 * random gait's trace is the same, byte for byte, after its robot declares the {@code latch}
 * actuator and the {@code dock} sensor on every module and its states arm and release plates.
 */
class PlateActionsInvisibleProperties {
    private static final String[] ACTIONS = {"", " latch=\"0\"", " latch=\"1\"", " latch=\"0, 1\"", " unlatch=\"0\"",
        " unlatch=\"1\"", " unlatch=\"0, 1\"", " latch=\"0\" unlatch=\"1\""};

    @Provide
    Arbitrary<List<Integer>> actions() {
        return Arbitraries.integers().between(0, ACTIONS.length - 1).list().ofMinSize(4).ofMaxSize(4);
    }

    @Property(tries = 40)
    void latchesDockSensorsAndPlateActionsLeaveAPlainRunsTraceAlone(
            @ForAll("gaits") SchedulerProperties.Gait g, @ForAll("actions") List<Integer> actions,
            @ForAll @LongRange(min = 0, max = 1000) long seed) {
        String plain = g.script().replace("<s0 angles=\"", "<s0 angles=\"20*rand() + ");
        String docking = plain.replace("</structure>",
                "</structure><sensors><dock elements=\"g\"/></sensors><actuators><latch elements=\"g\"/></actuators>");
        for (int i = 0; i < g.targets().size(); i++) {
            docking = docking.replace("<s" + i + " angles=", "<s" + i + ACTIONS[actions.get(i)] + " angles=");
        }
        assertEquals(SchedulerProperties.trace(plain, seed), SchedulerProperties.trace(docking, seed), docking);
    }

    @Provide
    Arbitrary<SchedulerProperties.Gait> gaits() {
        return new SchedulerProperties().gaits();
    }
}
