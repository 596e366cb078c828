package org.parpe.gui.help;

import org.parpe.gui.text.UiMsg;

/** The texts of the Help menu, in the IDE's language; PARSL's words and examples stay as they are written. */
public final class HelpText {

    private HelpText() {
    }

    /** The quick reference's table: one row per section of a PARSL program (section, what it holds, an example). */
    public static String[][] sections() {
        return new String[][] {
            {"<robot>", UiMsg.SECTION_ROBOT.text(), "<legs elements=\"0..5, 8\"/>"},
            {"<parameters>", UiMsg.SECTION_PARAMETERS.text(), "<N value=\"10\" min=\"4\" max=\"40\"/>"},
            {"<controls>", UiMsg.SECTION_CONTROLS.text(), "<speed type=\"slider\" min=\"0.5\" max=\"4\" value=\"1\"/>"},
            {"<states>", UiMsg.SECTION_STATES.text(), "<up angles=\"30\"/>"},
            {"<automata>", UiMsg.SECTION_AUTOMATA.text(), "<wave states=\"up, down\" times=\"1, 1\"/>"},
            {"<behaviors>", UiMsg.SECTION_BEHAVIORS.text(), "<wave group=\"legs\" phase=\"0.25\" period=\"2\"/>"},
            {"<main>", UiMsg.SECTION_MAIN.text(), "<walk time=\"10\"/>"},
        };
    }

    /** What section {@code name} ({@code states}, without brackets) holds, as the quick reference says; null for another word. */
    public static String sectionHolds(String name) {
        for (String[] row : sections()) {
            if (row[0].equals("<" + name + ">")) {
                return row[1];
            }
        }
        return null;
    }

    /** The lines under the table; the first is the one above it. */
    public static String[] notes() {
        return new String[] {UiMsg.NOTE_SECTIONS.text(), UiMsg.NOTE_EDITING.text(), UiMsg.NOTE_RUNNING.text(),
            UiMsg.NOTE_3D.text(), UiMsg.NOTE_LANGUAGE.text()};
    }

    /** Help → About PARPE. */
    public static String about() {
        return UiMsg.ABOUT.text(org.parpe.core.Version.NUMBER, System.getProperty("java.version"),
                org.eclipse.swt.SWT.getVersion());
    }
}
