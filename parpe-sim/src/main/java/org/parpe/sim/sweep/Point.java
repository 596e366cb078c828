package org.parpe.sim.sweep;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * One run of a sweep.
 *
 * @param index       the run's number, 0-based, in combination order (combination × repeats + repeat)
 * @param combination the combination of parameter values, 0-based
 * @param repeat      which repetition of the combination, 0-based
 * @param values      the varied parameters' values, in the order of the sweep's axes
 * @param seed        the seed of {@code rand()} for this run
 */
public record Point(int index, int combination, int repeat, Map<String, Double> values, long seed) {

    public Point {
        values = Collections.unmodifiableMap(new LinkedHashMap<>(values));
    }
}
