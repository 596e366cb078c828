package org.parpe.core.text;

import java.util.Locale;

/**
 * The keys of PARPE's messages: the loader's diagnostics, expression errors, run-time errors and
 * warnings, and the export's. Each constant is a key of {@code Messages.properties} (English) and
 * of its translations beside it; {@code MessagesTest} fails on a key missing from a bundle, on a
 * bundle key without a constant here, on a constant no code uses and on placeholders that differ
 * from the English ones.
 */
public enum Msg implements Key {
    // Names.suggest
    DID_YOU_MEAN,

    // Attrs
    TAKES_NO_ATTRIBUTES,
    ALLOWED_ATTRIBUTES,
    UNKNOWN_ATTRIBUTE,
    NEEDS_ATTRIBUTE,
    NO_TEXT_INSIDE,
    NO_ELEMENTS_INSIDE,
    INVALID_NAME,
    RESERVED_NAME,

    // Assembly
    NO_SCRIPT_YET,
    NOT_A_SCRIPT_HARDWARE,
    NOT_A_SCRIPT_ROBOT_CONFIG,
    NOT_A_SCRIPT_WORLD,
    UNKNOWN_SECTION,
    DID_YOU_MEAN_ELEMENT,
    SECTIONS_ARE,
    SECTION_TWICE,
    CANNOT_INCLUDE,
    CONFINED_TO_FOLDER,
    CONFINED_TO_FILE,
    INCLUDE_CYCLE,
    INCLUDE_TOO_DEEP,
    CANNOT_READ_INCLUDED,
    CANNOT_READ_FILE,

    // RobotResolver
    NO_ROBOT_SECTION,
    ROBOT_FILE_AND_ELEMENTS,
    CANNOT_READ_ROBOT_FILE,
    ROBOT_FILE_ROOT,
    UNKNOWN_ROBOT_ELEMENT,
    ROBOT_NEEDS_STRUCTURE,
    ROBOT_PART_TWICE,
    EMPTY_ELEMENT_ITEM,
    MODULE_ID_TOO_LARGE,
    MODULE_TWICE,
    ELEMENTS_EMPTY,
    RANGE_END_NOT_CONSTANT,
    RANGE_END_NOT_WHOLE,
    RANGE_END_TOO_LARGE,
    ALL_IN_STRUCTURE,
    NOT_AN_ELEMENT,
    GROUP_DEFINED_LATER,
    GROUP_NOT_DEFINED,
    NOT_IMPLEMENTED,
    DECLARED_TWICE_IN,
    CARRIER_NOT_IN_STRUCTURE,

    // kinds of names (Msg.kind) and a kind with its name (Msg.named)
    NAMED,
    KIND_GROUP,
    KIND_STATE,
    KIND_AUTOMATON,
    KIND_BEHAVIOR,
    KIND_MACRO,
    KIND_PARAMETER,
    KIND_CONTROL,
    KIND_RADIO_WORD,
    KIND_SLIDER,
    KIND_RADIO,
    KIND_SENSOR,
    KIND_ACTUATOR,
    KIND_GAIT_TABLE,

    // StateResolver, BehaviorResolver, MainResolver
    ALREADY_DEFINED,
    DEFINED_AT,
    AN_EARLIER_PLACE,
    BAD_INTERP,
    EMPTY_PLATE_ITEM,
    BAD_PLATE,
    LATCH_AND_UNLATCH,
    EMPTY_ANGLE_ITEM,
    STATES_AND_ROWS,
    NEEDS_STATES_OR_ROWS,
    EMPTY_STATE_ITEM,
    STATE_NOT_DEFINED,
    GAIT_TABLE_ROW,
    TIMES_COUNT,
    ONE_STATE,
    N_STATES,
    BAD_TIME_CONDITION,
    EMPTY_DURATION,
    EMPTY_MACRO_ITEM,
    MACRO_NAME_TAKEN,
    MACRO_TWICE,
    AUTOMATON_NOT_DEFINED,
    BAD_CYCLES,
    BEHAVIOR_NOT_DEFINED,
    MACRO_VALUE_MISSING,
    MACRO_NOT_A_GROUP,

    // Parameter, Declarations
    PARAMETER_NOT_FINITE,
    PARAMETER_BELOW_MIN,
    PARAMETER_ABOVE_MAX,
    UNKNOWN_PARAMETER,
    NO_PARAMETERS,
    PARAMETER_TYPE,
    NOT_A_PLAIN_NUMBER,
    MIN_ABOVE_MAX,
    VALUE_OUT_OF_BOUNDS,
    CONTROL_NAME_TAKEN,
    BAD_CONTROL_TYPE,
    STEP_NOT_POSITIVE,
    SLIDER_KEYS,
    RADIO_KEYS,
    EMPTY_RADIO_ITEM,
    RADIO_WORD_TWICE,
    RADIO_VALUE,
    UNKNOWN_KEY,
    KEY_COUNT,

