package org.parpe.sim.sweep;

import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.parpe.core.model.Parameter;

/**
 * The parameters an optimisation searches: every parameter with a {@code min} below its
 * {@code max} that is not fixed, mapped to the unit cube. Values are quantised (whole numbers
 * for count-like parameters, otherwise about a thousandth of the range) so that the best
 * values, written back into a script as short decimals, give exactly the gait that was measured.
 */
public final class SearchSpace {
    private final List<Parameter> parameters;
    private final double[] steps;

    /** The space of {@code parameters} without the {@code fixed} ones. */
    public SearchSpace(List<Parameter> parameters, Set<String> fixed) {
        List<Parameter> chosen = new ArrayList<>();
        for (Parameter p : parameters) {
            if (p.min() != null && p.max() != null && p.min() < p.max() && !fixed.contains(p.name())) {
                chosen.add(p);
            }
        }
        this.parameters = List.copyOf(chosen);
        this.steps = new double[chosen.size()];
        for (int i = 0; i < steps.length; i++) {
            Parameter p = chosen.get(i);
            steps[i] = SweepSpec.integral(p) ? 1 : Math.pow(10, Math.floor(Math.log10((p.max() - p.min()) / 1000)));
        }
    }

    /** The searched parameters, in file order. */
    public List<Parameter> parameters() {
        return parameters;
    }

    /** Each searched parameter as the axis it is searched over: its {@code min} to its {@code max}. */
    public List<Axis> axes() {
        return parameters.stream().map(p -> Axis.continuous(p.name(), p.min(), p.max())).toList();
    }

    /** The number of searched parameters. */
    public int dimension() {
        return parameters.size();
    }

    /** The parameter values of the point {@code x} of the unit cube (clamped into it), quantised. */
    public Map<String, Double> values(double[] x) {
        Map<String, Double> values = new LinkedHashMap<>();
        for (int i = 0; i < parameters.size(); i++) {
            Parameter p = parameters.get(i);
            double u = Math.max(0, Math.min(1, x[i]));
            double raw = p.min() + u * (p.max() - p.min());
            BigDecimal step = BigDecimal.valueOf(steps[i]);
            BigDecimal q = BigDecimal.valueOf(raw).divide(step, 0, RoundingMode.HALF_EVEN).multiply(step);
            double v = Math.max(p.min(), Math.min(p.max(), q.doubleValue()));
            values.put(p.name(), v);
        }
        return values;
    }

    /** The point of the unit cube of the parameters' default values. */
    public double[] defaults() {
        double[] x = new double[parameters.size()];
        for (int i = 0; i < x.length; i++) {
            Parameter p = parameters.get(i);
            x[i] = (p.value() - p.min()) / (p.max() - p.min());
        }
        return x;
    }
}
