package org.parpe.sim.text;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.parpe.core.text.BundleCheck;
import org.parpe.core.text.ProseLiterals;

/**
 * The translators' check of the simulator's own messages (docs/cli.md, "Translating PARPE"):
 * {@code mvn -B -o -pl parpe-sim -am test -Dtest=SimMessagesTest -Dsurefire.failIfNoSpecifiedTests=false}.
 */
class SimMessagesTest {
    /** Literals that read as prose but are no text for the user in a language, by reason. */
    private static final java.util.Set<String> ALLOWED = java.util.Set.of(
            // a place before "warning:", as a file's name is (SourcePos.origin), English for the tools that read it
            "simulated robot ",
            // the comment at the top of an exported MJCF/URDF/SDF file (the file is English, as the formats are)
            "PARPE robot '", "' (parpe export --target mjcf). Joints and actuators m<ID> are the",
            " modules; a control is the module's angle in radians.",
            "' (parpe export --target sdf). Joint m<ID> is module ID's servo;",
            "' (parpe export --target urdf). Joint m<ID> is module ID's servo;",
            " its value is the module angle minus the initial angle, in radians.",
            // part names a generator writes into the robot configuration (a file's names)
            "Lleg", "Rleg", "Larm", "Rarm",
            // faults of PARPE's own (IllegalArgumentException from code, never from a user's input)
            "invalid robot configuration '", "a configuration needs a root", " must have 1 <= K <= N",
            "a build edit has a text edit or a refusal, not both or neither", "a refused edit cannot be applied: ",
            "' is a configuration file, not a generator; open it");

    /**
     * Files whose texts for the user are not in the bundles yet (docs/decisions.md, "What is still
     * English"): the robot builder's refusals and edit names, the shard merger's and the sweep
     * file's problems, grading's report and limits, the robot sheet; the files they write (sweep
     * shards' first lines, the report's style) are file formats. Take a file off this list when
     * its texts move to {@link SimMsg}.
     */
    private static final java.util.Set<String> NOT_YET = java.util.Set.of("org/parpe/sim/build/DraftEdits.java",
            "org/parpe/sim/build/RobotDraft.java", "org/parpe/sim/sweep/Merger.java", "org/parpe/sim/sweep/SweepCsv.java",
            "org/parpe/sim/sweep/Axis.java", "org/parpe/sim/sweep/Constraints.java", "org/parpe/sim/sweep/Objective.java",
            "org/parpe/sim/grade/Isolation.java", "org/parpe/sim/grade/Grading.java", "org/parpe/sim/grade/Replay.java",
            "org/parpe/sim/grade/Report.java", "org/parpe/sim/grade/ReportPage.java", "org/parpe/sim/grade/GradeShard.java",
            "org/parpe/sim/grade/Students.java", "org/parpe/sim/sheet/RobotSheet.java");


    @Test
    void everyBundleHasEveryKeyNoOtherAndTheEnglishPlaceholders() {
        List<String> problems = BundleCheck.problems(SimMsg.BUNDLE, List.of(SimMsg.values()));
        assertEquals(List.of(), problems, "fix the bundles of org.parpe.sim.text.SimMsg:\n" + String.join("\n", problems));
    }

    @Test
    void everyKeyIsUsedByTheCode() throws IOException {
        StringBuilder code = new StringBuilder();
        try (Stream<Path> s = Files.walk(Path.of("src/main/java"))) {
            for (Path p : (Iterable<Path>) s.filter(p -> p.toString().endsWith(".java")
                    && !p.endsWith("text/SimMsg.java"))::iterator) {
                code.append(Files.readString(p));
            }
        }
        List<String> unused = BundleCheck.unusedIn(code, List.of(SimMsg.values()), "SimMsg.");
        assertEquals(List.of(), unused, "keys no code uses: remove them from SimMsg and every bundle");
    }

    /**
     * Issue 38: "a test fails on any user-visible string literal ... in messages outside the
     * bundles". Every literal of the main code that reads as prose is a text outside the bundles
     * unless {@link #ALLOWED} gives its reason (the physics library's patched
     * copies, {@code org.ode4j}, are not PARPE's words and are not read).
     */
    @Test
    void noProseLiteralOutsideTheBundles() throws IOException {
        List<String> found = ProseLiterals.inTree(Path.of("src/main/java"), NOT_YET::contains, ALLOWED::contains);
        assertEquals(List.of(), found, "text for the user outside the bundles: give it a key in SimMsg\n" + String.join("\n", found));
    }
}
