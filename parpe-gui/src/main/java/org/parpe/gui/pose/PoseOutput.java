package org.parpe.gui.pose;

import java.io.IOException;
import java.nio.file.Path;
import java.util.function.Consumer;
import org.eclipse.jface.text.BadLocationException;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.window.Window;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.io.AtomicFiles;
import org.parpe.core.io.OutputPlan;
import org.parpe.core.load.LoadResult;
import org.parpe.core.model.Program;
import org.parpe.core.run.RunOutcome;
import org.parpe.gui.run.RunOn;
import org.parpe.gui.text.PanelMsg;
import org.parpe.serial.record.RecordingWriter;

/**
 * What the Pose panel does with its list: play it (×0.5…×4, once or looped, on the simulator,
 * the robot or both) by running its §12 recording through the IDE's run pipeline, so it moves
 * exactly as PARSL runs it; save it as a §12 recording; and "Use on another group", which writes
 * it into the open script for other groups (one undoable edit). UI thread only.
 */
final class PoseOutput {
    /** Playback rates offered. */
    static final double[] RATES = {0.5, 1, 2, 4};

    private final PoseHost host;
    private final PosePanel panel;
    private final Combo rate;
    private final Button loop;
    private final Combo target;

    PoseOutput(Composite parent, PoseHost host, PosePanel panel) {
        this.host = host;
        this.panel = panel;
        Composite row = org.parpe.gui.panels.WrapRow.of(parent);
        new Label(row, SWT.NONE).setText(PanelMsg.POSE_PLAY_AT.text());
        rate = new Combo(row, SWT.READ_ONLY);
        for (double r : RATES) {
            rate.add("\u00d7" + (r == Math.rint(r) ? Integer.toString((int) r) : Double.toString(r)));
        }
        rate.select(1);
        rate.setToolTipText(PanelMsg.POSE_RATE_TIP.text());
        loop = new Button(row, SWT.CHECK);
        loop.setText(PanelMsg.POSE_LOOP.text());
        loop.setToolTipText(PanelMsg.POSE_LOOP_TIP.text());
        new Label(row, SWT.NONE).setText(PanelMsg.POSE_PLAY_ON.text());
        target = new Combo(row, SWT.READ_ONLY);
        for (RunOn t : RunOn.values()) {
            target.add(t.label());
        }
        target.select(0);
        button(row, PanelMsg.POSE_PLAY.text(), PanelMsg.POSE_PLAY_TIP.text(), this::play);
        button(row, PanelMsg.POSE_STOP.text(), PanelMsg.POSE_STOP_TIP.text(), host::stop);
        row = org.parpe.gui.panels.WrapRow.of(parent);
        button(row, PanelMsg.POSE_SAVE_RECORDING.text(), PanelMsg.POSE_SAVE_RECORDING_TIP.text(),
                this::saveAs);
        button(row, PanelMsg.POSE_USE_ON_GROUP.text(),
                PanelMsg.POSE_USE_ON_GROUP_TIP.text(), this::useOnGroups);
    }

    private static void button(Composite parent, String text, String tip, Runnable action) {
        Button b = new Button(parent, SWT.PUSH);
        b.setText(text);
        b.setToolTipText(tip);
        b.addListener(SWT.Selection, e -> action.run());
    }

    /** Chooses the rate, loop and target of the next playback (as a user would in the row's widgets). */
    void choose(double playRate, boolean looped, RunOn on) {
        for (int i = 0; i < RATES.length; i++) {
            if (RATES[i] == playRate) {
                rate.select(i);
            }
        }
        loop.setSelection(looped);
        target.select(on.ordinal());
    }

    /** The poses, or null with a message when there are none. */
    private PoseList poses() {
        PoseList l = panel.poses();
        if (l == null || l.size() == 0) {
            host.status(PanelMsg.POSE_CAPTURE_FIRST.text());
            return null;
        }
        return l;
    }