    // InstanceChecks, NameRegistry
    IN_THIS_INVOCATION,
    GROUPS_OVERLAP,
    ANGLE_COUNT,
    ONE_MODULE,
    N_MODULES,
    WITH_NOTE,
    LINE_N,
    AT_PLACE,
    LATCHES_WITHOUT_LATCH,
    UNLATCHES_WITHOUT_LATCH,
    LOCAL_GROUP_TOO_SMALL,
    LOCAL_MODULE_WITHOUT_SENSOR,
    LOCAL_GROUP_WITHOUT_SENSOR,
    NAME_CLASH,

    // expressions: Lexer, Syntax, ExprCompiler, NameResolver, Channel
    IN_EXPRESSION,
    CANNOT_PARSE_EXPRESSION,
    UNEXPECTED_TOKEN,
    MALFORMED_EXPRESSION,
    DOLLAR_ALONE,
    UNTERMINATED_STRING,
    SINGLE_EQUALS,
    SINGLE_AMPERSAND,
    SINGLE_BAR,
    NOT_ASCII_DIGIT,
    UNEXPECTED_CHARACTER,
    EMPTY_EXPRESSION,
    VALUE_EXPECTED_BEFORE,
    UNMATCHED_CLOSE,
    COMMA_OUTSIDE_CALL,
    DECIMAL_COMMA,
    OPERATOR_MISSING,
    LETTER_O,
    VALUE_EXPECTED_AFTER,
    UNCLOSED_OPEN,
    SUM_NEEDS_ARGUMENT,
    ONE_ARGUMENT,
    N_ARGUMENTS,
    UNKNOWN_FUNCTION,
    NUMBER_TOO_LARGE,
    NOT_A_RADIO_WORD,
    GROUP_MACRO_IN_EXPRESSION,
    GROUP_IN_EXPRESSION,
    CONTROL_WITHOUT_DOLLAR,
    FUNCTION_NOT_CALLED,
    ONLY_PARAMETERS_HERE,
    UNKNOWN_NAME,
    VARIABLE_NOT_HERE,
    COUNT_WHERE,
    VARIABLE_WHERE,
    NAME_WITH_DOLLAR,
    UNKNOWN_DOLLAR_NAME,
    SENSORS_NOT_HERE,
    MODULE_NOT_IN_ROBOT,
    MODULE_WITHOUT_SENSOR,
    LOCAL_SENSOR_NOT_HERE,
    ANGLE_NO_ARGUMENT,
    ACCEL_NEEDS_AXIS,
    TOUCH_NEEDS_SIDE,
    DOCK_NEEDS_PLATE,

    // XmlReader
    NO_DOCTYPE,
    MALFORMED_XML_UNKNOWN,
    MALFORMED_XML,
    QUOTE_THE_VALUE,

    // run time: Nodes, Functions, Engine, InstanceRun, ScriptRuntimeError, PlatesByHand, Run
    NOT_FINITE,
    A_SUM,
    A_DIFFERENCE,
    A_PRODUCT,
    A_QUOTIENT,
    SUM_CALL,
    DIVISION_BY_ZERO,
    REMAINDER_BY_ZERO,
    FUNCTION_NOT_FINITE,
    MOD_BY_ZERO,
    VALUE_NOT_FINITE,
    AT_TIME,
    NEGATIVE_DURATION,
    TOTAL_DURATION,
    PERIOD_NOT_POSITIVE,
    NO_POSITIVE_DURATION,
    TOO_MANY_TRANSITIONS,
    INSTANCES_OVERLAP,
    ARMS_BY_HAND,
    RELEASES_BY_HAND,
    JOIN_BY_HAND,
    PART_BY_HAND,
    WHILE_CLOSING,

    // controls set while running (TickInputs), breakpoints reached (Breakpoints)
    UNKNOWN_CONTROL,
    CONTROL_IS_RADIO,
    CONTROL_RANGE,
    BREAK_ENTERED,
    BREAK_EXIT,

    // export: CExport, MemoryReport
    EXPORT_NEEDS_MAIN,
    TICK_NOT_POSITIVE,
    NAME_TOO_LONG_FOR_C,
    TABLES_TOO_LARGE,
    TOO_LITTLE_RAM,
    TOO_LITTLE_FLASH,
    TICK_TOO_SLOW,
    EXPORT_ARMS_PLATES,
    EXPORT_RELEASES_PLATES,
    FLOAT_CLOCK_WAVE,
    MEMORY_HOST,
    MEMORY_BOARD,
    MEMORY_BOARD_KEPT,

