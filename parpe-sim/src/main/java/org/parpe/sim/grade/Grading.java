package org.parpe.sim.grade;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import org.parpe.core.io.AtomicFiles;
import org.parpe.sim.world.Challenge;
import org.parpe.sim.text.SimMsg;

/**
 * Grades a class: every student of a folder run in a challenge, {@code jobs} children at once
 * ({@link Isolation}), each run's trace kept as {@code OUT/traces/NNN.csv} (NNN: the student's
 * place in name order, from 1), the rows ranked ({@link Row#ranked}). Used by {@code parpe
 * grade} and the IDE's Class window alike; the rows depend only on the inputs, not on
 * {@code jobs}. Interrupting the calling thread stops the runs under way (their children killed).
 *
 * @param challengeFile the challenge file, as the children read it
 * @param challenge     the challenge read from it
 * @param studentsDir   the students' folder (the children's working folder)
 * @param out           the report folder; its {@code traces} folder must exist
 * @param limits        each run's CPU-time and memory limit
 */
public record Grading(Path challengeFile, Challenge challenge, Path studentsDir, Path out, Isolation.Limits limits) {
    /** Told of each student graded, from the worker threads, one call at a time. */
    public interface Listener {
        /** Student {@code s} is graded, the {@code done}-th of {@code total}. */
        void graded(int done, int total, Students.Student s);
    }

    /** The trace of the {@code index}-th student (from 0), relative to the report folder. */
    public static String traceName(int index) {
        return String.format(Locale.ROOT, "traces/%03d.csv", index + 1);
    }

    /**
     * Makes the report folder {@code out} and its traces folder: null, or why not (one inside the
     * students' folder is refused: the next grading would take the report for a student), the
     * folder named as {@code what} calls it ("--out").
     */
    public static String prepare(Path out, Path studentsDir, String what) {
        try {
            Path existing = out.toAbsolutePath().normalize();
            while (!Files.exists(existing)) { // the part of out that exists, links followed
                existing = existing.getParent();
            }
            if (existing.toRealPath().startsWith(studentsDir.toRealPath())) {
                return SimMsg.GRADE_OUT_INSIDE.text(what, studentsDir);
            }
            Files.createDirectories(out.resolve("traces"));
            return null;
        } catch (IOException e) {
            return SimMsg.GRADE_CANNOT_MAKE_REPORT.text(out, e.getMessage());
        }
    }

    /** Grades {@code students} (the whole class, in name order) with {@code jobs} runs at once; the rows ranked. */
    public List<Row> run(List<Students.Student> students, int jobs, Listener listener) throws InterruptedException {
        return Row.ranked(run(students, 0, students.size(), jobs, listener), challenge.tieBreak());
    }

    /**
     * Grades the students {@code from}..{@code to}−1 of the class {@code students} (a shard), with
     * {@code jobs} runs at once; their rows in name order, not ranked.
     */
    public List<Row> run(List<Students.Student> students, int from, int to, int jobs, Listener listener)
            throws InterruptedException {
        ExecutorService pool = Executors.newFixedThreadPool(jobs);
        AtomicInteger done = new AtomicInteger();
        Object lock = new Object();
        List<Future<Row>> futures = new ArrayList<>();
        for (int i = from; i < to; i++) {
            Students.Student s = students.get(i);
            String trace = traceName(i);
            futures.add(pool.submit(() -> {
                Row r = runOne(s, trace);
                synchronized (lock) {
                    listener.graded(done.incrementAndGet(), to - from, s);
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
        } catch (ExecutionException e) {
            throw new IllegalStateException("grading failed", e.getCause());
        } finally {
            pool.shutdownNow();
        }
        return rows;
    }

    /**
     * The rows of the shards {@code parts} of this class: they must cover the students exactly
     * once, each under its name; ranked. Throws with what is missing, doubled or foreign.
     */
    public List<Row> merge(List<Students.Student> students, List<GradeShard.Part> parts) throws IOException {
        Row[] rows = new Row[students.size()];
        for (GradeShard.Part p : parts) {
            if (p.total() != students.size()) {
                throw new IOException(SimMsg.GRADE_SHARD_CLASS.text(p.k() + "/" + p.n(), p.total(), studentsDir,
                        students.size()));
            }
            for (int i = p.from(); i < p.to(); i++) {
                Students.Student s = students.get(i);
                if (!s.name().equals(p.names().get(i - p.from()))) {
                    throw new IOException(SimMsg.GRADE_SHARD_NAME.text(p.k() + "/" + p.n(), p.names().get(i - p.from()),
                            i + 1, s.name()));
                }
                if (rows[i] != null) {
                    throw new IOException(SimMsg.GRADE_STUDENT_TWICE.text(i + 1, s.name()));
                }
                String trace = p.traces().get(i - p.from());
                rows[i] = new Row(s, p.outcomes().get(i - p.from()), trace,
                        trace.isEmpty() ? new double[0] : TracePath.read(out.resolve(trace)), 0);
            }
        }
        return Row.ranked(java.util.Arrays.asList(rows), challenge.tieBreak());
    }

    private Row runOne(Students.Student s, String trace) throws IOException, InterruptedException {
        if (!s.problem().isEmpty()) {
            return new Row(s, Outcome.failed(s.problem()), "", new double[0], 0);
        }
        Path target = out.resolve(trace);
        Path part = target.resolveSibling(target.getFileName() + ".part");
        Files.deleteIfExists(part);
        Outcome o = Isolation.run(challengeFile, studentsDir, s.script(), s.root(), part, limits);
        // a run that counts, or that ran until a run-time error (its time), keeps its trace; one stopped at a limit does not
        boolean keep = Files.isRegularFile(part) && (o.ranked() || o.time() > 0);
        if (!keep) {
            Files.deleteIfExists(part);
            Files.deleteIfExists(target);
            return new Row(s, o, "", new double[0], 0);
        }
        AtomicFiles.moveIntoPlace(part, target);
        return new Row(s, o, trace, TracePath.read(target), 0);
    }
}
