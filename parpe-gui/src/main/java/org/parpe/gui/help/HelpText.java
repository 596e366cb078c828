package org.parpe.gui.help;

/** The texts of the Help menu. */
public final class HelpText {
    /** The quick reference's table: one row per section of a PARSL program (section, what it holds, an example). */
    public static final String[][] SECTIONS = {
        {"<robot>", "groups of modules; <sensors>", "<legs elements=\"0..5, 8\"/>"},
        {"<parameters>", "numbers asked before the run", "<N value=\"10\" min=\"4\" max=\"40\"/>"},
        {"<controls>", "live inputs: slider, radio, text; used as $name", "<speed type=\"slider\" min=\"0.5\" max=\"4\" value=\"1\"/>"},
        {"<states>", "target angles in degrees", "<up angles=\"30\"/>"},
        {"<automata>", "states in turn, or a gait table", "<wave states=\"up, down\" times=\"1, 1\"/>"},
        {"<behaviors>", "automata on groups", "<wave group=\"legs\" phase=\"0.25\" period=\"2\"/>"},
        {"<main>", "behaviors in sequence", "<walk time=\"10\"/>"},
    };
    /** The lines under the table. */
    public static final String[] NOTES = {
        "A PARSL program has these sections, in any order.",
        "Editing: Ctrl+Space completes names; errors are underlined and listed in Problems. Ctrl+plus / Ctrl+minus / Ctrl+0: text size.",
        "Running: F5 runs, F6 pauses, Shift+F5 stops, Esc is the emergency stop.",
        "3D view: drag to rotate, right-drag to pan, wheel to zoom, double-click to reframe.",
        "The full language is specified in PARSL.md; Help > Tutorial teaches it step by step.",
    };
    public static final String ABOUT = String.join("\n",
            "PARPE " + org.parpe.core.Version.NUMBER + ": PolyKinetic Phase Automata Robot Programming Environment",
            "",
            "An open reimplementation of PARC's PolyKinetic environment for PolyBot modular robots:",
            "write PARSL, run it in the simulator or on the robot, steer it live.",
            "",
            "Java " + System.getProperty("java.version") + ", SWT " + org.eclipse.swt.SWT.getVersion());

    private HelpText() {
    }
}
