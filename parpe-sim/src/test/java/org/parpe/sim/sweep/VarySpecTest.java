package org.parpe.sim.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.parpe.core.model.Parameter;

class VarySpecTest {
    private static List<Parameter> params() throws SweepException {
        return Scripts.snake(1, Map.of()).parameters();
    }

    @Test
    void integerRangesGiveEveryInteger() throws Exception {
        Axis a = VarySpec.parse("bend=4..12", params());
        assertEquals(Axis.Kind.INTEGERS, a.kind());
        assertEquals(List.of(4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0), a.values());
    }

    @Test
    void countsGiveEvenlySpacedValuesWithBothEnds() throws Exception {
        assertEquals(List.of(10.0, 15.0, 20.0, 25.0, 30.0, 35.0, 40.0), VarySpec.parse("bend=10..40:7", params()).values());
        assertEquals(List.of(0.5, 1.0, 1.5), VarySpec.parse(" period = 0.5..1.5:3", params()).values());
        assertEquals(List.of(0.1, 0.25, 0.9), VarySpec.parse("phase=0.1,0.25,0.9", params()).values());
    }

    @Test
    void fractionalRangesAreContinuousAndOnlyRandomSweepsTakeThem() throws Exception {
        Axis a = VarySpec.parse("period=0.5..1.5", params());
        assertEquals(Axis.Kind.CONTINUOUS, a.kind());
        SweepException e = assertThrows(SweepException.class, () -> SweepSpec.grid(List.of(a), 1, 0).check());
        assertEquals("--vary period=0.5..1.5 has fractional ends, so a grid needs a number of values: write"
                + " period=0.5..1.5:K, or draw with --random COUNT", e.getMessage());
        SweepSpec.random(List.of(a), 5, 1, 0).check();
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "bend|--vary 'bend': expected NAME=A..B, NAME=A..B:K or NAME=V1,V2,...",
        "bnd=1..2|--vary bnd=1..2: unknown parameter 'bnd' (did you mean 'bend'?); the script's parameters are bend, period, phase",
        "bend=|--vary bend=: no values after '='; expected A..B, A..B:K or V1,V2,...",
        "bend=40..10|--vary bend=40..10: empty range: the start 40 is greater than the end 10",
        "bend=10..40:0|--vary bend=10..40:0: K (the number of values) must be >= 1, got 0",
        "bend=10..40:x|--vary bend=10..40:x: K (the number of values) must be a whole number >= 1, got 'x'",
        "bend=10..40:1|--vary bend=10..40:1: K = 1 gives a single value, but 10..40 is a range; write bend=10 instead",
        "bend=10..7x|--vary bend=10..7x: '7x' is not a number",
        "bend=1..2..3|--vary bend=1..2..3: expected A..B or A..B:K, got '1..2..3'",
        "bend=10..90|--vary bend=10..90: parameter 'bend' must be <= 60, got 90 (its bounds are 0..60)",
        "phase=-0.5,0.5|--vary phase=-0.5,0.5: parameter 'phase' must be >= 0, got -0.5 (its bounds are 0..1)",
        "period=1,,2|--vary period=1,,2: '' is not a number",
    })
    void badSpecsGetOneClearLine(String spec, String message) throws Exception {
        SweepException e = assertThrows(SweepException.class, () -> VarySpec.parse(spec, params()));
        assertEquals(message, e.getMessage());
    }

    @Test
    void anAxisVariedTwiceIsRefused() throws Exception {
        Axis a = VarySpec.parse("bend=1..2", params());
        SweepException e = assertThrows(SweepException.class, () -> SweepSpec.grid(List.of(a, a), 1, 0).check());
        assertEquals("parameter 'bend' is varied twice", e.getMessage());
    }

    @Test
    void aBadSpecificationKeepsItsKeySoItIsShownInTheUsersLanguage() {
        SweepException e = assertThrows(SweepException.class, () -> VarySpec.parse("bend=40..20", params()));
        assertEquals("--vary bend=40..20: empty range: the start 40 is greater than the end 20", e.getMessage());
        assertEquals("--vary bend=40..20: leerer Bereich: der Anfang 40 ist größer als das Ende 20",
                e.text().format(java.util.Locale.GERMAN));
        assertEquals("--vary bend=40..20: intervalo vacío: el inicio 40 es mayor que el final 20",
                e.text().format(java.util.Locale.forLanguageTag("es")));
    }
}
