package org.parpe.cli.hw;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.parpe.cli.Inputs;
import org.parpe.cli.OutputFile;
import org.parpe.cli.UsageException;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.expr.ExprCompiler;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Group;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.bus.BusMaster;
import org.parpe.serial.link.SerialLink;
import org.parpe.serial.record.PoseRecorder;
import org.parpe.serial.record.PoseRecording;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code parpe record}: posable programming from hardware (PARSL.md §12). Makes a group limp,
 * captures a pose on each Enter (or every {@code --every} ms) and saves a PARSL recording that
 * {@code parpe run} plays back. The file is rewritten after every pose, so Ctrl-C, the end of
 * input or a crash never lose what was captured.
 */
@Command(name = "record", mixinStandardHelpOptions = true, description = {"Record poses of a group of modules posed by hand into a PARSL file.",
    "Press Enter to capture a pose; Ctrl-D (end of input) or Ctrl-C finishes."})
public final class RecordCommand implements Callable<Integer> {
    @Option(names = "--port", required = true, paramLabel = "PATH", description = "The serial device of the modules.")
    String port;

    @Option(names = "--baud", defaultValue = "115200", paramLabel = "N", description = "Line speed (default ${DEFAULT-VALUE}).")
    int baud;

    @Option(names = "--group", required = true, paramLabel = "NAME", description = "The group to record.")
    String group;

    @ArgGroup(exclusive = true, multiplicity = "1")
    Source source;

    /** Where the group's modules come from. */
    static class Source {
        @Option(names = "--script", paramLabel = "FILE", description = "A PARSL script whose <robot> defines the group.")
        Path script;

        @Option(names = "--modules", paramLabel = "IDS", description = "The group's modules in order, e.g. 0..3.")
        String modules;
    }

    @Option(names = "--out", required = true, paramLabel = "FILE.xml", description = "The recording to write.")
    Path out;

    @Option(names = "--every", paramLabel = "MS", description = "Capture every MS milliseconds instead of on Enter.")
    Integer every;

    @Option(names = "--count", paramLabel = "N", description = "Stop after N poses.")
    Integer count;

    @Spec
    CommandSpec spec;

    private OutputFile outFile;

    /** Standard input, replaceable by tests. */
    InputStream input = System.in;

    @Override
    public Integer call() throws Exception {
        PrintWriter err = spec.commandLine().getErr();
        try {
            return record(err);
        } catch (UsageException e) {
            err.println("parpe: " + e.getMessage());
            return 2;
        }
    }

    private int[] groupModules() throws UsageException {
        if (source.modules != null) {
            return ModuleList.parse(source.modules, "--modules");
        }
        Inputs.check(source.script);
        LoadResult r = ScriptLoader.load(source.script, Map.of());
        if (r.program() == null) {
            StringBuilder b = new StringBuilder("the script has errors:");
            for (Diagnostic d : r.errors()) {
                b.append('\n').append(d.format());
            }
            throw new UsageException(b.toString());
        }
        Group g = r.program().group(group).orElse(null);
        if (g == null) {
            throw new UsageException("group '" + group + "' is not defined in " + source.script + "; it defines "
                    + String.join(", ", r.program().robot().groups().stream().map(Group::name).toList()));
        }
        return g.modules().stream().mapToInt(Integer::intValue).toArray();
    }

    private void validate() throws UsageException {
        if (every != null && (every < 1 || every > 3_600_000)) {
            throw new UsageException("--every must be in 1..3600000 ms, got " + every);
        }
        if (count != null && count < 1) {
            throw new UsageException("--count must be >= 1, got " + count);
        }
        if (!group.matches("[A-Za-z_][A-Za-z0-9_]*")) {
            throw new UsageException("--group must be a PARSL name ([A-Za-z_][A-Za-z0-9_]*), got '" + group + "'");
        }
        // the recording defines the group, the automaton rec_GROUP and the behavior play_GROUP
        for (String name : new String[] {group, "rec_" + group, "play_" + group}) {
            if (ExprCompiler.isReserved(name) && !name.equals("all")) {
                throw new UsageException("--group '" + group + "' cannot be used: '" + name
                        + "' is a reserved word of PARSL (a function, constant or keyword)");
            }
        }
        outFile = OutputFile.of("--out", out.toString(), source.script == null ? List.of() : List.of(source.script));
    }

    private int record(PrintWriter err) throws UsageException, IOException, InterruptedException {
        validate();
        int[] ids = groupModules();
        BusMaster bus;
        try {
            bus = new BusMaster(SerialLink.open(port, baud), BusConfig.defaults().withBaud(baud));
        } catch (IOException | IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        try {
            PoseRecorder recorder = new PoseRecorder(bus, ids);
            java.util.List<Integer> missing = recorder.missing();
            if (!missing.isEmpty()) {
                throw new UsageException("modules " + missing + " of group '" + group + "' do not answer on " + port
                        + "; nothing was made limp");
            }
            recorder.begin();
            RecordingSession session = new RecordingSession(recorder, new PoseRecording(group, ids), outFile,
                    "recorded from " + port, err);
            SerialLink.beforePortsClose(session::end);
            return session.run(every, count, new BufferedReader(new InputStreamReader(input, StandardCharsets.UTF_8)));
        } finally {
            bus.close();
        }
    }

    /** Formats one pose for the console. */
    static String describe(int n, double t, double[] pose) {
        StringBuilder b = new StringBuilder(String.format(Locale.ROOT, "pose %d at %.3f s:", n, t));
        for (double a : pose) {
            b.append(String.format(Locale.ROOT, " %.2f", a));
        }
        return b.toString();
    }
}
