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
            "' is a configuration file, not a generator; open it",
            // Constraints: the tilt limit's callers (optimize --max-tilt, the IDE's Optimise tab) refuse a bad one first
            "the tilt limit must be >= 0 degrees, got ",
            // file formats: a sweep shard's framing lines (SweepCsv), a grading shard's first line (GradeShard), which
            // merge and grade --merge read back; the HTML report's style sheet (ReportPage)
            "# parpe sweep shard (\\d{1,6})/(\\d{1,6}): (\\d{1,9}) runs from run (\\d{1,9}) of (\\d{1,9})",
            "# parpe sweep shard %d/%d: complete", "# parpe sweep shard ", " runs from run ",
            "parpe grade shard (\\d{1,6})/(\\d{1,6}): students (\\d+)\\.\\.(\\d+) of (\\d+)",
            "parpe grade shard %d/%d: students %d..%d of %d%n",
            "table{border-collapse:collapse;margin-top:1em}td,th{border:1px solid #bbb;padding:.25em .5em;",
            "tr.bad td{background:#fff3f0}pre{margin:0;white-space:pre-wrap;font-size:.85em;max-width:50em}",
            "svg{border:1px solid #999;background:#fafafa;max-width:100%;height:auto}.sw{display:inline-block;");

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
        List<String> found = ProseLiterals.inTree(Path.of("src/main/java"), file -> false, ALLOWED::contains);
        assertEquals(List.of(), found, "text for the user outside the bundles: give it a key in SimMsg\n" + String.join("\n", found));
    }
}
