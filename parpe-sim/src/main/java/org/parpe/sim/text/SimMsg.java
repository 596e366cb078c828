package org.parpe.sim.text;

import org.parpe.core.text.Key;

/**
 * The keys of the simulator's own messages: why a sweep or an optimisation cannot start or its
 * shards cannot be merged, a robot that does not fit its world, a score in words, why a robot
 * cannot be exported, the robot builder's refusals and edit names, why a student's run did not
 * count, the grading report's and the robot sheet's words. Each constant is a key of
 * {@code SimMessages.properties} (English) and of its translations beside it;
 * {@code SimMessagesTest} fails on a key missing from a bundle, on a bundle key without a constant
 * here, on a constant no code uses, on placeholders that differ from the English ones and on an
 * English sentence in the module's code.
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
    GRADE_AND_MORE,

    // build.DraftEdits, RobotDraft: the robot builder's refusals and its edits' names (the Undo menu)
    BUILD_START,
    BUILD_NOT_A_CONFIG,
    BUILD_HAS_PARTS,
    BUILD_HAS_PROBLEMS,
    BUILD_NO_PART_YET,
    BUILD_NO_PART,
    BUILD_NOT_SEGMENT,
    BUILD_TYPE_PLATES,
    BUILD_PART_PLATES,
    BUILD_PLATE_TAKEN,
    BUILD_CHOOSE_TYPE,
    BUILD_HUB_PLATES,
    BUILD_QUARTER_TURNS,
    BUILD_KIT_EMPTY,
    BUILD_ADD,
    BUILD_ADD_TURNED,
    BUILD_ROOT_HOLDS_ONE,
    BUILD_ROOT_HOLDS,
    BUILD_REMOVE,
    BUILD_REMOVE_WITH_ONE,
    BUILD_REMOVE_WITH,
    BUILD_TURN_ROOT,
    BUILD_TURNED_ALREADY,
    BUILD_TURN,
    BUILD_ID_NEGATIVE,
    BUILD_ID_ALREADY,
    BUILD_ID_USED,
    BUILD_SET_ID,
    BUILD_ANGLE_RANGE,
    BUILD_ANGLE_ALREADY,
    BUILD_SET_ANGLE,
    BUILD_LIMP_ALREADY,
    BUILD_STIFF_ALREADY,
    BUILD_MAKE_LIMP,
    BUILD_MAKE_STIFF,
    BUILD_NOT_CONNECTED,
    BUILD_ROOT_ALREADY,
    BUILD_MAKE_ROOT,
    BUILD_POSE_NAMES,
    BUILD_POSE_NUMBER,
    BUILD_HEIGHT_NUMBER,
    BUILD_POSE_ALREADY,
    BUILD_SET_POSE,
    BUILD_NOT_ASSEMBLED,
    BUILD_LOOP_SELF,
    BUILD_LOOP_APART,
    BUILD_CLOSE_LOOP,
    BUILD_NO_SEGMENT,
    BUILD_IDS_IN_ORDER,
    BUILD_NUMBER_MODULES,
    DRAFT_INTERNAL_ERROR,

    // sweep.Merger, SweepCsv: why shards cannot be merged (after FILE:LINE: error:, LOAD_ERROR)
    UNPLACED,
    SHARD_SPAN,
    SHARD_NO_RUNS,
    MERGE_RUN_NOT_IN_SHARD,
    MERGE_NOT_A_RESULT,
    MERGE_COLUMNS_DIFFER,
    MERGE_CHANGED,
    MERGE_RUN_OUT_OF_ORDER,
    MERGE_SHORT_COMPLETE,
    MERGE_UNFINISHED,
    MERGE_OTHER_SPLIT,
    MERGE_SHARD_TWICE,
    MERGE_SHARD_MISSING,
    MERGE_RUN_TWICE,
    MERGE_NOT_A_ROW,
    MERGE_OTHER_SIZE,
    MERGE_RUN_TOO_LARGE,
    MERGE_ONLY_HEADER,
    MERGE_RUNS_MISSING,
    CSV_COLUMNS,
    CSV_NOT_A_NUMBER,

    // sweep.Axis, Objective: a best value at a bound; an objective's axis label
    AT_UPPER_BOUND,
    AT_LOWER_BOUND,
    OBJECTIVE_FORWARD_SPEED,
    OBJECTIVE_SPEED,
    OBJECTIVE_FORWARD,
    OBJECTIVE_DISTANCE,
    OBJECTIVE_SCORE,

    // grade: limits (Isolation), the report folder and shards (Grading, GradeShard), students (Students), traces (Replay)
    GRADE_OUT_OF_MEMORY,
    GRADE_NO_RESULT,
    GRADE_CPU_LIMIT,
    GRADE_WALL_LIMIT,
    GRADE_OUT_INSIDE,
    GRADE_CANNOT_MAKE_REPORT,
    GRADE_SHARD_CLASS,
    GRADE_SHARD_NAME,
    GRADE_STUDENT_TWICE,
    GRADE_SHARD_FIRST_LINE,
    GRADE_SHARD_EXPECTED,
    GRADE_SHARD_INCOMPLETE,
    GRADE_SHARD_HOLDS,
    GRADE_LINK,
    GRADE_NO_SCRIPT,
    GRADE_SCRIPTS,
    REPLAY_NOT_A_TRACE,
    REPLAY_NOT_NUMBERS,

    // grade.Report, ReportPage: the summary line and the HTML report's words
    GRADE_SUMMARY,
    REPORT_TITLE,
    REPORT_RANK,
    REPORT_STUDENT,
    REPORT_SCORE,
    REPORT_PARTS,
    REPORT_FORWARD,
    REPORT_DISTANCE,
    REPORT_FELL,
    REPORT_TIME,
    REPORT_TRACE,
    REPORT_PROBLEM,
    REPORT_YES,
    REPORT_NO,

    // sheet.RobotSheet: the robot sheet's title, views, scale and part list
    SHEET_TITLE,
    SHEET_TOP,
    SHEET_FRONT,
    SHEET_SIDE,
    SHEET_SCALE,
    SHEET_PART,
    PART_ONE,
    PART_SEGMENT,
    PART_NODE,
    PART_FOOT,
    PART_HUB,
    PART_SEGMENTS,
    PART_NODES,
    PART_FEET,
    PART_HUBS,
    SHEET_TYPE,
    SHEET_MODULE_ID,
    SHEET_ANGLE,
    SHEET_LIMP,
    SHEET_DEFINED_AT,
    SHEET_HUB_PLATES,
    SHEET_LINE,
    SHEET_MORE;

    /** The bundle of these keys. */
    public static final String BUNDLE = "org.parpe.sim.text.SimMessages";

    @Override
    public String bundle() {
        return BUNDLE;
    }
}