    /** Plays the poses; {@code onEnd} (may be null) gets the outcome. Returns false if it did not start. */
    boolean play(Consumer<RunOutcome> onEnd) {
        PoseList l = poses();
        Program open = panel.program();
        if (l == null || open == null) {
            return false;
        }
        if (host.running()) {
            host.status(PanelMsg.POSE_RUN_GOING_ON.text());
            return false;
        }
        double r = RATES[Math.max(0, rate.getSelectionIndex())];
        String text = RecordingWriter.toParsl(l.toRecording(), "playback in the Pose panel", r, loop.getSelection());
        LoadResult loaded = host.load(host.scriptPath().resolveSibling("pose-playback.xml"), text);
        if (loaded.program() == null) {
            host.status(PanelMsg.POSE_CANNOT_PLAY.text(loaded.errors().stream().map(Diagnostic::message).findFirst().orElse("?")));
            return false;
        }
        RunOn t = RunOn.values()[Math.max(0, target.getSelectionIndex())];
        host.play(loaded.program(), t, host.robotSpec(open), outcome -> {
            host.status(outcome.status() == RunOutcome.Status.ERROR ? PanelMsg.POSE_PLAYBACK_FAILED.text(outcome.message())
                    : PanelMsg.POSE_PLAYBACK_ENDED.text(String.format(java.util.Locale.ROOT, "%.2f", outcome.time())));
            if (onEnd != null) {
                onEnd.accept(outcome);
            }
        });
        return true;
    }

    private void play() {
        play(null);
    }

    private void saveAs() {
        if (poses() == null) {
            return;
        }
        Path chosen = org.parpe.gui.panels.FileDialogs.ask(host.shell(), SWT.SAVE, PanelMsg.POSE_SAVE_TITLE.text(), "*.xml",
                panel.poses().group() + "-poses.xml", null);
        if (chosen != null) {
            save(chosen);
        }
    }

    /**
     * Writes the poses as a §12 recording to {@code file} by the output rules; refuses the script
     * open in the editor. False (and a message) on failure.
     */
    boolean save(Path file) {
        PoseList l = poses();
        if (l == null) {
            return false;
        }
        for (Path open : host.openFiles()) {
            if (OutputPlan.sameFile(open, file)) {
                // replacing it on disk would leave the editor with the old text, not even marked modified
                host.status(PanelMsg.POSE_SAVE_OVER_SCRIPT.text(file.getFileName(), PanelMsg.POSE_USE_ON_GROUP.text()));
                return false;
            }
        }
        String origin = "recorded in the PARPE IDE's Pose panel from " + host.scriptPath().getFileName();
        String text = RecordingWriter.toParsl(l.toRecording(), origin);
        try {
            AtomicFiles.write(file, text);
        } catch (IOException | RuntimeException e) {
            host.status(PanelMsg.POSE_CANNOT_SAVE.text(file, e.getMessage()));
            return false;
        }
        panel.markKept(l);
        host.status(PanelMsg.POSE_SAVED.text(l.size(), l.group(), file));
        return true;
    }

    private void useOnGroups() {
        PoseList l = poses();
        Program open = panel.program();
        if (l == null || open == null) {
            return;
        }
        UseOnGroupDialog d = new UseOnGroupDialog(host.shell(), open, l);
        if (d.open() == Window.OK) {
            useOnGroups(d.request());
        }
    }

    /**
     * Writes the poses into the open script for {@code request}'s groups as one edit of the
     * editor's document (one Undo reverts it); returns what was written, or null (and a message).
     */
    ScriptInsert.Result useOnGroups(ScriptInsert.Request request) {
        Program open = panel.program();
        String problem = open == null ? PanelMsg.POSE_NOT_LOADED.text() : ScriptInsert.check(open, request);
        if (problem != null) {
            host.status(problem);
            return null;
        }
        IDocument doc = host.document();
        String before = doc.get();
        ScriptInsert.Result r = ScriptInsert.insert(before, open, request);
        String after = r.text();
        int start = 0;
        while (start < before.length() && start < after.length() && before.charAt(start) == after.charAt(start)) {
            start++;
        }
        int endBefore = before.length();
        int endAfter = after.length();
        while (endBefore > start && endAfter > start && before.charAt(endBefore - 1) == after.charAt(endAfter - 1)) {
            endBefore--;
            endAfter--;
        }
        try {
            doc.replace(start, endBefore - start, after.substring(start, endAfter));
        } catch (BadLocationException e) {
            host.status(PanelMsg.POSE_CANNOT_CHANGE.text(e.getMessage()));
            return null;
        }
        panel.markKept(panel.poses());
        String said = r.said(request.targets());
        host.status(said);
        panel.say(said);
        return r;
    }
}
