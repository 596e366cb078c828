package org.parpe.cli.text;

import org.parpe.core.text.Key;

/**
 * The keys of the command line's own messages (those of the loader, the simulator and the
 * buses are {@link org.parpe.core.text.Msg}'s). Each constant is a key of
 * {@code CliMessages.properties} and its translations; {@code CliTextTest} fails on a missing,
 * unused or mismatched one.
 */
public enum CliMsg implements Key {
    // Main
    UNKNOWN_LANGUAGE,
    UNKNOWN_COMMAND,
    TRY_HELP,
    OUT_OF_MEMORY,
    INTERNAL_ERROR,

    // check
    EMPTY_FOLDER,
    OK,
    OK_CHALLENGE,
    ONE_ERROR,
    N_ERRORS,

    // run
    NOTHING_TO_RUN,
    NO_DURATION,
    STOPPED_AT,
    WORLD_TIME_LIMIT,
    PROGRESS,

    // options shared by commands: Inputs, ParamValues, ClockOptions
    CANNOT_READ,
    CANNOT_READ_STIMULUS,
    PARAM_SYNTAX,
    PARAM_NOT_A_NUMBER,
    TICK_OUT_OF_RANGE,
    DURATION_NEGATIVE,
    TOO_MANY_TICKS,

    // export
    CANNOT_WRITE,
    BAD_TARGET,
    TARGET_NEEDS_SCRIPT,
    ROBOT_OPTIONS_ONLY,
    TARGET_NEEDS_ROBOT,
    BOARD_OPTIONS_ONLY,
    EXPORT_DURATION,
    GAIT_NEEDS_SCRIPT,
    BAD_BOARD,
    WROTE_FILES,
    BUILD_WITH,

    // the simulator's options, race, robot
    WRITTEN_FOR_WORLD,
    NEEDS_SIM,
    WORLD_HAS_ERRORS,
    SEE_ABOVE,
    DURATION_NOT_POSITIVE,
    SCRIPT_ERRORS,
    NO_MAIN,
    RUN_TIME_ERROR,
    RANK,
    SCRIPT,
    ROBOT,
    FORWARD_M,
    DISTANCE_M,
    SPEED_MPS,
    MAX_TILT,
    SCORE,
    PARTS,
    OUT_SVG_OR_PNG,
    CHECK_ONLY,
    ROBOT_OK,
    ROBOT_OK_KIT,
    CANNOT_DRAW_ROBOT,
    WROTE,

    // diagram
    WIDTH_FOR_PNG,
    WIDTH_RANGE,
    GAIT_TOO_LONG,
    PNG_TOO_LARGE,
    CANNOT_DRAW_DIAGRAM,
    CANNOT_DRAW_DIAGRAM_WIDTH,
    DIAGRAM_NO_MAIN,
    NO_SUCH_BEHAVIOR,
    NO_BEHAVIORS,
    NO_SUCH_AUTOMATON,
    NO_AUTOMATA,
    INSTANCE_RANGE,
    GROUP_IS_MACRO,

    // sweep, optimize: their options' errors (SweepCommand, SimSweepOptions, OptimizeCommand)
    RANDOM_AT_LEAST_ONE,
    CANNOT_WRITE_OUT,
    SHARD_SYNTAX,
    SHARD_N_TOO_LARGE,
    SHARD_K_RANGE,
    SHARD_K_N,
    BAD_OBJECTIVE,
    SCORE_NEEDS_WORLD,
    JOBS_RANGE,
    FALL_TILT_RANGE,
    BAD_PARAMS_ABOVE,
    MAX_TILT_RANGE;

    /** The bundle of these keys. */
    public static final String BUNDLE = "org.parpe.cli.text.CliMessages";

    @Override
    public String bundle() {
        return BUNDLE;
    }
}
