package org.parpe.gui.app;

import org.parpe.gui.text.UiMsg;
import org.parpe.gui.prefs.Prefs;
import java.nio.file.Path;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.parpe.gui.view3d.View3D;
import org.parpe.sim.SimTarget;
import org.parpe.sim.config.RobotConfigs;

/**
 * The bar above the 3D view: the simulated robot (automatic, one of the simulator's generators,
 * or a configuration file), the world it runs in, Track robot, module IDs and a reset of the camera.
 */
public final class ViewBar {
    /** The last choice, which asks for a file. */
    private final String browseItem = UiMsg.VIEW_ROBOT_FILE.text();

    private final IdeWindow ide;
    private final Combo robot;
    private final WorldPicker world;
    private final Button track;
    private final Button ids;
    private final Button reset;
    private final Prefs prefs;
    private final Composite bar;
    private String file;

    ViewBar(Composite parent, IdeWindow ide, Prefs prefs) {
        this.ide = ide;
        this.prefs = prefs;
        // In a narrow 3D pane the check boxes and Reset view go behind a chevron (») instead of off the edge.
        bar = new org.parpe.gui.panels.OverflowBar(parent).control();
        bar.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        new Label(bar, SWT.NONE).setText(UiMsg.VIEW_ROBOT.text());
        robot = new Combo(bar, SWT.READ_ONLY);
        robot.add(UiMsg.VIEW_ROBOT_AUTO.text(SimTarget.AUTO));
        RobotConfigs.generatorNames().forEach(robot::add);
        file = prefs.get("view.robotFile", null);
        if (file != null) {
            robot.add(file);
        }
        robot.add(browseItem);
        // Each file has its own robot (RunChoices): auto until the file is shown.
        robot.select(0);
        robot.setToolTipText(UiMsg.VIEW_ROBOT_TIP.text());
        robot.addListener(SWT.Selection, e -> chosen());
        world = new WorldPicker(bar, ide, prefs, this::worldChosen);
        track = new Button(bar, SWT.CHECK);
        track.setText(UiMsg.VIEW_TRACK.text());
        track.setSelection(Boolean.parseBoolean(prefs.get("view.track", "true")));
        ids = new Button(bar, SWT.CHECK);
        ids.setText(UiMsg.VIEW_IDS.text());
        ids.setSelection(Boolean.parseBoolean(prefs.get("view.ids", "false")));
        reset = new Button(bar, SWT.PUSH);
        reset.setText(UiMsg.VIEW_RESET.text());
        Button cameraButton = new Button(bar, SWT.PUSH);
        cameraButton.setText(UiMsg.VIEW_CAMERA.text());
        cameraButton.setToolTipText(UiMsg.VIEW_CAMERA_TIP.text());
        cameraButton.addListener(SWT.Selection, e -> ide.openModuleCamera());
        reset.setToolTipText(UiMsg.VIEW_RESET_TIP.text());
        track.addListener(SWT.Selection, e -> prefs.put("view.track", Boolean.toString(track.getSelection())));
        ids.addListener(SWT.Selection, e -> prefs.put("view.ids", Boolean.toString(ids.getSelection())));
    }

    /** The bar (tests). */
    Composite control() {
        return bar;
    }

    /** Connects the check boxes to {@code view}. */
    void attach(View3D view) {
        view.setTrackRobot(track.getSelection());
        view.setShowIds(ids.getSelection());
        track.addListener(SWT.Selection, e -> view.setTrackRobot(track.getSelection()));
        ids.addListener(SWT.Selection, e -> view.setShowIds(ids.getSelection()));
        reset.addListener(SWT.Selection, e -> {
            view.resetView();
            track.setSelection(true);
            view.setTrackRobot(true);
        });
    }

    private void chosen() {
        if (browseItem.equals(robot.getText())) {
            Path p = org.parpe.gui.panels.FileDialogs.ask(robot.getShell(), SWT.OPEN, UiMsg.ROBOT_CONFIG_FILE.text(), "*.xml", null, null);
            if (p == null) {
                robot.select(0);
                return;
            }
            useFile(p.toString());
        }
        ide.robotChosen(robot());
        ide.runs.invalidatePreview();
        if (ide.program() != null) {
            ide.runs.updatePreview(ide.program());
        }
        ide.view.resetView();
    }

    private void worldChosen() {
        ide.choices.worldChosen(world.choice());
        ide.runs.invalidatePreview();
        if (ide.program() != null) {
            ide.runs.updatePreview(ide.program());
        }
        ide.view.resetView();
    }

    /** The world picker. */
    WorldPicker world() {
        return world;
    }

    /** {@code auto}, a generator name, or a configuration file path. */
    String robot() {
        // the first item is the script's own robot, whatever words the language puts around "auto"
        return robot.getSelectionIndex() == 0 ? SimTarget.AUTO : robot.getText();
    }

    /** Adds the configuration file {@code path} to the choices (replacing the previous file) and selects it. */
    void useFile(String path) {
        if (file != null) {
            robot.remove(file);
        }
        file = path;
        robot.add(path, robot.getItemCount() - 1);
        robot.select(robot.indexOf(path));
        prefs.put("view.robotFile", path);
    }

    /** Turns TrackRobot on or off for now (automation framing a group), without changing the preference. */
    public void trackRobot(boolean on) {
        track.setSelection(on);
        ide.view.setTrackRobot(on);
    }

    /**
     * Shows {@code choice} ({@code auto}, a generator name or a configuration file) as the robot,
     * as chosen for the file now in the editor; an unknown name shows {@code auto}.
     */
    void show(String choice) {
        if (SimTarget.AUTO.equals(choice)) {
            robot.select(0);
        } else if (robot.indexOf(choice) >= 0) {
            robot.select(robot.indexOf(choice));
        } else if (java.nio.file.Files.isRegularFile(java.nio.file.Path.of(choice))) {
            useFile(choice);
        } else {
            robot.select(0);
        }
    }

    /** Picks a robot by generator name as the user does in the picker (automation, tests). */
    void select(String name) {
        int at = robot.indexOf(name);
        if (at >= 0) {
            robot.select(at);
            robot.notifyListeners(SWT.Selection, new org.eclipse.swt.widgets.Event());
        }
    }
}
