package org.parpe.cli.sweep;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.parpe.cli.Inputs;
import org.parpe.cli.OutputFile;
import org.parpe.core.io.CsvCells;
import org.parpe.cli.UsageException;
import org.parpe.core.xml.InputFiles;
import org.parpe.sim.sweep.SweepCsv;
import org.parpe.sim.sweep.SweepException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code parpe merge}: joins the CSV files of the shards of one sweep ({@code sweep --shard K/N})
 * into the file one machine would have written, checking that no run is missing or doubled.
 */
@Command(name = "merge", mixinStandardHelpOptions = true, description = "Join the CSV files of the shards of one sweep"
        + " (parpe sweep --shard K/N) into one, in run order; refuses missing, doubled or foreign runs.")
public final class MergeCommand implements Callable<Integer> {
    @Parameters(arity = "1..*", paramLabel = "SHARD.csv", description = "The shards' files, in any order.")
    List<Path> files = new ArrayList<>();

    @Option(names = "--out", paramLabel = "FILE.csv|-", defaultValue = "-", description = "The merged file (default: standard output).")
    String out;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        Map<String, List<String>> shards = new LinkedHashMap<>();
        try {
            for (Path f : files) {
                Inputs.check(f);
                if (shards.containsKey(f.toString())) {
                    throw new UsageException("'" + f + "' is given twice");
                }
                shards.put(f.toString(), InputFiles.readText(f).lines().toList());
            }
            List<String> merged;
            try {
                merged = SweepCsv.merge(shards);
            } catch (SweepException e) {
                err.println(e.getMessage().contains(": error: ") ? e.getMessage() : "parpe: " + e.getMessage());
                return 1;
            }
            // foreign cells are copied: a shard may hold text a spreadsheet would run as a formula
            String text = String.join("\n", merged.stream().map(CsvCells::safeLine).toList()) + "\n";
            OutputFile target = OutputFile.ofOptional(OutputFile.plan(files), "--out", out);
            if (target == null) {
                PrintWriter o = spec.commandLine().getOut();
                o.print(text);
                if (o.checkError()) {
                    err.println("parpe: cannot write to standard output: it is closed or its pipe is broken");
                    return 2;
                }
            } else {
                target.write(text);
            }
            err.println("parpe: merged " + (merged.size() - 1) + " runs from " + files.size() + " files");
            return 0;
        } catch (UsageException e) {
            err.println("parpe: " + e.getMessage());
            return 2;
        } catch (IOException e) {
            err.println("parpe: cannot read a shard: " + e.getMessage());
            return 2;
        }
    }
}
