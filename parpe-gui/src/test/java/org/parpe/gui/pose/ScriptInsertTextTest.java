package org.parpe.gui.pose;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The exact text "Use on another group" writes, pinned before issue 32 moved it onto the edit
 * layer (sections found by the elements' source spans, not by patterns over comment-masked
 * text): a self-closing section opened, sections that exist (one closed on its last child's
 * line), a {@code <main>} with entries, sections written at the end of the root.
 */
class ScriptInsertTextTest {
    static String write(String text, List<String> groups, double period, double phase, double offset) {
        return ScriptInsert.insert(text, ScriptInsertTest.load(text),
                new ScriptInsert.Request(ScriptInsertTest.legPoses(), groups, period, phase, offset)).text();
    }

    @Test
    void aSelfClosingSectionIsOpenedAndMissingOnesAreWrittenAtTheEnd() {
        assertEquals(A, write(ScriptInsertTest.LEGS, List.of("leftLeg"), 4, 0.5, 0));
    }

    @Test
    void sectionsThatExistGetTheNewElementsLastAndMainPlaysItFirst() {
        String text = ScriptInsertTest.LEGS.replace("<automata/>", "<automata>\n    <wave states=\"rec_leg\"/>\n  </automata>\n"
                + "  <behaviors>\n    <still>\n      <wave group=\"leg\" period=\"1\"/>\n    </still></behaviors>\n"
                + "  <main> <!-- x -->\n    <still/>\n  </main>");
        assertEquals(B, write(text, List.of("leftLeg", "rightLeg"), 2, 0, 0.25));
    }

    @Test
    void aRootClosedOnTheLastSectionsLineGetsTheSectionsBeforeItsEndTag() {
        String text = ScriptInsertTest.LEGS.replace("  <automata/>\n", "").replace("</states>\n</program>", "</states></program>");
        assertEquals(C, write(text, List.of("leftLeg"), 4, 0.5, 0));
    }

    static final String A = """
            <?xml version="1.0"?>
            <!-- two legs; </automata> in a comment must not be taken for the section's end -->
            <program>
              <robot>
                <structure>
                  <leg elements="0, 1"/>
                  <leftLeg elements="2, 3"/>
                  <rightLeg elements="4, 5"/>
                </structure>
              </robot>
              <automata>
                <!-- 3 poses of group leg, recorded in the Pose panel -->
                <rec_leg_2 times="1.50, 1.00, 2.00">
                  30.00, 0.00
                  30.00, -40.00
                  -30.00, -40.00
                </rec_leg_2>
              </automata>
              <states>
                <rec_leg angles="0"/>
                <play_leg angles="10"/>
              </states>
              <main>
                <play_leg_2/>
              </main>
              <behaviors>
                <play_leg_2>
                  <rec_leg_2 group="leftLeg" period="4" phase="0.5" offset="0"/>
                </play_leg_2>
              </behaviors>
            </program>
            """;

    static final String B = """
            <?xml version="1.0"?>
            <!-- two legs; </automata> in a comment must not be taken for the section's end -->
            <program>
              <robot>
                <structure>
                  <leg elements="0, 1"/>
                  <leftLeg elements="2, 3"/>
                  <rightLeg elements="4, 5"/>
                </structure>
              </robot>
              <automata>
                <wave states="rec_leg"/>
                <!-- 3 poses of group leg, recorded in the Pose panel -->
                <rec_leg_2 times="1.50, 1.00, 2.00">
                  30.00, 0.00
                  30.00, -40.00
                  -30.00, -40.00
                </rec_leg_2>
              </automata>
              <behaviors>
                <still>
                  <wave group="leg" period="1"/>
                </still>
                  <play_leg_2>
                    <rec_leg_2 group="leftLeg" period="2" phase="0" offset="0"/>
                    <rec_leg_2 group="rightLeg" period="2" phase="0" offset="0.25"/>
                  </play_leg_2>
                </behaviors>
              <main>
                <play_leg_2 time="6"/> <!-- x -->
                <still/>
              </main>
              <states>
                <rec_leg angles="0"/>
                <play_leg angles="10"/>
              </states>
            </program>
            """;

    static final String C = """
            <?xml version="1.0"?>
            <!-- two legs; </automata> in a comment must not be taken for the section's end -->
            <program>
              <robot>
                <structure>
                  <leg elements="0, 1"/>
                  <leftLeg elements="2, 3"/>
                  <rightLeg elements="4, 5"/>
                </structure>
              </robot>
              <states>
                <rec_leg angles="0"/>
                <play_leg angles="10"/>
              </states>
              <main>
                <play_leg_2/>
              </main>

              <behaviors>
                <play_leg_2>
                  <rec_leg_2 group="leftLeg" period="4" phase="0.5" offset="0"/>
                </play_leg_2>
              </behaviors>

              <automata>
                <!-- 3 poses of group leg, recorded in the Pose panel -->
                <rec_leg_2 times="1.50, 1.00, 2.00">
                  30.00, 0.00
                  30.00, -40.00
                  -30.00, -40.00
                </rec_leg_2>
              </automata>
            </program>
            """;
}
