package org.parpe.core.run;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.math.BigDecimal;
import java.math.RoundingMode;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import org.junit.jupiter.api.Test;

/**
 * The trace's fast number formatting prints what C's {@code printf("%.6f")} prints (PARSL.md
 * §13 rule 23): the exact value of the double rounded half-even. Java's {@code String.format}
 * is not the reference: it rounds the shortest decimal representation half-up.
 */
class TraceFormatProperties {
    @Provide
    Arbitrary<Double> values() {
        return Arbitraries.oneOf(Arbitraries.doubles().between(-200, 200).ofScale(12),
                Arbitraries.doubles().between(-1e10, 1e10).ofScale(9),
                Arbitraries.integers().between(-2_000_000, 2_000_000).map(i -> i / 1e6),
                Arbitraries.integers().between(-2_000_000, 2_000_000).map(i -> (i + 0.5) / 1e6),
                Arbitraries.integers().between(-1 << 20, 1 << 20).map(i -> i / 128.0),
                Arbitraries.longs().map(l -> Double.longBitsToDouble(l & 0x7fef_ffff_ffff_ffffL) * (l < 0 ? -1 : 1)),
                Arbitraries.doubles().between(-1e20, 1e20),
                Arbitraries.doubles().between(-1e-5, 1e-5).ofScale(15));
    }

    /** The reference: exact decimal expansion, half-even, without a sign when it rounds to zero. */
    static String reference(double v) {
        String s = new BigDecimal(v).setScale(6, RoundingMode.HALF_EVEN).toPlainString();
        return s.equals("-0.000000") ? "0.000000" : s;
    }

    @Property(tries = 20_000)
    void likePrintfSixDecimals(@ForAll("values") double v) {
        StringBuilder sb = new StringBuilder();
        TraceWriter.format(sb, v);
        assertEquals(reference(v), sb.toString(), "value " + v);
    }

    @Test
    void exactTiesRoundHalfEvenAndHugeValuesPrintTheirExactDigits() {
        // Expected strings are what C (and Python's '%.6f') prints for these doubles.
        String[][] cases = {{"0.0078125", "0.007812"}, {"0.0234375", "0.023438"}, {"5e-7", "0.000000"},
            {"1.0000005", "1.000001"}, {"2.5e-6", "0.000003"}, {"1152921504606846976", "1152921504606846976.000000"},
            {"1e23", "99999999999999991611392.000000"}, {"1e17", "100000000000000000.000000"},
            {"-0.0078125", "-0.007812"}, {"999999.9999995", "999999.999999"}, {"999999.99999951", "1000000.000000"}, {"0.1", "0.100000"}};
        for (String[] c : cases) {
            StringBuilder sb = new StringBuilder();
            TraceWriter.format(sb, Double.parseDouble(c[0]));
            assertEquals(c[1], sb.toString(), c[0]);
        }
    }

    @Test
    void nonFiniteValuesOfExtraColumnsPrintAsJavaReadsThem() {
        StringBuilder sb = new StringBuilder();
        TraceWriter.format(sb, Double.NaN);
        sb.append(' ');
        TraceWriter.format(sb, Double.NEGATIVE_INFINITY);
        assertEquals("NaN -Infinity", sb.toString());
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
