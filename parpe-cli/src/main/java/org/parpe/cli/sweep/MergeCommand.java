package org.parpe.cli.sweep;

import org.parpe.cli.text.CliMsg;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.parpe.cli.options.Inputs;
import org.parpe.cli.options.OutputFile;
import org.parpe.core.io.CsvCells;
import org.parpe.core.io.IoReasons;
import org.parpe.core.io.OutputPlan;
import org.parpe.cli.options.UsageException;
import org.parpe.core.xml.InputFiles;
import org.parpe.sim.sweep.Axis;
import org.parpe.sim.sweep.IncompleteSweepException;
import org.parpe.sim.sweep.Objective;
import org.parpe.sim.sweep.SweepCsv;
import org.parpe.sim.sweep.SweepCsv.Shard;
import org.parpe.sim.sweep.SweepException;
import org.parpe.sim.sweep.SweepResult;
import org.parpe.sim.sweep.SweepRow;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code parpe merge}: joins the CSV files of the shards of one sweep ({@code sweep --shard K/N})
 * into the file one machine would have written, checking that no run is missing or doubled and
 * that every shard ran to its end; names the shards to run again, and can draw the sweep's plot.
 */
@Command(name = "merge", mixinStandardHelpOptions = true, description = "Join the CSV files of the shards of one sweep"
        + " (parpe sweep --shard K/N) into one, in run order; refuses missing, doubled or foreign runs.")
public final class MergeCommand implements Callable<Integer> {
    @Parameters(arity = "1..*", paramLabel = "SHARD.csv", descriptionKey = "files", description = "The shards' files, in any order.")
    List<Path> files = new ArrayList<>();

    @Option(names = "--out", paramLabel = "FILE.csv|-", defaultValue = "-", description = "The merged file (default: standard output).")
    String out;

    @Option(names = "--plot", paramLabel = "FILE.png", description = "Also draw the plot a one-machine sweep draws.")
    String plot;

    @Option(names = "--objective", paramLabel = "NAME", defaultValue = "forward-speed",
            description = "What the plot ranks by: forward-speed, speed, forward, distance, score (default ${DEFAULT-VALUE}).")
    String objective;

    @Option(names = "--count-fallen", description = "Let a run whose robot fell over be the best on the plot, as sweep"
            + " --count-fallen does (by default it never is).")
    boolean countFallen;

    @Spec
    CommandSpec spec;

    /** Reports missing and unfinished shards, where their unfinished rows are, and how to rerun them. */
    private void incomplete(PrintWriter err, IncompleteSweepException e) {
        e.getMessage().lines().forEach(l -> err.println(l.startsWith("error: ") ? "parpe: " + l.substring(7) : l));
        for (Path partial : partialsBeside()) {
            Shard s = firstLine(partial);
            if (s != null && s.n() == e.of() && e.rerun().contains(s.k())) {
                err.println("parpe: " + CliMsg.PARTIAL_HOLDS.text(partial, s.k(), s.n()));
            }
        }
        String ks = e.rerun().stream().map(String::valueOf).collect(Collectors.joining(","));
        err.println("parpe: " + (e.rerun().size() > 1 ? CliMsg.RERUN_SHARDS : CliMsg.RERUN_SHARD).text(ks, e.of()));
    }

    /** The {@code *.partial} files in the folders of the given shards that were not given themselves. */
    private List<Path> partialsBeside() {
        Set<Path> given = new TreeSet<>();
        Set<Path> dirs = new TreeSet<>();
        for (Path f : files) {
            Path abs = f.toAbsolutePath().normalize();
            given.add(abs);
            dirs.add(abs.getParent());
        }
        List<Path> found = new ArrayList<>();
        for (Path dir : dirs) {
            try (Stream<Path> list = Files.list(dir)) {
                list.filter(p -> p.getFileName().toString().endsWith(".partial") && !given.contains(p)).sorted()
                        .forEach(found::add);
            } catch (IOException e) {
                // a folder we cannot list has nothing to show
            }
        }
        return found;
    }

    private static Shard firstLine(Path file) {
        try (Stream<String> lines = Files.lines(file)) {
            return lines.findFirst().map(SweepCsv::shardOf).orElse(null);
        } catch (IOException | java.io.UncheckedIOException e) {
            return null;
        }
    }

    /** The varied parameters of merged rows, each with the values found. */
    private static List<Axis> axes(List<SweepRow> rows) {
        List<Axis> axes = new ArrayList<>();
        if (!rows.isEmpty()) {
            for (String name : rows.get(0).values().keySet()) {
                axes.add(Axis.list(name, rows.stream().map(r -> r.values().get(name)).distinct().sorted().toList()));
            }
        }
        return axes;
    }

