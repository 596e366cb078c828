package org.parpe.cli.hw;

import org.parpe.cli.text.CliMsg;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.parpe.cli.options.Inputs;
import org.parpe.cli.options.OutputFile;
import org.parpe.cli.options.ReadsInput;
import org.parpe.cli.options.UsageException;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.lang.Vocabulary;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.model.Group;
import org.parpe.core.run.TargetException;
import org.parpe.serial.bus.BusConfig;
import org.parpe.serial.link.LinkOpener;
import org.parpe.serial.link.SerialLink;
import org.parpe.serial.record.PoseRecorder;
import org.parpe.serial.record.PoseRecording;
import org.parpe.serial.servo.ServoBus;
import org.parpe.serial.servo.ServoModel;
import org.parpe.serial.servo.ServoProtocol;
import org.parpe.serial.servo.host.ServoBuses;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ProfileReader;
import org.parpe.serial.servo.profile.ServoMapping;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code parpe record}: posable programming from hardware (PARSL.md §12). Makes a group limp,
 * captures a pose on each Enter (or every {@code --every} ms) and saves a PARSL recording that
 * {@code parpe run} plays back. The file is rewritten after every pose, so Ctrl-C, the end of
 * input or a crash never lose what was captured.
 */
@Command(name = "record", mixinStandardHelpOptions = true, description = {"Record poses of a group of modules posed by hand into a PARSL file.",
    "Press Enter to capture a pose; Ctrl-D (end of input) or Ctrl-C finishes."})
public final class RecordCommand implements ReadsInput, Callable<Integer> {
    @Option(names = "--port", paramLabel = "PATH",
            description = "The serial device of the modules (G1 without --hardware; overrides the profile's port).")
    String port;

    @Option(names = "--hardware", paramLabel = "PROFILE.xml",
            description = "Record the servos of this hardware profile (Dynamixel 2.0, Feetech STS/SCS or G1).")
    Path hardware;

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

    /** Standard input, or what the command line was handed instead ({@link ReadsInput}). */
    InputStream input = System.in;

    @Override
    public void readFrom(InputStream in) {
        input = in;
    }

    @Override
    public Integer call() throws Exception {
        return record(spec.commandLine().getErr());
    }

    private int[] groupModules() throws UsageException {
        if (source.modules != null) {
            return ModuleList.parse(source.modules, "--modules");
        }
        Inputs.check(source.script);
        LoadResult r = ScriptLoader.load(source.script, Map.of());
        if (r.program() == null) {
            StringBuilder b = new StringBuilder(CliMsg.SCRIPT_HAS_ERRORS.text());
            for (Diagnostic d : r.errors()) {
                b.append('\n').append(d.format());
            }
            throw new UsageException(b.toString());
        }
        Group g = r.program().group(group).orElse(null);
        if (g == null) {
            throw new UsageException(CliMsg.GROUP_NOT_DEFINED.text(group, source.script,
                    String.join(", ", r.program().robot().groups().stream().map(Group::name).toList())));
        }
        return g.modules().stream().mapToInt(Integer::intValue).toArray();
    }

    private void validate() throws UsageException {
        if (every != null && (every < 1 || every > 3_600_000)) {
            throw new UsageException(CliMsg.EVERY_RANGE.text(every));
        }
        if (count != null && count < 1) {
            throw new UsageException(CliMsg.COUNT_AT_LEAST_ONE.text(count));
        }
        if (!group.matches("[A-Za-z_][A-Za-z0-9_]*")) {
            throw new UsageException(CliMsg.GROUP_NAME.text(group));
        }
        // the recording defines the group, the automaton rec_GROUP and the behavior play_GROUP
        for (String name : new String[] {group, "rec_" + group, "play_" + group}) {
            if (Vocabulary.isReserved(name) && !name.equals("all")) {
                throw new UsageException(CliMsg.GROUP_RESERVED.text(group, name));
            }
        }
        List<Path> inputs = new java.util.ArrayList<>();
        if (source.script != null) {
            inputs.add(source.script);
        }
        if (hardware != null) {
            inputs.add(hardware);
        }
        outFile = OutputFile.of(OutputFile.plan(inputs), "--out", out.toString());
    }

    private int record(PrintWriter err) throws UsageException, IOException, InterruptedException {
        validate();
        int[] ids = groupModules();
        HardwareProfile profile = profile();
        List<ServoMapping> servos = mappings(profile, ids);
        String device = profile == null ? port : profile.port();
        if (device == null) {
            throw new UsageException(CliMsg.NO_SERIAL_PORT.text(hardware));
        }
        ServoProtocol protocol = profile == null ? ServoProtocol.G1 : profile.protocol();
        int rate = profile == null ? baud : profile.baud();
        ServoBus bus;
        try {
            bus = ServoBuses.open(protocol, LinkOpener.serial(device, rate), BusConfig.defaults().withBaud(rate));
        } catch (IOException | IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        try {
            PoseRecorder recorder = new PoseRecorder(bus, servos);
            List<Integer> missing = recorder.missing();
            if (!missing.isEmpty()) {
                throw new UsageException(CliMsg.GROUP_SILENT.text(missing, group, device, protocol.key(), rate));
            }
            recorder.begin();
            // A servo recording plays back through its profile; a G1 one through the port.
            String playWith = hardware == null ? "--port " + device
                    : "--hardware " + hardware + (port == null ? "" : " --port " + port);
            RecordingSession session = new RecordingSession(recorder, new PoseRecording(group, ids), outFile,
                    "recorded from " + device, playWith, err);
            SerialLink.beforePortsClose(session::end);
            return session.run(every, count, new BufferedReader(new InputStreamReader(input, StandardCharsets.UTF_8)));
        } finally {
            bus.close();
        }
    }

    private HardwareProfile profile() throws UsageException {
        if (hardware == null) {
            if (port == null) {
                throw new UsageException(CliMsg.GIVE_PORT_OR_HARDWARE.text());
            }
            return null;
        }
        try {
            return ProfileReader.load(hardware, port, "--hardware");
        } catch (TargetException e) {
            StringBuilder b = new StringBuilder(e.getMessage() + ":");
            e.diagnostics().forEach(d -> b.append('\n').append(d.format()));
            throw new UsageException(b.toString());
        }
    }

    /** The group's servos: from the profile, or G1 modules addressed by their module ID. */
    private static List<ServoMapping> mappings(HardwareProfile profile, int[] ids) throws UsageException {
        List<ServoMapping> out = new ArrayList<>();
        List<Integer> unmapped = new ArrayList<>();
        ServoModel g1 = ServoModel.defaultFor(ServoProtocol.G1);
        for (int id : ids) {
            ServoMapping m = profile == null
                    ? new ServoMapping(id, id, g1, 0, 1, g1.minDegrees(), g1.maxDegrees(), SourcePos.origin("--port"))
                    : profile.forModule(id);
            if (m == null) {
                unmapped.add(id);
            } else {
                out.add(m);
            }
        }
        if (!unmapped.isEmpty()) {
            throw new UsageException(CliMsg.NO_SERVO_FOR_MODULES.text(unmapped, profile.file()));
        }
        return out;
    }

    /** Formats one pose for the console. */
    static String describe(int n, double t, double[] pose) {
        StringBuilder b = new StringBuilder(CliMsg.POSE_AT.text(n, String.format(Locale.ROOT, "%.3f", t)));
        for (double a : pose) {
            b.append(String.format(Locale.ROOT, " %.2f", a));
        }
        return b.toString();
    }
}
