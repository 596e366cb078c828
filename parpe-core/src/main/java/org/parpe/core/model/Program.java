package org.parpe.core.model;

import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * A loaded, validated PARSL program for one set of parameter values: the immutable model the
 * scheduler runs. Lists keep document order.
 *
 * @param file            the main file as named by the user
 * @param robot           groups, modules and sensors
 * @param parameters      declared parameters (with their defaults)
 * @param parameterValues the value of every parameter used for this model
 * @param controls        declared controls
 * @param radioWords      the symbol code of every radio word (PARSL.md §4)
 * @param states          named states
 * @param automata        phase automata and gait tables
 * @param behaviors       behaviors
 * @param main            the main sequence, or {@code null} for a program without one
 */
public record Program(String file, Robot robot, List<Parameter> parameters,
                      Map<String, Double> parameterValues, List<Control> controls,
                      Map<String, Integer> radioWords, List<StateDef> states,
                      List<Automaton> automata, List<Behavior> behaviors, MainDef main) {

    public Program {
        parameters = List.copyOf(parameters);
        parameterValues = Map.copyOf(parameterValues);
        controls = List.copyOf(controls);
        radioWords = Map.copyOf(radioWords);
        states = List.copyOf(states);
        automata = List.copyOf(automata);
        behaviors = List.copyOf(behaviors);
    }

    /** The robot's module IDs in ascending order (the trace's column order). */
    public int[] moduleIds() {
        return robot.moduleIds();
    }

    /** The main sequence, if the program has one. */
    public Optional<MainDef> mainDef() {
        return Optional.ofNullable(main);
    }

    /** The group called {@code name}, including the implicit {@code all}. */
    public Optional<Group> group(String name) {
        return robot.group(name);
    }

    /** The control called {@code name}. */
    public Optional<Control> control(String name) {
        return controls.stream().filter(c -> c.name().equals(name)).findFirst();
    }

    /** The behavior called {@code name}. */
    public Optional<Behavior> behavior(String name) {
        return behaviors.stream().filter(b -> b.name().equals(name)).findFirst();
    }

    /** The automaton called {@code name}. */
    public Optional<Automaton> automaton(String name) {
        return automata.stream().filter(a -> a.name().equals(name)).findFirst();
    }

    /** The state called {@code name}. */
    public Optional<StateDef> state(String name) {
        return states.stream().filter(s -> s.name().equals(name)).findFirst();
    }
}