    // the Arduino sketch's options and checks (org.parpe.serial.export)
    HOST_IS_FOR_C,
    SKETCH_OPTIONS_ONLY,
    BAD_SERVO,
    PINS_FOR_PWM,
    BAD_PIN,
    BAD_BAUD,
    MODEL_FOR_BUS,
    MODEL_NOT_OF_SERVO,
    SKETCH_SENSORS,
    PIN_COUNT,
    TOO_MANY_PWM,
    MODULE_NOT_SERVO_ID,
    SKETCH_TICK,
    SKETCH_EDITED,

    // InputFiles (exception texts, formatted when thrown)
    IS_A_DIRECTORY,
    NO_SUCH_FILE,
    NOT_A_REGULAR_FILE,
    PERMISSION_DENIED,
    NOT_UTF8,
    FILE_TOO_LARGE,
    N_BYTES,
    MORE_THAN_BYTES,

    // files written: AtomicFiles, OutputPlan, Output, IoReasons (exception texts, formatted when thrown)
    FOLDER_IS_FILE,
    DANGLING_LINK,
    NAME_TOO_LONG,
    NO_DIRECTORY,
    NOT_REPLACEABLE,
    WRITE_PROTECTED,
    OTHER_OWNER,
    CANNOT_WRITE_OUTPUT,
    NOT_A_VALID_PATH,
    OUTPUT_NOT_REGULAR,
    DIRECTORY_NOT_WRITABLE,
    OUTPUT_IS_INPUT,
    OUTPUT_TWICE,
    OUTPUT_EXISTS,
    OUTPUT_EXISTS_HINT,

    // files of the simulator, kits and hardware profiles: FlatXmlFile
    CANNOT_READ_THE,
    NOT_WELL_FORMED,
    HAS_NO_ATTRIBUTE,
    NEEDS_THE_ATTRIBUTE,
    MUST_BE_WHOLE,
    MUST_BE_NUMBER,
    MUST_BE_IN_RANGE,
    MUST_BE_ONE_OF,
    NO_DOCTYPE_IN,
    EXPECTED_ROOT,
    NOT_THIS_KIND,
    NOT_THIS_KIND_BUT_SCRIPT,
    MAY_NOT_CONTAIN_TEXT,
    MAY_NOT_CONTAIN_ELEMENT,
    FILE_ROBOT_CONFIG,
    FILE_KIT,
    FILE_CHALLENGE,
    FILE_WORLD,
    FILE_HARDWARE,
    EXPECTED_ROBOT_CONFIG,
    EXPECTED_KIT,
    EXPECTED_CHALLENGE,
    EXPECTED_WORLD,
    EXPECTED_HARDWARE,

    // simulator: robot configurations
    CONFIG_UNEXPECTED_ATTRIBUTE,
    CONFIG_UNKNOWN_ELEMENT,
    CONFIG_NO_PART,
    UNKNOWN_PART_TYPE,
    SEGMENT_NEEDS_ID,
    ONLY_SEGMENTS_TAKE,
    ONLY_HUBS_TAKE_PLATES,
    LIMP_TRUE_OR_FALSE,
    BAD_ORIENTATION,
    BAD_ORIENTATION_DEGREES,
    BAD_PLATE_REF,
    ALREADY_A_ROOT,
    HEIGHT_NEGATIVE,
    CONFIG_HAS_NO_PARTS,
    ROOT_PART_NOT_DEFINED,
    PART_NAME_TWICE,
    SEGMENT_ID_NEGATIVE,
    MODULE_ID_TWICE,
    INITIAL_ANGLE_RANGE,
    HUB_PLATES,
    CONNECTED_TO_ITSELF,
    PART_NOT_DEFINED,
    PART_PLATES,
    PLATE_ALREADY_CONNECTED,
    LINE_NOTE,
    UNKNOWN_ROBOT,
    EXPECTED_KEY_VALUE,
    GIVEN_TWICE,
    GENERATOR_NO_PARAMETER,
    ROOT_CONNECTED_TO_ROOT,
    NOT_CONNECTED_TO_ROOT,
    NOT_CONNECTED_TO_ROOTS,
    LOOP_DOES_NOT_FIT,
    MORE_OVERLAPS,
    PARTS_OVERLAP,
    SEGMENT_CANNOT_TURN,

