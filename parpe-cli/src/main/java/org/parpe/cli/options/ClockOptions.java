package org.parpe.cli.options;

import org.parpe.cli.text.CliMsg;
import org.parpe.core.lang.Numbers;

/**
 * Bounds of {@code --tick} and {@code --duration}, shared by {@code run} and {@code race}: a tick
 * too small or a duration of too many ticks would run for days (or, at {@code 1e-320}, never end).
 */
public final class ClockOptions {
    /** The smallest tick, seconds. */
    public static final double MIN_TICK = 1e-6;
    /** The largest tick, seconds. */
    public static final double MAX_TICK = 10;
    /** The most ticks one run may take ({@code --duration / --tick}). */
    public static final double MAX_TICKS = 1e9;

    private ClockOptions() {
    }

    /** Checks a tick and an optional duration (seconds); the problem names the value and the bound. */
    public static void check(double tick, Double duration) throws UsageException {
        if (!(tick >= MIN_TICK && tick <= MAX_TICK)) {
            throw new UsageException(CliMsg.TICK_OUT_OF_RANGE.text(Numbers.format(MIN_TICK), Numbers.format(MAX_TICK), tick));
        }
        if (duration == null) {
            return;
        }
        if (!(duration >= 0)) {
            throw new UsageException(CliMsg.DURATION_NEGATIVE.text(duration));
        }
        if (duration / tick > MAX_TICKS) {
            throw new UsageException(CliMsg.TOO_MANY_TICKS.text(Numbers.brief(duration), Numbers.brief(tick),
                    Numbers.brief(duration / tick), Numbers.format(MAX_TICKS)));
        }
    }
}
