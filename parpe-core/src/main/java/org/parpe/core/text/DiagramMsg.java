package org.parpe.core.text;

/**
 * The keys of the words the diagrams draw ({@code org.parpe.core.diagram}: lanes, rings, the
 * phase wheel, the gait picture, the work bench's cards) and of their notes, what a view cannot
 * draw. Each constant is a key of {@code Diagrams.properties} (English) and of its translations
 * beside it; PARSL's names ({@code <main>}, {@code angles}, {@code phase}, ...) stay as the file
 * writes them. {@code DiagramTextTest} checks the bundles and that every key is used.
 */
public enum DiagramMsg implements Key {
    // Layouts: lanes, swimlanes, gait picture
    UNTIL_AUTOMATA_END,
    TIME,
    EXIT_WHEN,
    RUNS_ONCE,
    RUNS_FOREVER,
    RUNS_TIMES,
    BEHAVIOR,
    BEHAVIOR_ENTRY,
    MACRO_GROUP,
    MIRRORED,
    IF,
    AND,
    DRIVES_TWICE,
    ONE_MODULE,
    MODULES,
    GAIT_TITLE,
    MODULE_AXIS,
    MORE_STATES,

    // Rings: an automaton's ring and the phase wheel
    RING_AUTOMATON,
    RING_GAIT_TABLE,
    ONE_CYCLE,
    CYCLE_VARIES,
    SECONDS,
    LASTS,
    RING_CAPTION,
    ON,
    WHEEL_LAG,
    WHEEL_POSITION_0,
    WHEEL_POSITION,

    // Diagrams.plates and DockReads: what a state does to the plates, what an exit waits on
    LATCHES,
    RELEASES,
    PLATE,
    PLATES,
    DOCK,
    DOCK_MODULE,
    DOCK_ITS,
    DOCK_PREVIOUS,
    DOCK_NEXT,
    DOCK_NTH,

    // Workbench: the cards of what <main> does not run
    NOT_RUN_BY_MAIN,
    MORE,
    CARD_GAIT_TABLE,
    CARD_AUTOMATON,

    // Diagrams: the notes of what a view cannot draw
    MACRO_WITHOUT_VALUE,
    DURATION_WHILE_RUNNING,
    CYCLES_WHILE_RUNNING,

    // NodePlaces: the layout file beside a script, where the IDE keeps the places of dragged nodes
    LAYOUT_FOREIGN,
    LAYOUT_BAD_LINE,
    LAYOUT_BAD,
    LAYOUT_BAD_LINES;

    /** The bundle of these keys. */
    public static final String BUNDLE = "org.parpe.core.text.Diagrams";

    @Override
    public String bundle() {
        return BUNDLE;
    }
}
