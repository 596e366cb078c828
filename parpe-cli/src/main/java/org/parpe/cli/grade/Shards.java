package org.parpe.cli.grade;

import org.parpe.cli.text.CliMsg;
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
            throw new UsageException(CliMsg.MERGE_N_RANGE.text(n));
        }
        List<GradeShard.Part> parts = new ArrayList<>();
        List<String> missing = new ArrayList<>();
        for (int k = 1; k <= n; k++) {
            int[] range = SweepSpec.shard(students.size(), k, n);
            Path file = grading.out().resolve(GradeShard.fileName(k, n));
            if (!Files.exists(file)) {
                missing.add(range[0] < range[1] ? CliMsg.SHARD_STUDENTS.text(k, range[0] + 1, range[1]) : Integer.toString(k));
                continue;
            }
            GradeShard.Part p;
            try {
                p = GradeShard.read(file);
            } catch (IOException e) {
                throw new UsageException(e.getMessage());
            }
            if (p.k() != k || p.n() != n || p.from() != range[0] || p.to() != range[1]) {
                throw new UsageException(file + ":1: " + CliMsg.WRONG_GRADE_SHARD.text(p.from() + 1, p.to(), p.k() + "/" + p.n(),
                        k + "/" + n, students.size()));
            }
            parts.add(p);
        }
        if (!missing.isEmpty()) {
            String ks = String.join(", ", missing);
            throw new UsageException((missing.size() > 1 ? CliMsg.GRADE_SHARDS_MISSING : CliMsg.GRADE_SHARD_MISSING)
                    .text(ks, n, grading.out()));
        }
        try {
            return grading.merge(students, parts);
        } catch (IOException e) {
            throw new UsageException(e.getMessage());
        }
    }
}
