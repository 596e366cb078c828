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
import org.parpe.core.xml.InputFiles;
import org.parpe.sim.SimMetrics;
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
 * Arguments: CHALLENGE SCRIPT CONFINED-TO TRACE.
 */
public final class GradeChild {
    /** The most messages a row shows: a script with thousands of errors must not swell the report. */
    static final int MAX_MESSAGES = 5;

    private GradeChild() {
    }

    public static void main(String[] args) throws IOException {
        PrintStream out = new PrintStream(System.out, false, StandardCharsets.UTF_8);
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
            return Outcome.failed(messages(found.all(), "the challenge has errors"));
        }
        try {
            InputFiles.check(script);
        } catch (IOException e) {
            return Outcome.failed("cannot read '" + script + "': " + e.getMessage());
        }
        LoadResult r = ScriptLoader.load(script, c.parameters(), root);
        if (r.program() == null) {
            return Outcome.failed(messages(r.errors(), "the script does not load"));
        }
        // A value the challenge fixes must reach the script: outside the script's own min..max it
        // would be dropped and the script's default would run instead. A parameter the script
        // does not have is no matter (it does not use it).
        List<Diagnostic> unfixed = r.parameterErrors().stream()
                .filter(d -> !d.message().startsWith("unknown parameter")).toList();
        if (!unfixed.isEmpty()) {
            return Outcome.failed(messages(unfixed, "") + "\n(the challenge fixes this parameter's value)");
        }
        int modules = r.program().moduleIds().length;
        if (modules > c.maxModules()) {
            return Outcome.failed(script + ": error: the robot has " + modules + " modules; this challenge allows at most "
                    + c.maxModules() + " (max-modules)");
        }
        List<String> forbidden = r.program().robot().sensors().stream().filter(d -> !c.sensors().contains(d.type()))
                .map(d -> new Diagnostic(Severity.ERROR, d.pos(), "the script declares the " + d.type() + " sensor, which this"
                        + " challenge does not allow (it allows " + (c.sensors().isEmpty() ? "no sensors"
                        : String.join(", ", new java.util.TreeSet<>(c.sensors()))) + "; the sensors rule of the challenge)")
                        .format()).toList();
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
            return Outcome.failed(messages(runDiags.all(), "run-time error at " + outcome.time() + " s"));
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
            lines.add(String.format(Locale.ROOT, "... and %d more", more));
        }
        return lines.isEmpty() ? fallback : String.join("\n", lines);
    }
}
