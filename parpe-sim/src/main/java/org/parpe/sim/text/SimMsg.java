package org.parpe.sim.text;

import org.parpe.core.text.Key;

/**
 * The keys of the simulator's own messages: why a sweep or an optimisation cannot start, a robot
 * that does not fit its world, a score in words, why a robot cannot be exported, why a student's
 * run did not count. Each
 * constant is a key of {@code SimMessages.properties} (English) and of its translations beside
 * it; {@code SimMessagesTest} fails on a key missing from a bundle, on a bundle key without a
 * constant here, on a constant no code uses and on placeholders that differ from the English ones.
 */
public enum SimMsg implements Key {
    // SweepSpec, Sweep, OptimizeSpec
    NOTHING_TO_VARY,
    VARIED_TWICE,
    FRACTIONAL_ENDS,
    REPEAT_AT_LEAST_ONE,
    RANDOM_AT_LEAST_ONE,
    TOO_MANY_RUNS,
    MORE_THAN,
    VARIED_AND_FIXED,
    STARTS_AT_LEAST_ONE,
    BUDGET_TOO_SMALL,

    // VarySpec
    VARY_SYNTAX,
    VARY_WHERE,
    NO_VALUES,
    UNKNOWN_PARAMETER,
    NO_PARAMETERS,
    PARAMETERS_ARE,
    RANGE_SYNTAX,
    EMPTY_RANGE,
    K_NOT_WHOLE,
    K_TOO_LARGE,
    K_BELOW_ONE,
    K_ONE_RANGE,
    TOO_MANY_INTEGERS,
    NOT_A_NUMBER,
    WITH_BOUNDS,

    // Evaluator, Optimizer, ParameterDefaults
    DURATION_NOT_POSITIVE,
    TICK_RANGE,
    SCRIPT_DOES_NOT_LOAD,
    NOT_LOADING,
    LOAD_ERROR,
    LOAD_ERRORS,
    NO_MAIN,
    NOTHING_TO_OPTIMISE,
    DEFINED_ELSEWHERE,
    NO_ELEMENT,
    NO_VALUE_ATTRIBUTE,

    // Simulator.misfit, SimTarget
    MISFIT_ARENA,
    MISFIT_INSIDE,
    ROBOT_MISFIT,

    // WorldScore.inWords
    LIST_SEPARATOR,
    SCORE_ZONE,
    SCORE_PATH,
    SCORE_CHECKPOINT,
    SCORE_CHECKPOINTS,
    SCORE_DELIVERED,
    SCORE_PRESS,
    SCORE_PRESSES,
    SCORE_DISQUALIFIED,
    SCORE_TILT,
    SCORE_ARENA,

    // bridge.Export
    EXPORT_SUMMARY,
    EXPORT_SUMMARY_LATCHES,
    EXPORT_LOOP,
    EXPORT_LOOPS,
    EXPORT_LATCH_PAIR,
    EXPORT_LATCH_PAIRS,
    EXPORT_ROBOTS,
    EXPORT_DIR_IS_FILE,
    EXPORT_NOT_REGULAR,
    EXPORT_PART_NAME,

    // grade.GradeChild
    GRADE_CHALLENGE_ERRORS,
    GRADE_CANNOT_READ,
    GRADE_DOES_NOT_LOAD,
    GRADE_FIXED_PARAMETER,
    GRADE_TOO_MANY_MODULES,
    GRADE_SENSOR_NOT_ALLOWED,
    GRADE_NO_SENSORS,
    GRADE_RUN_TIME_ERROR,
    GRADE_AND_MORE;

    /** The bundle of these keys. */
    public static final String BUNDLE = "org.parpe.sim.text.SimMessages";

    @Override
    public String bundle() {
        return BUNDLE;
    }
}
