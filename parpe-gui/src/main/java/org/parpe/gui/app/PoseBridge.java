package org.parpe.gui.app;

import org.parpe.gui.text.UiMsg;
import org.parpe.gui.hardware.ConnectedRobot;
import org.parpe.gui.hardware.HardwareDialog;

import java.nio.file.Path;
import java.util.Map;
import java.util.function.Consumer;
import org.eclipse.jface.text.IDocument;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.load.LoadResult;
import org.parpe.core.model.Program;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.editor.ScriptDocument;
import org.parpe.gui.pose.PoseHardware;
import org.parpe.gui.pose.PoseHost;
import org.parpe.gui.run.RunOn;
import org.parpe.gui.view3d.View3D;
import org.parpe.serial.servo.profile.HardwareProfile;
import org.parpe.serial.servo.profile.ProfileReader;
import org.parpe.sim.SimTarget;

/** The IDE window as the Pose panel sees it. UI thread only. */
final class PoseBridge extends WindowBridge implements PoseHost {
    PoseBridge(IdeWindow ide) {
        super(ide);
    }

    @Override
    public Program program() {
        return ide.program();
    }

    @Override
    public String robotSpec(Program program) {
        String choice = ide.robotChoice();
        return SimTarget.AUTO.equals(choice) ? SimTarget.autoSpec(program) : choice;
    }

    @Override
    public View3D view() {
        return ide.view;
    }

    @Override
    public IDocument document() {
        return ide.editor.document();
    }

    @Override
    public Path scriptPath() {
        return ide.files.pathForLoading();
    }

    @Override
    public LoadResult load(Path path, String text) {
        return ScriptDocument.load(path, text, Map.of());
    }

    @Override
    public boolean running() {
        return ide.runs.running();
    }

    @Override
    public void play(Program program, RunOn target, String spec, Consumer<RunOutcome> onEnd) {
        ide.runs.play(program, target, spec, onEnd);
    }

    @Override
    public void stop() {
        ide.runs.stop();
    }

    @Override
    public void status(String message) {
        ide.status.setMessage(message);
    }

    @Override
    public PoseHardware hardware() {
        HardwareDialog d = ide.hardware.hardwareDialog();
        if (d == null || d.shell().isDisposed() || d.servos().isEmpty()) {
            return null;
        }
        HardwareProfile profile = null;
        String file = ide.toolbar.hardwareProfile();
        if (file != null) {
            DiagnosticList problems = new DiagnosticList();
            profile = ProfileReader.read(Path.of(file), problems);
            if (profile == null) {
                ide.status.setMessage(UiMsg.PROFILE_HAS_ERRORS_FIRST.text(file,
                        problems.all().isEmpty() ? "" : problems.all().get(0).format()));
                return null;
            }
        }
        return new ConnectedRobot(d, profile);
    }
}
