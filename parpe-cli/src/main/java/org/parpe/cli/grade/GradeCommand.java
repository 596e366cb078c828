package org.parpe.cli.grade;

import org.parpe.cli.text.CliMsg;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.parpe.cli.options.Inputs;
import org.parpe.cli.options.OutputFile;
import org.parpe.cli.options.UsageException;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.io.OutputPlan;
import org.parpe.cli.sweep.SweepCommand;
import org.parpe.sim.grade.GradeShard;
import org.parpe.sim.grade.Grading;
import org.parpe.sim.grade.Isolation;
import org.parpe.sim.grade.Report;
import org.parpe.sim.grade.ReportPage;
import org.parpe.sim.grade.Row;
import org.parpe.sim.grade.Students;
import org.parpe.sim.sweep.SweepSpec;
import org.parpe.sim.world.Challenge;
import org.parpe.sim.world.ChallengeReader;
import org.parpe.sim.world.World;
import org.parpe.sim.world.WorldReader;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code parpe grade CHALLENGE STUDENTS_DIR --out REPORT_DIR}: every student's script run in the
 * challenge, each in a child JVM with a CPU-time and memory limit and confined to its folder,
 * then ranked into {@code report.csv} and {@code report.html} with a trace per run in
 * {@code traces/}. The report depends only on the inputs, not on {@code --jobs}.
 */
@Command(name = "grade", mixinStandardHelpOptions = true, description = "Run every student's script of a folder in a"
        + " challenge (each in its own JVM, with CPU-time and memory limits, reading only its own folder) and write a"
        + " ranked report: REPORT_DIR/report.csv, REPORT_DIR/report.html and a trace per run in REPORT_DIR/traces/.")
public final class GradeCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "CHALLENGE.xml", descriptionKey = "challenge", description = "The challenge (examples/challenges).")
    Path challengeFile;

    @Parameters(index = "1", paramLabel = "STUDENTS_DIR", descriptionKey = "students",
            description = "A folder with one script per student, or one folder per student.")
    Path studentsDir;

    @Option(names = "--out", required = true, paramLabel = "REPORT_DIR", description = "Where the report goes (made if missing).")
    Path out;

    @Option(names = {"-j", "--jobs"}, paramLabel = "N", description = "Runs at once (default: one per core).")
    Integer jobs;

    @Option(names = "--cpu-limit", paramLabel = "SECONDS", defaultValue = Isolation.Limits.DEFAULT_CPU_SECONDS,
            description = "CPU time one run may use, its JVM's start included (default ${DEFAULT-VALUE}).")
    double cpuLimit;

    @Option(names = "--memory", paramLabel = "MB", defaultValue = Isolation.Limits.DEFAULT_MEMORY_MB, description = "Heap of one run (default ${DEFAULT-VALUE}).")
    int memoryMb;

    @Option(names = "--shard", paramLabel = "K/N", description = "Grade only the K-th of N equal shares of the students"
            + " (1 <= K <= N), into REPORT_DIR/shard-K-of-N.grade and the traces; then --merge N writes the report"
            + " (docs/cluster.md).")
    String shard;

    @Option(names = "--merge", paramLabel = "N", description = "Run nobody: rank the files of the N shards in REPORT_DIR"
            + " (--shard K/N) into the report one machine would have written.")
    Integer merge;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        try {
            return grade(err);
        } catch (UsageException e) {
            err.println("parpe: " + e.getMessage());
            return 2;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            err.println("parpe: " + CliMsg.INTERRUPTED.text());
            return 130;
        }
    }

    private int grade(PrintWriter err) throws UsageException, InterruptedException {
        Inputs.check(challengeFile);
        DiagnosticList found = new DiagnosticList();
        Challenge c = ChallengeReader.read(challengeFile, found);
        World world = c == null ? null : WorldReader.read(c.world(), found);
        found.all().forEach(d -> err.println(d.format()));
        if (world == null) {
            throw new UsageException(CliMsg.CHALLENGE_HAS_ERRORS.text(challengeFile));
        }
        if (!Files.isDirectory(studentsDir)) {
            throw new UsageException(CliMsg.NOT_A_STUDENTS_FOLDER.text(studentsDir));
        }
        int n = jobs();
        prepare();
        OutputPlan plan = OutputFile.plan(List.of(challengeFile, c.world()));
        OutputFile csv = OutputFile.of(plan, "--out", out.resolve("report.csv").toString());
        OutputFile html = OutputFile.of(plan, "--out", out.resolve("report.html").toString());
        List<Students.Student> students;
        try {
            students = Students.of(studentsDir);
        } catch (IOException e) {
            throw new UsageException(CliMsg.CANNOT_LIST.text(studentsDir, e.getMessage()));
        }
        Grading grading = new Grading(challengeFile, c, studentsDir, out, new Isolation.Limits(cpuLimit, memoryMb));
        Grading.Listener progress = (done, total, s) -> {
            err.println(CliMsg.GRADED.text(done, total, oneLine(s.name())));
            err.flush();
        };
        if (shard != null) {
            int[] kn = SweepCommand.parseShard(shard);
            int[] range = SweepSpec.shard(students.size(), kn[0], kn[1]);
            List<Row> part = grading.run(students, range[0], range[1], n, progress);
            Path file = out.resolve(GradeShard.fileName(kn[0], kn[1]));
            OutputFile.of(plan, "--out", file.toString()).write(GradeShard.format(kn[0], kn[1], range[0], students.size(), part));
            PrintWriter o = spec.commandLine().getOut();
            o.println(CliMsg.GRADED_SHARD.text(kn[0], kn[1], range[0] + 1, range[1], students.size(), file));
            o.flush();
            return 0;
        }
        List<Row> rows = merge != null ? Shards.merge(grading, students, merge) : grading.run(students, n, progress);
        csv.write(Report.csv(rows));
        html.write(ReportPage.html(rows, c, world));
        PrintWriter o = spec.commandLine().getOut();
        for (Row r : rows) {
            String first = r.outcome().reason().lines().findFirst().orElse("");
            o.println(String.format(Locale.ROOT, "%-4s %s  %s", r.rank() > 0 ? Integer.toString(r.rank()) : "-",
                    oneLine(r.student().name()), r.rank() > 0 ? String.format(Locale.ROOT, "%.1f", r.outcome().score()) : first));
        }
        o.println(CliMsg.REPORT_IN.text(Report.summary(rows, c), out.resolve("report.html")));
        o.flush();
        return 0;
    }

    /** Checks the options of sharding and limits; returns how many students are graded at once. */
    private int jobs() throws UsageException {
        if (shard != null && merge != null) {
            throw new UsageException(CliMsg.SHARD_OR_MERGE.text());
        }
        if (!(cpuLimit > 0) || memoryMb < 64) {
            throw new UsageException(CliMsg.GRADE_LIMITS.text(cpuLimit, memoryMb));
        }
        int n = jobs == null ? Runtime.getRuntime().availableProcessors() : jobs;
        if (n < 1) {
            throw new UsageException(CliMsg.JOBS_AT_LEAST_ONE.text(n));
        }
        return n;
    }

    /** Makes the report folder and its traces folder; refuses one inside the students' folder. */
    private void prepare() throws UsageException {
        String why = Grading.prepare(out, studentsDir, "--out");
        if (why != null) {
            throw new UsageException(why);
        }
    }

    /** A name on one terminal line: control characters shown as '?'. */
    private static String oneLine(String s) {
        return s.replaceAll("\\p{Cntrl}", "?");
    }
}
