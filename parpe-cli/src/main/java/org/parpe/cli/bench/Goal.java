package org.parpe.cli.bench;

import org.parpe.cli.text.CliMsg;
import java.util.regex.Pattern;

/**
 * What a figure of {@code parpe bench} must reach: at least or at most a bound. {@code figures}
 * names the figures it applies to; a {@code *} in it stands for any part of a name
 * ({@code sim.*.bytes_per_tick}).
 */
public record Goal(String figures, boolean atLeast, double bound) {

    /** The figures must be at least {@code bound}. */
    public static Goal atLeast(String figures, double bound) {
        return new Goal(figures, true, bound);
    }

    /** The figures must be at most {@code bound}. */
    public static Goal atMost(String figures, double bound) {
        return new Goal(figures, false, bound);
    }

    /** Whether the figure called {@code name} has this goal. */
    public boolean appliesTo(String name) {
        StringBuilder regex = new StringBuilder();
        for (String part : figures.split("\\*", -1)) {
            regex.append(regex.length() == 0 ? "" : ".*").append(Pattern.quote(part));
        }
        return name.matches(regex.toString());
    }

    /** Whether {@code value} meets the goal. */
    public boolean holds(double value) {
        return atLeast ? value >= bound : value <= bound;
    }

    /** The goal as printed: {@code >= 30000000}. */
    public String describe() {
        return (atLeast ? ">= " : "<= ") + BenchResults.number(bound);
    }

    /** The goal and its verdict for {@code value}: {@code goal >= 3: holds}. */
    public String verdict(double value) {
        return CliMsg.GOAL_VERDICT.text(describe(), (holds(value) ? CliMsg.HOLDS : CliMsg.MISSED).text());
    }
}
