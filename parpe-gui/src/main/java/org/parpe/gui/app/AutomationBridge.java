package org.parpe.gui.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.function.Consumer;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.MenuItem;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.run.JointSink;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.automation.BenchHost;
import org.parpe.gui.automation.Screenshot;
import org.parpe.gui.diagram.DiagramPane;
import org.parpe.gui.grid.GridPane;
import org.parpe.gui.robot.RobotTab;
import org.parpe.gui.run.LiveStates;
import org.parpe.gui.run.RunOn;
import org.parpe.gui.run.Speed;
import org.parpe.gui.view3d.View3D;

/** The IDE window as the command line's automation and the IDE benchmark drive it. UI thread only. */
final class AutomationBridge implements BenchHost {
    private final IdeWindow ide;

    AutomationBridge(IdeWindow ide) {
        this.ide = ide;
    }

    @Override
    public Display display() {
        return ide.shell.getDisplay();
    }

    @Override
    public boolean closed() {
        return ide.closed();
    }

    @Override
    public int validations() {
        return ide.validations();
    }

    @Override
    public String fileName() {
        return ide.files.name();
    }

    @Override
    public boolean runnable() {
        return ide.program() != null && ide.problems().errorCount() == 0;
    }

    @Override
    public List<Diagnostic> problems() {
        return ide.problems().shown();
    }

    @Override
    public String statusMessage() {
        return ide.status.message();
    }

    @Override
    public boolean showScriptPoses() {
        ide.bottom.showPose();
        ide.pose.pollNow();
        return ide.pose.loadFromScript();
    }

    @Override
    public boolean posingReady() {
        return ide.pose.posingReady();
    }

    @Override
    public void focusOnPosedModules() {
        if (ide.view.focus(ide.pose.posedModules())) {
            ide.viewBar.trackRobot(false);
        }
    }

    @Override
    public boolean selectGaitTable(String name) {
        GridPane grid = ide.grid;
        if (!grid.showTable(name)) {
            return false;
        }
        grid.select(grid.table().rows().size() - 1, Math.max(1, grid.table().width()), 0, 1);
        return true;
    }

    @Override
    public String gaitTableShown() {
        return ide.grid.table() == null ? null : ide.grid.table().name();
    }

    @Override
    public void runInSimulator(Speed speed, double seconds, Consumer<RunOutcome> onEnd) {
        ide.toolbar.setTarget(RunOn.SIMULATOR);
        ide.toolbar.setSpeed(speed);
        ide.runs.run(false, seconds, onEnd);
    }

    @Override
    public boolean running() {
        return ide.runs.running();
    }

    @Override
    public void stop() {
        ide.runs.stop();
    }

    @Override
    public void screenshot(Path file) throws IOException {
        Screenshot.save(ide.shell, file);
    }

    @Override
    public List<String> menuTitles() {
        return Arrays.stream(ide.shell.getMenuBar().getItems()).map(MenuItem::getText).toList();
    }

    @Override
    public void close() {
        ide.files.autosaveNow();
        ide.shell.dispose();
    }

    @Override
    public void open(Path file) {
        ide.files.openPath(file);
    }

    @Override
    public boolean reading() {
        return ide.files.reading();
    }

    @Override
    public void fillScreen() {
        ide.shell.setBounds(display().getPrimaryMonitor().getClientArea());
    }

    @Override
    public View3D view() {
        return ide.view;
    }

    @Override
    public DiagramPane diagram() {
        return ide.diagram;
    }

    @Override
    public RobotTab robotTab() {
        return ide.robotTab;
    }

    @Override
    public void observeRuns(JointSink sink) {
        ide.runs.controller().observeRuns(sink);
    }

    @Override
    public LiveStates live() {
        return ide.runs.controller().live();
    }
}
