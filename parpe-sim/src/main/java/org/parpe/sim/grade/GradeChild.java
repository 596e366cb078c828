package org.parpe.sim.grade;

import java.io.IOException;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.Severity;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.TargetException;
import org.parpe.core.text.Lang;
import org.parpe.core.text.Msg;
import org.parpe.core.xml.InputFiles;
import org.parpe.sim.SimMetrics;
import org.parpe.sim.text.SimMsg;
import org.parpe.sim.SimTarget;
import org.parpe.sim.Simulator;
import org.parpe.sim.world.Challenge;
import org.parpe.sim.world.ChallengeReader;
import org.parpe.sim.world.World;
import org.parpe.sim.world.WorldReader;

/**
 * One student's run, in a JVM of its own started by {@link Isolation}: loads the script confined
 * to its folder, runs it in the challenge, writes the trace and prints the outcome as
 * {@code key=value} lines on standard output ({@link Outcome#parse} reads them). Its working
 * folder is the students' folder, so that messages name files as the teacher sees them.
 * Arguments: CHALLENGE SCRIPT CONFINED-TO TRACE LANGUAGE (the grading JVM's {@link Lang}, so the
 * report's reasons are in the teacher's language).
 */
public final class GradeChild {
    /** The most messages a row shows: a script with thousands of errors must not swell the report. */
    static final int MAX_MESSAGES = 5;

    private GradeChild() {
    }

    public static void main(String[] args) throws IOException {
        PrintStream out = new PrintStream(System.out, false, StandardCharsets.UTF_8);
        Lang.use(Locale.forLanguageTag(args[4]));
        Outcome o;
        try {
            o = grade(Path.of(args[0]), Path.of(args[1]), Path.of(args[2]), Path.of(args[3]));
        } catch (TargetException e) {
            o = Outcome.failed(messages(e.diagnostics(), e.getMessage()));
        }
        out.print(o.format());
        out.flush();
        System.exit(0);
    }

    private static Outcome grade(Path challengeFile, Path script, Path root, Path trace)
            throws IOException, TargetException {
        DiagnosticList found = new DiagnosticList();
        Challenge c = ChallengeReader.read(challengeFile, found);
        World world = c == null ? null : WorldReader.read(c.world(), found);
        if (world == null) {
            return Outcome.failed(messages(found.all(), SimMsg.GRADE_CHALLENGE_ERRORS.text()));
        }
        try {
            InputFiles.check(script);
        } catch (IOException e) {
            return Outcome.failed(SimMsg.GRADE_CANNOT_READ.text(script, e.getMessage()));
        }
        LoadResult r = ScriptLoader.load(script, c.parameters(), root);
        if (r.program() == null) {
            return Outcome.failed(messages(r.errors(), SimMsg.GRADE_DOES_NOT_LOAD.text()));
        }
        // A value the challenge fixes must reach the script: outside the script's own min..max it
        // would be dropped and the script's default would run instead. A parameter the script
        // does not have is no matter (it does not use it).
        List<Diagnostic> unfixed = r.parameterErrors().stream()
                .filter(d -> d.text().key() != Msg.UNKNOWN_PARAMETER).toList();
        if (!unfixed.isEmpty()) {
            return Outcome.failed(messages(unfixed, "") + "\n" + SimMsg.GRADE_FIXED_PARAMETER.text());
        }
        int modules = r.program().moduleIds().length;
        if (modules > c.maxModules()) {
            return Outcome.failed(script + ": error: " + SimMsg.GRADE_TOO_MANY_MODULES.text(modules, c.maxModules()));
        }
        List<String> forbidden = r.program().robot().sensors().stream().filter(d -> !c.sensors().contains(d.type()))
                .map(d -> new Diagnostic(Severity.ERROR, d.pos(), SimMsg.GRADE_SENSOR_NOT_ALLOWED, d.type(),
                        c.sensors().isEmpty() ? SimMsg.GRADE_NO_SENSORS.text()
                        : String.join(", ", new java.util.TreeSet<>(c.sensors()))).format()).toList();
        if (!forbidden.isEmpty()) {
            return Outcome.failed(String.join("\n", forbidden.subList(0, Math.min(MAX_MESSAGES, forbidden.size()))));
        }
        SimTarget target = new SimTarget(c.robot(), world);
        DiagnosticList runDiags = new DiagnosticList();
        RunOutcome outcome;
        try (Writer w = Files.newBufferedWriter(trace, StandardCharsets.UTF_8)) {
            Run.Builder run = Run.builder(r.program(), new RunOptions(c.tick(), 0, List.of()), runDiags)
                    .duration(c.duration()).trace(w);
            target.attach(run);
            outcome = run.build().execute();
        }
        if (outcome.status() == RunOutcome.Status.ERROR) {
            return Outcome.failedAt(messages(runDiags.all(), SimMsg.GRADE_RUN_TIME_ERROR.text(outcome.time())), outcome.time());
        }
        Simulator s = target.simulator();
        SimMetrics m = s.metrics();
        return Outcome.ran(m, outcome.time());
    }

    /** The first {@link #MAX_MESSAGES} errors of {@code ds}, one a line, or {@code fallback}. */
    static String messages(List<Diagnostic> ds, String fallback) {
        List<String> lines = new ArrayList<>();
        ds.stream().filter(d -> d.severity() == Severity.ERROR).limit(MAX_MESSAGES).forEach(d -> lines.add(d.format()));
        long more = ds.stream().filter(d -> d.severity() == Severity.ERROR).count() - lines.size();
        if (more > 0) {
            lines.add(SimMsg.GRADE_AND_MORE.text(more));
        }
        return lines.isEmpty() ? fallback : String.join("\n", lines);
    }
}
