package org.parpe.gui.sweep;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.eclipse.swt.widgets.Display;
import org.parpe.core.lang.Numbers;
import org.parpe.core.model.Parameter;
import org.parpe.core.text.Key;
import org.parpe.core.text.Message;
import org.parpe.gui.text.ToolMsg;
import org.parpe.sim.sweep.Axis;
import org.parpe.sim.sweep.Constraints;
import org.parpe.sim.sweep.Evaluator;
import org.parpe.sim.sweep.Objective;
import org.parpe.sim.sweep.OptimizeSpec;
import org.parpe.sim.sweep.SearchSpace;
import org.parpe.sim.sweep.SweepException;
import org.parpe.sim.sweep.SweepSpec;
import org.parpe.sim.text.SimMsg;

/**
 * What Start was pressed with: the script (the editor's text, loaded as its file), the robot,
 * the world, the seconds per run, the threads and the objective. Checks the boxes, then starts the
 * engine; every problem found before the start is a {@link SweepException} with one line.
 *
 * @param file      the path the text is loaded as
 * @param text      the editor's text
 * @param robot     {@code auto}, a generator, or a configuration file
 * @param world     the world file the runs are in, or null for the flat floor
 * @param duration  the seconds per run, as typed
 * @param jobs      the threads
 * @param objective what ranks the runs
 */
record StartRequest(Path file, String text, String robot, Path world, String duration, int jobs, Objective objective) {
    /** The scheduler's tick, as the IDE's runs and {@code parpe sweep} use. */
    static final double TICK = 0.01;
    /** The tilt beyond which a robot counts as fallen over, as {@code parpe sweep} counts it. */
    static final double FALL_TILT = org.parpe.sim.SimMetrics.FALL_TILT_DEG;

    /** A started sweep or optimisation. */
    record Started(Results results, SweepRunner runner, int total) {
    }

    private Evaluator.Settings settings(Map<String, Double> held) throws SweepException {
        if (objective == Objective.SCORE && world == null) {
            // as parpe sweep --objective score without --world: every run's score would be empty
            throw new SweepException(ToolMsg.SWEEP_SCORE_NEEDS_WORLD.text());
        }
        Double seconds = Numbers.parsePlain(duration);
        if (seconds == null || !(seconds > 0) || seconds.isInfinite() || seconds < TICK) {
            throw new SweepException(ToolMsg.SWEEP_BAD_SECONDS.text(Numbers.format(TICK), duration.trim()));
        }
        return new Evaluator.Settings(file, text, held, robot, seconds, TICK, FALL_TILT, world);
    }

    /** Starts the sweep the Sweep tab describes. */
    Started sweep(List<Parameter> parameters, SweepTab tab, Display display, SweepRunner.Events events)
            throws SweepException {
        Evaluator.Settings s = settings(tab.held());
        SweepSpec spec = tab.spec(parameters);
        List<String> names = spec.axes().stream().map(Axis::name).toList();
        Results results = new Results(file, Results.Mode.SWEEP, names, own(parameters, names), objective, Constraints.NONE,
                Results.KEEP, spec.size(), world != null);
        return new Started(results, SweepRunner.sweep(display, s, spec, jobs, events), spec.size());
    }

    /** Starts the optimisation the Optimise tab describes. */
    Started optimise(List<Parameter> parameters, OptimiseTab tab, Display display, SweepRunner.Events events)
            throws SweepException {
        Evaluator.Settings s = settings(Map.of());
        OptimizeSpec spec = tab.spec(objective);
        SearchSpace space = new SearchSpace(parameters, Set.of());
        if (space.dimension() == 0) {
            throw new SweepException(ToolMsg.SWEEP_NOTHING_TO_OPTIMISE.text(file.getFileName()));
        }
        List<String> names = space.parameters().stream().map(Parameter::name).toList();
        Results results = new Results(file, Results.Mode.OPTIMISE, names, own(parameters, names), objective, spec.constraints(),
                Results.KEEP, spec.budget(), world != null);
        return new Started(results, SweepRunner.optimise(display, s, spec, jobs, events), spec.budget());
    }

    /** The script's own values of the parameters {@code names}. */
    private static Map<String, Double> own(List<Parameter> parameters, List<String> names) {
        Map<String, Double> out = new java.util.LinkedHashMap<>();
        for (Parameter p : parameters) {
            if (names.contains(p.name())) {
                out.put(p.name(), p.value());
            }
        }
        return out;
    }

    /**
     * The engine's messages that name an option of {@code parpe sweep}/{@code optimize}, and the
     * dialog's words for each: the same arguments, the options named as the boxes are.
     */
    private static final Map<Key, Key> DIALOG_WORDS = Map.of(SimMsg.NOTHING_TO_VARY, ToolMsg.SWEEP_NOTHING_TO_VARY,
            SimMsg.VARY_WHERE, ToolMsg.SWEEP_ENGINE_WHERE, SimMsg.VARY_SYNTAX, ToolMsg.SWEEP_ENGINE_SYNTAX,
            SimMsg.FRACTIONAL_ENDS, ToolMsg.SWEEP_ENGINE_FRACTIONAL_ENDS, SimMsg.REPEAT_AT_LEAST_ONE, ToolMsg.SWEEP_ENGINE_REPEAT,
            SimMsg.RANDOM_AT_LEAST_ONE, ToolMsg.SWEEP_ENGINE_RANDOM, SimMsg.TOO_MANY_RUNS, ToolMsg.SWEEP_ENGINE_TOO_MANY_RUNS,
            SimMsg.K_TOO_LARGE, ToolMsg.SWEEP_ENGINE_K_TOO_LARGE, SimMsg.STARTS_AT_LEAST_ONE, ToolMsg.SWEEP_ENGINE_STARTS,
            SimMsg.BUDGET_TOO_SMALL, ToolMsg.SWEEP_ENGINE_BUDGET);

    /**
     * {@code m}, a message of the engine, in the dialog's words: where it names an option of the
     * command line, the dialog's message with the same arguments (also inside its arguments);
     * shown in the user's language.
     */
    static Message inDialogWords(Message m) {
        if (m.key() == null) {
            return m;
        }
        List<Object> args = m.args().stream().map(a -> a instanceof Message n ? (Object) inDialogWords(n) : a).toList();
        return new Message(DIALOG_WORDS.getOrDefault(m.key(), m.key()), args);
    }
}
