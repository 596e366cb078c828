package org.parpe.cli.grade;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import org.parpe.cli.Inputs;
import org.parpe.cli.OutputFile;
import org.parpe.cli.UsageException;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.io.AtomicFiles;
import org.parpe.core.io.OutputPlan;
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
    @Parameters(index = "0", paramLabel = "CHALLENGE.xml", description = "The challenge (examples/challenges).")
    Path challengeFile;

    @Parameters(index = "1", paramLabel = "STUDENTS_DIR",
            description = "A folder with one script per student, or one folder per student.")
    Path studentsDir;

    @Option(names = "--out", required = true, paramLabel = "REPORT_DIR", description = "Where the report goes (made if missing).")
    Path out;

    @Option(names = {"-j", "--jobs"}, paramLabel = "N", description = "Runs at once (default: one per core).")
    Integer jobs;

    @Option(names = "--cpu-limit", paramLabel = "SECONDS", defaultValue = "300",
            description = "CPU time one run may use, its JVM's start included (default ${DEFAULT-VALUE}).")
    double cpuLimit;

    @Option(names = "--memory", paramLabel = "MB", defaultValue = "512", description = "Heap of one run (default ${DEFAULT-VALUE}).")
    int memoryMb;

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
            err.println("parpe: interrupted");
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
            throw new UsageException("the challenge '" + challengeFile + "' has errors (above)");
        }
        if (!Files.isDirectory(studentsDir)) {
            throw new UsageException("'" + studentsDir + "' is not a folder of students' scripts");
        }
        if (!(cpuLimit > 0) || memoryMb < 64) {
            throw new UsageException("--cpu-limit must be > 0 s and --memory at least 64 MB, got " + cpuLimit + " and " + memoryMb);
        }
        int n = jobs == null ? Runtime.getRuntime().availableProcessors() : jobs;
        if (n < 1) {
            throw new UsageException("--jobs must be at least 1, got " + n);
        }
        Path traces = prepare();
        OutputPlan plan = OutputFile.plan(List.of(challengeFile, c.world()));
        OutputFile csv = OutputFile.of(plan, "--out", out.resolve("report.csv").toString());
        OutputFile html = OutputFile.of(plan, "--out", out.resolve("report.html").toString());
        List<Students.Student> students;
        try {
            students = Students.of(studentsDir);
        } catch (IOException e) {
            throw new UsageException("cannot list '" + studentsDir + "': " + e.getMessage());
        }
        List<Row> rows = Row.ranked(runAll(students, c, traces, n, err), c.tieBreak());
        csv.write(Report.csv(rows));
        html.write(ReportPage.html(rows, c, world));
        PrintWriter o = spec.commandLine().getOut();
        for (Row r : rows) {
            String first = r.outcome().reason().lines().findFirst().orElse("");
            o.println(String.format(Locale.ROOT, "%-4s %s  %s", r.rank() > 0 ? Integer.toString(r.rank()) : "-",
                    oneLine(r.student().name()), r.rank() > 0 ? String.format(Locale.ROOT, "%.1f", r.outcome().score()) : first));
        }
        o.println(Report.summary(rows, c) + "; report in " + out.resolve("report.html"));
        o.flush();
        return 0;
    }

    /** Makes the report folder and its traces folder; refuses one inside the students' folder. */
    private Path prepare() throws UsageException {
        try {
            Path existing = out.toAbsolutePath().normalize();
            while (!Files.exists(existing)) { // the part of --out that exists, links followed
                existing = existing.getParent();
            }
            if (existing.toRealPath().startsWith(studentsDir.toRealPath())) {
                throw new UsageException("--out must not be inside the students' folder '" + studentsDir + "'");
            }
            Files.createDirectories(out);
            return Files.createDirectories(out.resolve("traces"));
        } catch (IOException e) {
            throw new UsageException("cannot make the report folder '" + out + "': " + e.getMessage());
        }
    }

    private List<Row> runAll(List<Students.Student> students, Challenge c, Path traces, int n, PrintWriter err)
            throws InterruptedException {
        ExecutorService pool = Executors.newFixedThreadPool(n);
        AtomicInteger done = new AtomicInteger();
        List<Future<Row>> futures = new ArrayList<>();
        for (int i = 0; i < students.size(); i++) {
            Students.Student s = students.get(i);
            String trace = String.format(Locale.ROOT, "traces/%03d.csv", i + 1);
            futures.add(pool.submit(() -> {
                Row r = runOne(s, c, traces, trace);
                synchronized (err) {
                    err.println(String.format(Locale.ROOT, "graded %d/%d: %s", done.incrementAndGet(), students.size(),
                            oneLine(s.name())));
                    err.flush();
                }
                return r;
            }));
        }
        pool.shutdown();
        List<Row> rows = new ArrayList<>();
        try {
            for (Future<Row> f : futures) {
                rows.add(f.get());
            }
        } catch (java.util.concurrent.ExecutionException e) {
            throw new IllegalStateException("grading failed", e.getCause());
        } finally {
            pool.shutdownNow();
        }
        return rows;
    }

    private Row runOne(Students.Student s, Challenge c, Path traces, String trace) throws IOException, InterruptedException {
        if (!s.problem().isEmpty()) {
            return new Row(s, Outcome.failed(s.problem()), "", new double[0], 0);
        }
        Path target = out.resolve(trace);
        Path part = traces.resolve(target.getFileName() + ".part");
        Files.deleteIfExists(part);
        Outcome o = Isolation.run(challengeFile, studentsDir, s.script(), s.root(), part,
                new Isolation.Limits(cpuLimit, memoryMb));
        boolean keep = Files.isRegularFile(part) && (o.ranked() || o.reason().contains("run-time error"));
        if (!keep) {
            Files.deleteIfExists(part);
            Files.deleteIfExists(target);
            return new Row(s, o, "", new double[0], 0);
        }
        AtomicFiles.moveIntoPlace(part, target);
        return new Row(s, o, trace, TracePath.read(target), 0);
    }

    /** A name on one terminal line: control characters shown as '?'. */
    private static String oneLine(String s) {
        return s.replaceAll("\\p{Cntrl}", "?");
    }
}
