package org.parpe.gui.app;

import org.parpe.gui.text.UiMsg;
import org.parpe.gui.hardware.HardwareDialog;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.Consumer;
import org.eclipse.jface.window.Window;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.diag.Severity;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.load.LoadResult;
import org.parpe.core.lang.Numbers;
import org.parpe.core.model.Parameter;
import org.parpe.core.model.Program;
import org.parpe.core.run.Engine;
import org.parpe.core.run.EngineStatus;
import org.parpe.core.run.Run;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.RunOutcome;
import org.parpe.core.run.TargetException;
import org.parpe.gui.editor.ScriptDocument;
import org.parpe.gui.panels.ControlPanel;
import org.parpe.gui.panels.ParametersDialog;
import org.parpe.core.plot.AngleRecorder;
import org.parpe.gui.run.RunController;
import org.parpe.gui.run.RunOn;
import org.parpe.serial.bus.BusConfig;
import org.parpe.sim.SimMetrics;
import org.parpe.serial.servo.run.ServoDriver;
import org.parpe.serial.servo.run.ServoTarget;
import org.parpe.sim.snapshot.SimSnapshot;
import org.parpe.sim.SimTarget;
import org.parpe.sim.Simulator;
import org.parpe.sim.world.World;
import org.parpe.sim.world.WorldScore;
import org.parpe.sim.config.RobotConfig;
import org.parpe.sim.config.RobotConfigs;

/**
 * Run, Pause, Stop and the emergency stop; builds each run (parameters dialog, engine,
 * simulator, serial bus, plot recorder) and keeps the robot preview of the 3D view. The
 * engine runs on the {@link RunController}'s thread; everything here runs on the UI thread.
 */
