package org.parpe.gui.pose;

import java.util.ArrayList;
import java.util.List;
import org.eclipse.jface.dialogs.Dialog;
import org.eclipse.jface.dialogs.IDialogConstants;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Text;
import org.parpe.core.model.Group;
import org.parpe.core.lang.Numbers;
import org.parpe.core.model.Program;
import org.parpe.gui.text.PanelMsg;
import org.parpe.serial.record.PoseRecording;
import org.parpe.serial.record.RecordingWriter;

/**
 * "Use on another group": the groups of the open script with as many modules as the poses
 * (several may be chosen), the period, the phase between successive modules and the offset
 * between successive chosen groups. OK is refused, with the reason shown, until the values can
 * be written.
 */
final class UseOnGroupDialog extends Dialog {
    private final Program program;
    private final PoseRecording recording;
    private final List<String> candidates = new ArrayList<>();
    private org.eclipse.swt.widgets.List groups;
    private Text period;
    private Text phase;
    private Text offset;
    private Label problem;
    private org.eclipse.swt.widgets.Button first;
    private ScriptInsert.Request request;

    UseOnGroupDialog(Shell parent, Program program, PoseList poses) {
        super(parent);
        this.program = program;
        this.recording = poses.toRecording();
        for (Group g : program.robot().groups()) {
            if (g.size() == poses.modules().length && !g.implicit()) {
                candidates.add(g.name());
            }
        }
    }

    @Override
    protected void configureShell(Shell shell) {
        super.configureShell(shell);
        shell.setText(PanelMsg.POSE_USE_TITLE.text());
    }

    @Override
    protected Control createDialogArea(Composite parent) {
        Composite area = (Composite) super.createDialogArea(parent);
        area.setLayout(new GridLayout(2, false));
        Label intro = new Label(area, SWT.WRAP);
        intro.setText(PanelMsg.POSE_USE_INTRO.text(recording.size(), recording.group(), recording.modules().length));
        GridData wide = new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1);
        wide.widthHint = 420;
        intro.setLayoutData(wide);
        new Label(area, SWT.NONE).setText(PanelMsg.POSE_GROUPS.text());
        groups = new org.eclipse.swt.widgets.List(area, SWT.MULTI | SWT.BORDER | SWT.V_SCROLL);
        groups.setItems(candidates.toArray(new String[0]));
        GridData gd = new GridData(SWT.FILL, SWT.FILL, true, true);
        gd.heightHint = 110;
        groups.setLayoutData(gd);
        double cycle = 0;
        for (double t : RecordingWriter.rowTimes(recording)) {
            cycle += t;
        }
        period = field(area, PanelMsg.POSE_PERIOD.text(), Numbers.format(Math.round(cycle * 100) / 100.0),
                PanelMsg.POSE_PERIOD_TIP.text());
        phase = field(area, PanelMsg.POSE_PHASE.text(), "0", PanelMsg.POSE_PHASE_TIP.text());
        offset = field(area, PanelMsg.POSE_OFFSET.text(), "0.5", PanelMsg.POSE_OFFSET_TIP.text());
        // <main> plays its entries in turn: a behavior it does not name never plays (issue 23, item 10).
        boolean mainHasEntries = program.mainDef().map(m -> !m.entries().isEmpty()).orElse(false);
        first = new org.eclipse.swt.widgets.Button(area, SWT.CHECK);
        first.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1));
        first.setText(mainHasEntries ? PanelMsg.POSE_PLAY_FIRST.text(ScriptInsert.FIRST_CYCLES)
                : PanelMsg.POSE_MAIN_PLAYS.text());
        first.setToolTipText(PanelMsg.POSE_PLAY_FIRST_TIP.text());
        first.setSelection(true);
        first.setEnabled(mainHasEntries);
        problem = new Label(area, SWT.WRAP);
        problem.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1));
        problem.setForeground(area.getDisplay().getSystemColor(SWT.COLOR_DARK_RED));
        if (candidates.isEmpty()) {
            problem.setText(PanelMsg.POSE_NO_OTHER_GROUP.text(recording.modules().length));
        }
        return area;
    }

    private static Text field(Composite area, String label, String value, String tip) {
        new Label(area, SWT.NONE).setText(label);
        Text t = new Text(area, SWT.BORDER);
        t.setText(value);
        t.setToolTipText(tip);
        t.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
        return t;
    }

    @Override
    protected void okPressed() {
        Double p = Numbers.parsePlain(period.getText().trim());
        Double ph = Numbers.parsePlain(phase.getText().trim());
        Double off = Numbers.parsePlain(offset.getText().trim());
        if (p == null || ph == null || off == null) {
            problem.setText(PanelMsg.POSE_NOT_NUMBERS.text(period.getText().trim(), phase.getText().trim(), offset.getText().trim()));
            return;
        }
        ScriptInsert.Request r = new ScriptInsert.Request(recording, List.of(groups.getSelection()), p, ph, off, first.getSelection());
        String why = ScriptInsert.check(program, r);
        if (why != null) {
            problem.setText(why);
            problem.getParent().layout(true);
            return;
        }
        request = r;
        super.okPressed();
    }

    @Override
    protected void createButtonsForButtonBar(Composite parent) {
        createButton(parent, IDialogConstants.OK_ID, PanelMsg.POSE_WRITE.text(), true);
        createButton(parent, IDialogConstants.CANCEL_ID, IDialogConstants.CANCEL_LABEL, false);
    }

    /** What to write, after OK. */
    ScriptInsert.Request request() {
        return request;
    }
}
