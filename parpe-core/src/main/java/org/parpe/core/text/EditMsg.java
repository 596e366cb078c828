package org.parpe.core.text;

/**
 * The keys of the refusals of the diagram and section editors ({@code org.parpe.core.diagram}'s
 * edits, {@code org.parpe.core.edit}): why an edit asked for in the IDE cannot be written into
 * the script. Each constant is a key of {@code Edits.properties} (English) and of its
 * translations beside it; the edits throw them as {@code org.parpe.core.edit.EditRefused}, which
 * the IDE shows in its language. {@code DiagramTextTest} checks the bundles and that every key is
 * used.
 */
public enum EditMsg implements Key {
    // ElementWriter, ScriptEdits, SectionEdits
    BAD_NAME,
    NOT_FROM_TEXT,
    NOT_EMPTY,
    MODULE_COUNT,
    NOT_WELL_FORMED,
    SECTION_INCLUDED,

    // DiagramEdits, RingEdits, BehaviorEdits, PaletteEdits
    NO_SUCH_STATE,
    NO_SUCH_ENTRY,
    CANNOT_MOVE_ENTRY,
    TABLE_ADD_ROW,
    TABLE_EDIT_ROWS,
    LAST_STATE,
    ITEMS_MISMATCH,
    INSTANCE_NEEDS_GROUP,
    NAME_TAKEN,
    NO_BEHAVIOR,
    TAKES_MACROS,
    TABLE_NEEDS_ROWS,
    COUNT_NOT_WHOLE,
    COUNT_RANGE,
    EMPTY_ATTRIBUTE,

    // GaitTableExpansion: a phase automaton into a gait table and back
    ALREADY_TABLE,
    NOT_A_TABLE,
    NOT_REPEATING,
    STATE_HAS_EXIT,
    ROW_HAS_EXIT,
    NOT_CONSTANT,
    DURATION_OF_STATE,
    DURATION_OF_ROW,
    ANGLE_OF_STATE,
    NOT_LINEAR,
    ANGLE_COUNT,
    NOT_SHIFTED;

    /** The bundle of these keys. */
    public static final String BUNDLE = "org.parpe.core.text.Edits";

    @Override
    public String bundle() {
        return BUNDLE;
    }
}