public final class RunActions implements ControlPanel.ControlSink {
    private final IdeWindow ide;
    private final RunController controller;
    private final ExecutorService previewer = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "parpe-preview");
        t.setDaemon(true);
        return t;
    });
    private volatile Simulator sim;
    private volatile ServoDriver servos;
    private volatile SimSnapshot preview;
    private volatile String hardwareState = UiMsg.HW_NOT_CONNECTED.text();
    private String previewKey = "";
    private RunOutcome lastOutcome;
    /** Whether the run going on was ended by the emergency stop. */
    private boolean emergency;
    private volatile SimMetrics lastMetrics;
    /** The time limit of the world the run is in when it lasts that long (no duration given), else NaN. */
    private double worldLimit = Double.NaN;
    /** The score of the last run in a world, shown on the 3D line until the next run or another script or world. */
    private WorldScore finalScore;

    RunActions(IdeWindow ide) {
        this.ide = ide;
        this.controller = new RunController(ide.shell.getDisplay());
    }

    public RunController controller() {
        return controller;
    }

    public boolean running() {
        return controller.running();
    }

    RunOutcome lastOutcome() {
        return lastOutcome;
    }

    /** The picture for the 3D view: the running simulator's, else the preview. */
    public SimSnapshot snapshot() {
        Simulator s = sim;
        return s != null ? s.snapshot() : preview;
    }

    /** The modules driven at the last tick (empty when idle). */
    Set<Integer> driven() {
        EngineStatus st = controller.status();
        if (st == null || !running()) {
            return Set.of();
        }
        Set<Integer> out = new HashSet<>();
        for (int id : st.driven()) {
            out.add(id);
        }
        return out;
    }

    /** The user picked {@code t} in the tool bar for the file in the editor. */
    void targetChosen(RunOn t) {
        ide.choices.targetChosen(t);
    }

    /** Opens the Hardware dialog (Run > Hardware…). */
    void openHardware() {
        HardwareDialog.open(ide.hardware);
    }

    String hardwareState() {
        long since = hardwareSilentSince();
        return since < 0 ? hardwareState : UiMsg.HW_NOT_RESPONDING.text(silentTime(since));
    }

    /** The wall-clock time {@code since} (ms), as the status bar says when the robot went silent. */
    static String silentTime(long since) {
        // always with seconds: LocalTime.toString leaves ":00" out, so one alarm a minute read "09:31"
        return java.time.format.DateTimeFormatter.ofPattern("HH:mm:ss")
                .format(java.time.LocalTime.ofInstant(java.time.Instant.ofEpochMilli(since), java.time.ZoneId.systemDefault()));
    }

    /** Since when (wall-clock ms) the run's servos or G1 modules have not answered; −1 while they do or none are driven. */
    long hardwareSilentSince() {
        ServoDriver d = servos;
        return d != null ? d.notAnsweringSince() : -1;
    }

    /**
     * Starts a run of the editor's text (resumes if paused).
     *
     * @param interactive whether to ask for parameter values (automation uses the remembered ones)
     * @param runFor      simulated seconds to run, or negative for until the program ends
     * @param onEnd       also told the outcome (automation), may be null
     */
    public void run(boolean interactive, double runFor, Consumer<RunOutcome> onEnd) {
        if (controller.running()) {
            if (controller.paused()) {
                pause();
            }
            return;
        }
        if (ide.toolbar.target().hardware() && ide.hardware.held() != null) {
            // Two owners of one serial port would garble each other's packets.
            String why = UiMsg.HARDWARE_DIALOG_HOLDS_BUS.text();
            ide.status.setMessage(UiMsg.CANNOT_RUN.text(why));
            ide.shell.getDisplay().beep();
            report(onEnd, new RunOutcome(RunOutcome.Status.ERROR, 0, why));
            return;
        }
        if (ide.checks.emptyScript()) {
            ide.status.setMessage(UiMsg.CANNOT_RUN_EMPTY.text());
            report(onEnd, new RunOutcome(RunOutcome.Status.ERROR, 0, UiMsg.OUTCOME_FILE_EMPTY.text()));
            return;
        }
        // read afresh: the run sees the files the script includes as they are now
        ScriptDocument.Loaded read = ide.document.reread();
        LoadResult first = read.result();
        ide.checks.show(first);
        if (first.program() == null) {
            ide.status.setMessage(UiMsg.CANNOT_RUN_ERRORS.text(first.errors().size()));
            ide.bottom.showProblems();
            ide.shell.getDisplay().beep();
            report(onEnd, new RunOutcome(RunOutcome.Status.ERROR, 0, UiMsg.OUTCOME_SCRIPT_ERRORS.text()));
            return;
        }
        Map<String, Double> params = parameters(first.program(), interactive);
        if (params == null) {
            ide.status.setMessage(UiMsg.RUN_CANCELLED.text());
            return;
        }
        LoadResult loaded = read.bind(params);
        if (!loaded.ok()) {
            ide.checks.show(loaded);
            ide.problems().clearRunDiagnostics();
            loaded.parameterErrors().forEach(ide.bottom::runProblemLater);
            String why = loaded.parameterErrors().isEmpty() ? UiMsg.ERRORS_WITH_PARAMETERS.text()
                    : loaded.parameterErrors().get(0).message();
            ide.status.setMessage(UiMsg.CANNOT_RUN.text(why));
            ide.bottom.showProblems();
            report(onEnd, new RunOutcome(RunOutcome.Status.ERROR, 0, why));
            return;
        }
        start(loaded.program(), runFor, onEnd);
    }

    private void start(Program program, double runFor, Consumer<RunOutcome> onEnd) {
        RunOn target = ide.toolbar.target();
        start(program, target, robotSpec(program), runFor, onEnd);
        String misfit = target.sim() ? misfit(program, ide.robotChoice()) : null;
        if (misfit != null) {
            ide.bottom.runProblemLater(new Diagnostic(Severity.WARNING, SourcePos.origin(UiMsg.ORIGIN_ROBOT.text(ide.robotChoice())), misfit));
        }
    }

    /**
     * Why the robot {@code choice} does not fit {@code program}, or null: a standard robot other than
     * the one {@code auto} picks for the script (a snake lesson run on the humanoid after a
     * humanoid lesson). A configuration file is the user's own choice and is not second-guessed.
     */
    static String misfit(Program program, String choice) {
        if (SimTarget.AUTO.equals(choice) || !RobotConfigs.generatorNames().contains(choice)) {
            return null;
        }
        String fits = SimTarget.autoSpec(program);
        return fits.equals(choice) ? null : UiMsg.ROBOT_MISFIT.text(fits, choice);
    }

    /**
     * Runs a program made by the IDE (the Pose panel's playback) on {@code target}, simulating
     * the robot {@code spec}, until it ends or is stopped; refused while a run is going on or
     * the Hardware dialog holds the bus a hardware target needs.
     */
    void play(Program program, RunOn target, String spec, Consumer<RunOutcome> onEnd) {
        if (controller.running()) {
            report(onEnd, new RunOutcome(RunOutcome.Status.ERROR, 0, UiMsg.OUTCOME_RUN_GOING_ON.text()));
            return;
        }
        if (target.hardware() && ide.hardware.held() != null) {
            ide.status.setMessage(UiMsg.CANNOT_PLAY_ON_ROBOT.text());
            report(onEnd, new RunOutcome(RunOutcome.Status.ERROR, 0, UiMsg.HARDWARE_DIALOG_HOLDS_BUS.text()));
            return;
        }
        start(program, target, spec, -1, onEnd);
    }

    private void start(Program program, RunOn target, String spec, double runFor, Consumer<RunOutcome> onEnd) {
        String port = ide.toolbar.port();
        String profile = ide.toolbar.hardwareProfile();
        AngleRecorder recorder = org.parpe.gui.panels.PlotView.newRecorder();
        ide.plots.setModules(program.moduleIds());
        ide.plots.setRecorder(recorder);
        ide.problems().clearRunDiagnostics();
        ide.bottom.log(UiMsg.LOG_RUN.text(ide.files.name(), target.label(), target.sim() ? UiMsg.LOG_RUN_ROBOT.text(spec) : "",
                !target.hardware() ? "" : profile == null ? UiMsg.LOG_RUN_PORT.text(port) : UiMsg.LOG_RUN_PORT_PROFILE.text(port, profile)));
        controller.setSpeed(ide.toolbar.speed());
        finalScore = null;
        Run.Builder run = Run.builder(program, RunOptions.defaults(), ide.bottom::runProblemLater);
        World world = target.sim() ? ide.viewBar.world().world() : null; // read on the UI thread
        // a world's challenge lasts its time limit, as on the command line
        double limit = world != null && runFor < 0 ? world.timeLimit() : runFor;
        worldLimit = world != null && runFor < 0 ? world.timeLimit() : Double.NaN;
        controller.start(run, b -> attach(b, target, spec, world, port, profile, recorder), limit, outcome -> {
            if (ide.shell.isDisposed()) {
                return; // the window closed while the run was ending
            }
            ended(outcome);
            report(onEnd, outcome);
        }, ide.bottom::logLater);
        ide.controls.pushAll();
        ide.runStateChanged();
    }

    /** The robot to simulate: the picker's choice, or the one that fits the script for "auto". */
    private String robotSpec(Program program) {
        String choice = ide.robotChoice();
        return SimTarget.AUTO.equals(choice) ? SimTarget.autoSpec(program) : choice;
    }

    /**
     * Attaches the run's targets on the engine thread, as the command line does (opening the
     * bus and building the simulated robot take time), and the plots' recorder.
     */
    private void attach(Run.Builder run, RunOn target, String spec, World world, String port, String profile,
                        AngleRecorder recorder) throws TargetException {
        if (target.hardware()) {
            ServoTarget st = ServoTarget.open(profile == null ? null : Path.of(profile), port, UiMsg.HARDWARE_PROFILE.text(),
                    BusConfig.defaults(), ide.bottom::logLater);
            hardwareState = UiMsg.HW_CONNECTING.text(st.port() == null ? "" : st.port());
            attachDriver(run, st, st.profile() == null ? "" : " (" + st.profile().protocol().key() + ")");
        }
        if (target.sim()) {
            SimTarget st = new SimTarget(spec, world);
            run.attach(st);
            Simulator s = st.simulator();
            sim = s;
            run.closeAtEnd(() -> {
                preview = s.snapshot();
                lastMetrics = s.metrics();
                sim = null;
            });
        }
        recorder.attachTo(run);
    }

    /** Attaches {@code st}; the status line names its device, then {@code what}. */
    private void attachDriver(Run.Builder run, ServoTarget st, String what) throws TargetException {
        try {
            run.attach(st);
        } finally {
            hardwareState = st.driver() == null ? UiMsg.HW_NOT_CONNECTED.text() : UiMsg.HW_DRIVER.text(st.driver().name() + what);
        }
        servos = st.driver();
        // the servos do not latch: the user joins and parts plates by hand while the run waits (PARSL.md §14)
        run.plates(new HandDocking(ide, controller, run.engine().moduleIds()));
        run.closeAtEnd(() -> {
            servos = null;
            hardwareState = UiMsg.HW_DISCONNECTED.text();
        });
    }

    private void ended(RunOutcome outcome) {
        lastOutcome = outcome;
        boolean emergency = this.emergency;
        this.emergency = false;
        String t = String.format(java.util.Locale.ROOT, "%.2f s", outcome.time());
        SimMetrics m = lastMetrics;
        lastMetrics = null;
        boolean measured = m != null && outcome.status() != RunOutcome.Status.ERROR;
        String travelled = !measured ? "" : UiMsg.RUN_TRAVELLED.text(String.format(java.util.Locale.ROOT, "%.3f", m.distance()),
                String.format(java.util.Locale.ROOT, "%.3f", m.speed()), String.format(java.util.Locale.ROOT, "%+.3f", m.dx()));
        WorldScore score = measured ? m.score() : null;
        finalScore = score;
        if (m != null && m.fell()) {
            String choice = ide.robotChoice();
            ide.bottom.runProblemLater(new Diagnostic(Severity.WARNING, SourcePos.origin(UiMsg.ORIGIN_ROBOT.text(choice)), UiMsg.ROBOT_FELL,
                    String.format(java.util.Locale.ROOT, "%.0f", m.maxTiltDeg()), String.format(java.util.Locale.ROOT, "%.0f",
                    SimMetrics.FALL_TILT_DEG), SimTarget.AUTO.equals(choice) ? "" : UiMsg.ROBOT_FELL_WHICH.text(choice)));
            travelled += UiMsg.RUN_FELL_OVER.text();
        }
        String said = switch (outcome.status()) {
            case COMPLETED -> (outcome.time() >= worldLimit - 1e-6 ? UiMsg.RUN_TIME_LIMIT : UiMsg.RUN_COMPLETED).text(t, travelled);
            // An emergency stop is not an ordinary stop: the log and the status bar say which it was.
            case STOPPED -> (emergency ? UiMsg.RUN_EMERGENCY_STOPPED : UiMsg.RUN_STOPPED).text(t, travelled);
            case ERROR -> UiMsg.RUN_FAILED.text(outcome.message());
        };
        ide.bottom.log(said);
        if (score == null) {
            ide.status.setMessage(said);
        } else {
            // What a teacher records comes first: the status bar cuts a long message at its end.
            String points = UiMsg.RUN_SCORE.text(String.format(java.util.Locale.ROOT, "%.1f", score.score()));
            ide.bottom.log(points + ": " + score.inWords());
            ide.status.setMessage(points + " (" + score.inWords() + ") \u2014 " + Character.toLowerCase(said.charAt(0))
                    + said.substring(1));
            ide.bottom.showRunLog();
        }
        ide.runStateChanged();
    }

    private static void report(Consumer<RunOutcome> onEnd, RunOutcome outcome) {
        if (onEnd != null) {
            onEnd.accept(outcome);
        }
    }

    /** The parameter values for a run: asked in the dialog, or the remembered ones; null if cancelled. */
    private Map<String, Double> parameters(Program program, boolean interactive) {
        if (program.parameters().isEmpty()) {
            return Map.of();
        }
        String key = "params." + ide.files.pathForLoading() + ".";
        Map<String, Double> last = new HashMap<>();
        for (Parameter p : program.parameters()) {
            Double v = Numbers.parsePlain(ide.prefs.get(key + p.name(), ""));
            last.put(p.name(), v != null && p.check(v) == null ? v : p.value());
        }
        if (!interactive) {
            return last;
        }
        ParametersDialog d = new ParametersDialog(ide.shell, program.parameters(), last);
        if (d.open() != Window.OK) {
            return null;
        }
        d.values().forEach((name, v) -> ide.prefs.put(key + name, Numbers.format(v)));
        return d.values();
    }

    void pause() {
        if (controller.running()) {
            controller.setPaused(!controller.paused());
            ide.status.setMessage(controller.paused() ? UiMsg.RUN_PAUSED.text() : UiMsg.RUN_RUNNING.text());
            ide.runStateChanged();
        }
    }

    public void stop() {
        controller.stop();
    }

    /** Esc: stops the run at the next tick and tells the modules on the bus to stop at once. */
    void emergencyStop() {
        controller.stop();
        ServoDriver s = servos;
        if (s != null) {
            s.emergencyStop();
        }
        if (controller.running()) {
            emergency = true;
            ide.bottom.log(UiMsg.LOG_EMERGENCY_STOP.text());
            ide.status.setMessage(UiMsg.RUN_EMERGENCY_STOP.text());
        }
    }

    @Override
    public void setControl(String name, double value) {
        control(name, e -> e.setControl(name, value));
    }

    @Override
    public void setControlWord(String name, String word) {
        control(name, e -> e.setControlWord(name, word));
    }

    /**
     * Applies a control change to the running engine (at its next tick); a refused value becomes
     * a problem located at the control's definition.
     */
    private void control(String name, Consumer<Engine> change) {
        Engine e = controller.engine();
        if (e == null || !controller.running()) {
            return;
        }
        try {
            change.accept(e);
        } catch (IllegalArgumentException ex) {
            Program p = e.program();
            SourcePos where = p.controls().stream().filter(c -> c.name().equals(name)).map(c -> c.pos())
                    .findFirst().orElse(SourcePos.origin(UiMsg.ORIGIN_CONTROL.text(name)));
            ide.bottom.runProblemLater(new Diagnostic(Severity.ERROR, where, ex.getMessage()));
        }
    }

    /** Shows {@code program}'s robot in its starting pose when idle (built off the UI thread). */
    void updatePreview(Program program) {
        if (program == null || controller.running()) {
            return;
        }
        String spec = robotSpec(program);
        int[] ids = program.moduleIds();
        World world = ide.viewBar.world().world();
        String key = spec + java.util.Arrays.toString(ids) + ide.viewBar.world().file();
        if (key.equals(previewKey)) {
            return;
        }
        previewKey = key;
        previewer.execute(() -> {
            RobotConfig config = RobotConfigs.resolve(spec, ids, new DiagnosticList());
            if (config == null) {
                return;
            }
            try (Simulator s = new Simulator(config, world)) {
                preview = s.snapshot();
                // said when the robot or the world is chosen, not only when a run starts
                s.misfit().ifPresent(misfit -> ide.sayLater(UiMsg.ROBOT_MISFIT_SAY.text(spec, misfit)));
            } catch (RuntimeException e) {
                ide.bottom.logLater(UiMsg.CANNOT_SHOW_ROBOT.text(spec, e.getMessage()));
            }
        });
    }

    /**
     * "   score 45.0   (time limit 60 s)" while a run in a world goes on, "   final score 45.0" after
     * it until the next run or another script or world, else empty (UI thread).
     */
    String scoreText() {
        Simulator s = sim;
        if (s == null || s.world() == null) {
            WorldScore f = finalScore;
            return f == null ? "" : UiMsg.SCORE_FINAL.text(String.format(java.util.Locale.ROOT, "%.1f", f.score()));
        }
        return UiMsg.SCORE_LIVE.text(String.format(java.util.Locale.ROOT, "%.1f", s.liveScore()),
                String.format(java.util.Locale.ROOT, "%.0f", s.world().timeLimit()));
    }

    /** Drops the robot shown for the previous script, and the score of its last run. */
    void forgetPreview() {
        previewKey = "";
        preview = null;
        finalScore = null;
    }

    /** Forgets the preview so that the next validation rebuilds it (robot or world picker changed); the last score goes with it. */
    void invalidatePreview() {
        previewKey = "";
        finalScore = null;
    }

    void dispose() {
        emergencyStop();
        previewer.shutdownNow();
        try {
            controller.join(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