    // simulator: worlds, challenges, kits
    LEAVE_ARENA_NEEDS_ARENA,
    ELEMENT_GIVEN_TWICE,
    WORLD_UNKNOWN_ELEMENT,
    BAD_REGION,
    NAME_USED_TWICE,
    AT_LEAST,
    WALL_ENDS,
    MAX_BELOW_MIN,
    CUP_HEIGHT,
    BAD_AXIS,
    BAD_TURN,
    NO_OBJECT_PREFIX,
    NO_LEVER_CALLED,
    TRUE_OR_FALSE,
    NO_ZONE_CALLED,
    WORLD_DEFINES_NONE,
    EXPECTED_ONE_OF,
    KIT_RULE,
    CHALLENGE_UNKNOWN_ELEMENT,
    PARAMETER_SET_TWICE,
    SENSORS_LIST,
    BAD_TIE_BREAK,
    BEYOND_THE_KIT,
    KIT_UNEXPECTED_ATTRIBUTE,
    KIT_UNKNOWN_ELEMENT,
    KIT_UNKNOWN_PART_TYPE,
    KIT_TWICE,
    KIT_EMPTY,

    // servo buses: hardware profiles, ServoTarget
    PROFILE_UNKNOWN_ELEMENT,
    PROFILE_NEEDS_PROTOCOL,
    UNKNOWN_PROTOCOL,
    BAD_ON_FAULT,
    EMPTY_PORT,
    PROFILE_NO_SERVO,
    UNKNOWN_SERVO_MODEL,
    BAD_DIRECTION,
    MIN_NOT_BELOW_MAX,
    SERVO_RANGE,
    MODULE_MAPPED_TWICE,
    SERVO_ID_TWICE,
    NO_PORT_CHOSEN,
    NO_PORT_IN_PROFILE,
    PROFILE_UNREADABLE,
    PROFILE_ERRORS_ONE,
    PROFILE_ERRORS,
    CANNOT_OPEN_PORT,
    MODULES_UNMAPPED,
    BUS_FAILED_MODULES,
    BUS_FAILED_SERVOS,
    SERVOS_LIMP,
    THE_MODULES_ON,
    THE_SERVOS_OF_THE_PROFILE,
    MODULES_ANSWER,
    IN_PARENTHESES,
    MODULES_IN_PARENTHESES,
    SERVOS_ANSWER,
    MORE_AS_OTHER_MODEL,
    MODULE_SILENT,
    MODULES_SILENT,
    MODULE_UNADDRESSABLE,
    MODULES_UNADDRESSABLE,
    NO_MODULE_ANSWERS,
    SERVOS_SILENT,
    SERVOS_OTHER_MODEL,
    NO_SERVO_ANSWERS,

    // simulator: building the robot
    CANNOT_BUILD_ROBOT_ONE,
    CANNOT_BUILD_ROBOT,

    // simulator: the script and the robot
    ROBOT_LACKS_MODULES,

    // stimulus files: StimulusParser
    STIMULUS_LINE,
    STIMULUS_TIME,
    STIMULUS_UNKNOWN_NAME,
    STIMULUS_NOT_A_READING,
    STIMULUS_NO_SENSOR,
    STIMULUS_NUMBER,
    STIMULUS_RADIO_WORD,
    STIMULUS_SLIDER_RANGE,

    // the place of an entry in the other languages (Msg.ordinal)
    ORDINAL;

    /** The bundle of these keys. */
    public static final String BUNDLE = "org.parpe.core.text.Messages";

    @Override
    public String bundle() {
        return BUNDLE;
    }

    /**
     * The word for a kind of name as the loader names it internally ({@code group},
     * {@code radio word}, {@code sensor}, ...): {@code KIND_GROUP}, {@code KIND_RADIO_WORD}, ...
     */
    public static Message kind(String kind) {
        return Message.of(valueOf("KIND_" + kind.toUpperCase(Locale.ROOT).replace(' ', '_')));
    }

    /** A kind of name with the name: {@code group 'legs'}. */
    public static Message named(String kind, String name) {
        return Message.of(NAMED, kind(kind), name);
    }

    /**
     * {@code " (defined at PLACE)"} where a definition is reported at {@code anchor} (the include
     * that brought it in) rather than at its own {@code place}; no text without an anchor.
     */
    public static Message definedAt(Object anchor, Object place) {
        return anchor == null ? Message.EMPTY : Message.of(DEFINED_AT, place);
    }

    /**
     * The place of zero-based {@code index} as a person counts: in English the words of
     * {@link org.parpe.core.lang.Numbers#ordinal} ({@code first}, {@code second}, ...), in the
     * other languages {@link #ORDINAL} with the number ({@code 1.}, {@code 1.º}, {@code 1 番目}).
     */
    public static String ordinal(int index) {
        return Lang.current().getLanguage().equals(Locale.ENGLISH.getLanguage())
                ? org.parpe.core.lang.Numbers.ordinal(index) : ORDINAL.text(index + 1);
    }
}
