package org.parpe.core.run;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Locale;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import org.junit.jupiter.api.Test;

/** The trace's fast number formatting prints exactly what {@code %.6f} prints (PARSL.md §11). */
class TraceFormatProperties {
    @Provide
    Arbitrary<Double> values() {
        return Arbitraries.oneOf(Arbitraries.doubles().between(-200, 200).ofScale(12),
                Arbitraries.doubles().between(-1e10, 1e10).ofScale(9),
                Arbitraries.integers().between(-2_000_000, 2_000_000).map(i -> i / 1e6),
                Arbitraries.integers().between(-2_000_000, 2_000_000).map(i -> (i + 0.5) / 1e6),
                Arbitraries.doubles().between(-1e-5, 1e-5).ofScale(15));
    }

    @Property(tries = 20_000)
    void likePrintfSixDecimals(@ForAll("values") double v) {
        StringBuilder sb = new StringBuilder();
        TraceWriter.format(sb, v);
        String expected = String.format(Locale.ROOT, "%.6f", v);
        assertEquals(expected.equals("-0.000000") ? "0.000000" : expected, sb.toString(), "value " + v);
    }

    @Test
    void negativeZeroPrintsWithoutSign() {
        StringBuilder sb = new StringBuilder();
        TraceWriter.format(sb, -0.0);
        sb.append(' ');
        TraceWriter.format(sb, -1e-9);
        assertEquals("0.000000 0.000000", sb.toString());
    }
}
