package org.parpe.gui.text;

import org.parpe.core.text.Key;

/**
 * The keys of the IDE's texts: each constant is a key of {@code Ui.properties} (English) and of
 * {@code Ui_de}, {@code Ui_es}, {@code Ui_ja} beside it, so that a text without a key does not
 * compile. {@code UiTextTest} fails on a key missing from a bundle, a bundle key without a constant
 * here, a constant no code uses and placeholders that differ from the English ones. A menu text's
 * {@code &} marks its mnemonic, chosen per language.
 */
public enum UiMsg implements Key {
    // start-up (Main, IdeLanguage)
    UNKNOWN_LANGUAGE,
    NO_DISPLAY,
    CANNOT_READ_FILE,
    INTERNAL_ERROR_EVENT,

    // menu bar (MenuBar)
    MENU_FILE,
    MENU_EDIT,
    MENU_RUN,
    MENU_VIEW,
    MENU_HELP,
    MENU_NEW,
    MENU_OPEN,
    MENU_OPEN_RECENT,
    MENU_EXAMPLES,
    MENU_SAVE,
    MENU_SAVE_AS,
    MENU_EXPORT_ROBOT,
    MENU_EXPORT_PROGRAM,
    MENU_EXIT,
    NO_RECENT_FILES,
    FILE_NOT_FOUND,
    NO_LONGER_EXISTS,
    CLEAR_LIST,
    NO_EXAMPLES_FOLDER,
    MENU_TUTORIAL_LESSONS,
    MENU_UNDO,
    MENU_REDO,
    MENU_CUT,
    MENU_COPY,
    MENU_PASTE,
    MENU_SELECT_ALL,
    MENU_FIND_REPLACE,
    MENU_CONTENT_ASSIST,
    MENU_GO_TO_LINE,
    GO_TO_LINE,
    LINE_RANGE,
    ENTER_LINE_BETWEEN,
    ENTER_LINE_NUMBER,
    MENU_RUN_RUN,
    MENU_PAUSE_RESUME,
    MENU_STOP,
    MENU_EMERGENCY_STOP,
    MENU_HARDWARE,
    MENU_SWEEP,
    MENU_GRADE_CLASS,
    MENU_ZOOM_IN,
    MENU_ZOOM_OUT,
    MENU_RESET_ZOOM,
    MENU_RESET_3D,
    MENU_CLEAR_LOG,
    MENU_LANGUAGE,
    LANGUAGE_SYSTEM,
    LANGUAGE_TITLE,
    LANGUAGE_AFTER_RESTART,
    MENU_TUTORIAL,
    MENU_TUTORIAL_AT_START,
    MENU_QUICK_REFERENCE,
    MENU_ABOUT,
    ABOUT_TITLE,
    TUTORIAL_TITLE,
    TUTORIAL_NOT_FOUND,
    LESSON_CODE_NOT_INSERTED,
    LESSON_CODE_ADDS_NOTHING,
    LESSON_CODE_INSERTED,

    // Help texts (HelpText, QuickReference)
    ABOUT,
    SECTION_ROBOT,
    SECTION_PARAMETERS,
    SECTION_CONTROLS,
    SECTION_STATES,
    SECTION_AUTOMATA,
    SECTION_BEHAVIORS,
    SECTION_MAIN,
    NOTE_SECTIONS,
    NOTE_EDITING,
    NOTE_RUNNING,
    NOTE_3D,
    NOTE_LANGUAGE,
    QUICK_REFERENCE_TITLE,
    COLUMN_SECTION,
    COLUMN_HOLDS,
    COLUMN_EXAMPLE,
    ONLY_ONE_FILE,
    RUN_FOR_SECONDS;

    /** The bundle of these keys. */
    public static final String BUNDLE = "org.parpe.gui.text.Ui";

    @Override
    public String bundle() {
        return BUNDLE;
    }
}
