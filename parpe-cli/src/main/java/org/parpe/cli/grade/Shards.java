package org.parpe.cli.grade;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.parpe.cli.options.UsageException;
import org.parpe.sim.grade.GradeShard;
import org.parpe.sim.grade.Grading;
import org.parpe.sim.grade.Row;
import org.parpe.sim.grade.Students;
import org.parpe.sim.sweep.SweepSpec;

/**
 * {@code parpe grade --merge N}: the files of the N shards of a grading, checked (each there,
 * whole, of this class, split as a sweep is) and ranked into the rows a one-machine grading
 * gives; a missing shard is named with the students it holds and how to run it again.
 */
final class Shards {
    private Shards() {
    }

    static List<Row> merge(Grading grading, List<Students.Student> students, int n) throws UsageException {
        if (n < 1 || n > 999_999) {
            throw new UsageException("--merge expects the number of shards N, 1..999999, got " + n);
        }
        List<GradeShard.Part> parts = new ArrayList<>();
        List<String> missing = new ArrayList<>();
        for (int k = 1; k <= n; k++) {
            int[] range = SweepSpec.shard(students.size(), k, n);
            Path file = grading.out().resolve(GradeShard.fileName(k, n));
            if (!Files.exists(file)) {
                missing.add(k + (range[0] < range[1] ? " (students " + (range[0] + 1) + ".." + range[1] + ")" : ""));
                continue;
            }
            GradeShard.Part p;
            try {
                p = GradeShard.read(file);
            } catch (IOException e) {
                throw new UsageException(e.getMessage());
            }
            if (p.k() != k || p.n() != n || p.from() != range[0] || p.to() != range[1]) {
                throw new UsageException(file + ":1: holds students " + (p.from() + 1) + ".." + p.to() + " as shard " + p.k()
                        + "/" + p.n() + ", not shard " + k + "/" + n + " of these " + students.size() + " students");
            }
            parts.add(p);
        }
        if (!missing.isEmpty()) {
            String ks = String.join(", ", missing);
            throw new UsageException("shard" + (missing.size() > 1 ? "s " : " ") + ks + " of " + n + " missing in '"
                    + grading.out() + "': run it again (parpe grade CHALLENGE STUDENTS_DIR --out " + grading.out()
                    + " --shard K/" + n + "; with scripts/grade.slurm: PARPE_SHARDS=" + n + " sbatch --array=K ...),"
                    + " then merge again; see docs/cluster.md");
        }
        try {
            return grading.merge(students, parts);
        } catch (IOException e) {
            throw new UsageException(e.getMessage());
        }
    }
}
