package org.parpe.cli.export;

import org.parpe.cli.text.CliMsg;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import org.parpe.cli.options.UsageException;
import org.parpe.core.diag.Severity;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.model.Program;
import org.parpe.core.run.PlateSink;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.Stimulus;
import org.parpe.core.run.TargetException;
import org.parpe.sim.SimTarget;
import org.parpe.sim.bridge.Export;
import org.parpe.sim.bridge.Latches;
import org.parpe.sim.bridge.RobotModel;

/**
 * {@code parpe export --target mjcf|urdf|sdf --robot ROBOT --out DIR [SCRIPT]}: the robot in
 * another tool's format and, with a script, the commanded angles of a run of it on that robot
 * (for MJCF with a Python runner that plays them in MuJoCo). docs/bridges.md says how to use them.
 */
final class RobotExport {
    private RobotExport() {
    }

    /** What to export. */
    record Request(String target, String robot, Program program, List<Stimulus> stimuli, double duration, double tick,
                   Path out) {
    }

    /** Exports; returns the exit code (1: the robot or the names are wrong, located messages on {@code err}). */
    static int run(Request q, PrintWriter out, PrintWriter err) throws IOException, UsageException {
        DiagnosticList diags = new DiagnosticList();
        int[] ids = q.program() == null ? new int[0] : q.program().moduleIds();
        Set<Integer> latching = q.program() == null ? Set.of() : latchModules(q.program());
        Export.Robot robot = Export.robot(q.target(), q.robot(), ids, latching, diags);
        if (robot == null) {
            diags.all().forEach(d -> err.println(d.format()));
            return 1;
        }
        RobotModel m = robot.model();
        String base = robot.base();
        Map<String, String> files = new LinkedHashMap<>(robot.files());
        List<Latches.Pair> latches = robot.latches();
        if (q.program() != null) {
            String gait = gait(q, m, q.target().equals("mjcf") ? plates(latches) : List.of(), diags);
            diags.all().stream().filter(d -> d.severity() != Severity.ERROR).forEach(d -> err.println(d.format()));
            if (gait == null) {
                diags.all().stream().filter(d -> d.severity() == Severity.ERROR).forEach(d -> err.println(d.format()));
                return 3;
            }
            files.put(base + (q.target().equals("mjcf") ? ".ctrl.csv" : ".joints.csv"), gait);
            if (q.target().equals("mjcf")) {
                files.put("play_mujoco.py", runner());
            }
        }
        ExportFiles.write(q.out(), files);
        out.println((files.size() == 1 ? CliMsg.WROTE_ONE_FILE_LIST : CliMsg.WROTE_FILES_LIST).text(files.size(), q.out(),
                String.join(", ", files.keySet())));
        out.println(robot.summary());
        if (q.target().equals("mjcf") && q.program() != null) {
            out.println(CliMsg.PLAY.text() + ": python3 " + q.out().resolve("play_mujoco.py") + " " + q.out().resolve(base + ".xml") + " "
                    + q.out().resolve(base + ".ctrl.csv") + " --out trace.csv");
        }
        return 0;
    }

    /** The modules of {@code p} that carry the latch actuator (PARSL.md §14). */
    private static Set<Integer> latchModules(Program p) {
        Set<Integer> out = new TreeSet<>();
        p.robot().actuators().stream().filter(d -> d.type().equals("latch")).forEach(d -> out.addAll(d.modules()));
        return out;
    }

    /** The plates of {@code latches}, each once, in ascending module ID and plate. */
    private static List<Latches.Plate> plates(List<Latches.Pair> latches) {
        Set<Latches.Plate> out = new TreeSet<>((x, y) -> x.moduleId() != y.moduleId()
                ? Integer.compare(x.moduleId(), y.moduleId()) : Integer.compare(x.plate(), y.plate()));
        latches.forEach(l -> {
            out.add(l.a());
            out.add(l.b());
        });
        return new ArrayList<>(out);
    }

    /**
     * The commanded angles of a run of the script on the robot in the simulator, one row per
     * tick: for MJCF the module angles (the actuators' controls), for URDF and SDF the joint
     * values (module angle minus initial angle), radians, columns m&lt;ID&gt; in ascending ID;
     * then per latchable plate a column plate&lt;ID&gt;_&lt;P&gt; with the tick's plate action
     * ({@link PlateSink#NONE} 0, {@link PlateSink#ARM} 1, {@link PlateSink#RELEASE} 2).
     */
    private static String gait(Request q, RobotModel m, List<Latches.Plate> plates, DiagnosticList diags)
            throws UsageException {
        List<RobotModel.Joint> joints = new ArrayList<>(m.joints().stream().filter(RobotModel.Joint::revolute).toList());
        joints.sort((x, y) -> Integer.compare(x.moduleId(), y.moduleId()));
        int[] ids = q.program().moduleIds();
        int[] column = new int[joints.size()];
        double[] offset = new double[joints.size()];
        for (int k = 0; k < joints.size(); k++) {
            column[k] = java.util.Arrays.binarySearch(ids, joints.get(k).moduleId());
            offset[k] = q.target().equals("mjcf") ? 0 : joints.get(k).initial();
        }
        StringBuilder csv = new StringBuilder("time");
        joints.forEach(j -> csv.append(',').append(j.name()));
        plates.forEach(p -> csv.append(',').append(p.name()));
        csv.append('\n');
        int[] plateAt = new int[plates.size()];
        for (int k = 0; k < plateAt.length; k++) {
            plateAt[k] = 2 * java.util.Arrays.binarySearch(ids, plates.get(k).moduleId()) + plates.get(k).plate();
        }
        byte[] acts = new byte[2 * ids.length];
        Run.Builder b = Run.builder(q.program(), new RunOptions(q.tick(), 0, q.stimuli()), diags);
        try {
            b.attach(new SimTarget(q.robot()));
        } catch (TargetException e) {
            e.diagnostics().forEach(diags::report);
            return null;
        }
        if (!plates.isEmpty()) {
            // a tick's plate actions come before its setpoints reach the observer (Engine)
            b.plates((tick, time, actions, where) -> System.arraycopy(actions, 0, acts, 0, acts.length));
        }
        b.observer((tick, time, commanded) -> {
            csv.append(String.format(Locale.ROOT, "%.6f", time));
            for (int k = 0; k < column.length; k++) {
                double deg = column[k] < 0 ? Math.toDegrees(joints.get(k).initial()) : commanded[column[k]];
                csv.append(',').append(String.format(Locale.ROOT, "%.9f", Math.toRadians(deg) - offset[k]));
            }
            for (int at : plateAt) {
                csv.append(',').append(acts[at]);
            }
            java.util.Arrays.fill(acts, PlateSink.NONE);
            csv.append('\n');
        });
        RunOutcome o = b.duration(q.duration()).build().execute();
        return o.status() == RunOutcome.Status.ERROR ? null : csv.toString();
    }

    private static String runner() throws IOException {
        try (var in = RobotExport.class.getResourceAsStream("play_mujoco.py")) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }
}