    /**
     * The lines of {@code file} for the merge: a shard's file (its first line is a shard's
     * framing line, {@code sweep --shard}'s own output) is streamed whatever its size, since
     * sweep writes shards of up to 10 million runs; any other file is an input like every
     * other, at most {@link InputFiles#MAX_BYTES}.
     */
    private static SweepCsv.Source source(Path file) {
        return () -> {
            try {
                if (SweepCsv.shardOf(firstLine(file, 256)) == null) {
                    return InputFiles.readText(file).lines();
                }
                InputFiles.checkKind(file);
                return new java.io.BufferedReader(new java.io.InputStreamReader(Files.newInputStream(file),
                        java.nio.charset.StandardCharsets.UTF_8.newDecoder()), 1 << 16).lines();
            } catch (IOException e) {
                throw new IOException(CliMsg.CANNOT_READ.text(file, IoReasons.of(e)), e);
            }
        };
    }

    /** The first line of {@code file} within its first {@code max} bytes (empty if none). */
    private static String firstLine(Path file, int max) throws IOException {
        InputFiles.checkKind(file);
        byte[] head;
        try (java.io.InputStream in = Files.newInputStream(file)) {
            head = in.readNBytes(max);
        }
        String text = new String(head, java.nio.charset.StandardCharsets.UTF_8);
        int end = text.indexOf('\n');
        return end < 0 ? text : text.substring(0, end).replace("\r", "");
    }

    /** Plots the merged rows {@code kept} into {@code png}. */
    private void plot(OutputFile png, List<String> kept, Objective goal, PrintWriter err) throws SweepException, UsageException {
        SweepResult result = SweepCsv.read(kept);
        png.write(o -> Plots.sweep(o, CliMsg.PLOT_TITLE.text(out.equals("-") ? CliMsg.MERGED_SWEEP.text()
                : Path.of(out).getFileName(), result.rows().size()), axes(result.rows()), result.rows(), goal, countFallen));
        err.println("parpe: " + CliMsg.PLOT_IN.text(png));
    }

    /** The shards named, each read once; a file given twice is refused. */
    private Map<String, SweepCsv.Source> shards() throws UsageException, IOException {
        Map<String, SweepCsv.Source> shards = new LinkedHashMap<>();
        for (Path f : files) {
            Inputs.checkKind(f);
            if (shards.containsKey(f.toString())) {
                throw new UsageException(CliMsg.GIVEN_TWICE.text(f));
            }
            shards.put(f.toString(), source(f));
        }
        return shards;
    }

    /** Closes the {@code --out} file, or flushes standard output; false (said on {@code err}) when that failed. */
    private static boolean finish(Writer w, boolean stdout, PrintWriter err) throws IOException {
        if (stdout) {
            w.flush();
            if (((PrintWriter) w).checkError()) {
                err.println("parpe: " + CliMsg.CANNOT_WRITE_STDOUT.text(CliMsg.STDOUT_CLOSED.text()));
                return false;
            }
        } else {
            w.close();
        }
        return true;
    }

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        Writer w = null;
        try {
            Map<String, SweepCsv.Source> shards = shards();
            Objective goal = SimSweepOptions.objective(objective, true);
            OutputPlan plan = OutputFile.plan(files);
            OutputFile target = OutputFile.ofOptional(plan, "--out", out);
            OutputFile png = plot == null ? null : OutputFile.of(plan, "--plot", plot);
            List<String> kept = png == null ? null : new ArrayList<>();
            int runs;
            w = target == null ? spec.commandLine().getOut() : target.openWriter();
            Writer to = w;
            try {
                // foreign cells are copied: a shard may hold text a spreadsheet would run as a formula
                boolean[] header = {true};
                runs = SweepCsv.merge(shards, line -> {
                    if (header[0] && goal == Objective.SCORE && !SweepCsv.scored(line)) {
                        throw new SweepException(CliMsg.SCORE_NEEDS_SCORED_SHARDS.text());
                    }
                    header[0] = false;
                    if (kept != null) {
                        kept.add(line);
                    }
                    to.write(CsvCells.safeLine(line));
                    to.write('\n');
                });
            } catch (IncompleteSweepException e) {
                incomplete(err, e);
                return 1;
            } catch (SweepException e) {
                err.println(e.getMessage().contains(": error: ") ? e.getMessage() : "parpe: " + e.getMessage());
                return 1;
            }
            if (!finish(w, target == null, err)) {
                return 2;
            }
            err.println("parpe: " + CliMsg.MERGED.text(runs, files.size()));
            if (png != null) {
                plot(png, kept, goal, err);
            }
            return 0;
        } catch (UsageException e) {
            err.println("parpe: " + e.getMessage());
            return 2;
        } catch (SweepException e) {
            err.println("parpe: " + e.getMessage());
            return 1;
        } catch (IOException e) {
            err.println("parpe: " + e.getMessage()); // names the file: "cannot read 'F': …", "cannot write --out file 'F': …"
            return 2;
        } catch (java.io.UncheckedIOException e) {
            err.println("parpe: " + CliMsg.CANNOT_READ_SHARD.text(IoReasons.of(e.getCause())));
            return 2;
        } finally {
            OutputFile.abort(w); // a merge that failed leaves the old --out file, no temporary one
        }
    }
}
