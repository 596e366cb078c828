package org.parpe.sim.sweep;

import java.nio.file.Path;
import java.util.Map;
import java.util.function.BooleanSupplier;
import java.util.function.Function;

/**
 * The far side of a {@link Lanes lane}: an {@link Evaluator} living in a private class loader,
 * spoken to only with JDK types (the classes of this package differ on the two sides).
 * {@code {"load", file, text, fixed, robot, duration, tick, fallTilt, world}} loads the script and
 * returns {@code null} or {@code {message}}; {@code {"run", values, seed, cancelled}} returns
 * {@code {measurements, fell, error}} or {@code null} when cancelled.
 */
final class IsolatedEvaluator implements Function<Object[], Object[]> {
    private Evaluator evaluator;

    @Override
    @SuppressWarnings("unchecked")
    public Object[] apply(Object[] call) {
        if ("load".equals(call[0])) {
            try {
                evaluator = Evaluator.load(new Evaluator.Settings(Path.of((String) call[1]), (String) call[2],
                        (Map<String, Double>) call[3], (String) call[4], (Double) call[5], (Double) call[6],
                        (Double) call[7], call[8] == null ? null : Path.of((String) call[8])));
                return null;
            } catch (SweepException e) {
                return new Object[] {e.getMessage()};
            }
        }
        BooleanSupplier cancelled = (BooleanSupplier) call[3];
        Cancellation cancellation = new Cancellation() {
            @Override
            public boolean cancelled() {
                return cancelled.getAsBoolean();
            }
        };
        Point p = new Point(0, 0, 0, (Map<String, Double>) call[1], (Long) call[2]);
        SweepRow r = evaluator.run(p, cancellation);
        if (r == null) {
            return null;
        }
        return new Object[] {new double[] {r.duration(), r.distance(), r.forward(), r.forwardSpeed(), r.speed(),
            r.maxTiltDeg(), r.jointTravelDeg(), r.score()}, r.fell(), r.error()};
    }

    /** The row of {@code point} from the answer of a {@code run} call. */
    static SweepRow row(Point point, Object[] answer) {
        double[] m = (double[]) answer[0];
        return new SweepRow(point, m[0], m[1], m[2], m[3], m[4], m[5], m[6], (Boolean) answer[1], (String) answer[2],
                m[7]);
    }
}
