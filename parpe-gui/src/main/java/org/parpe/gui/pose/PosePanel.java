package org.parpe.gui.pose;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.SashForm;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Combo;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.parpe.core.model.Group;
import org.parpe.core.model.Program;
import org.parpe.gui.text.PanelMsg;

/**
 * The Pose panel (posable programming, the paper's Level I): choose a group, or Ctrl+click
 * modules in the 3D view; pose it in the simulator (sliders, or drag a module in the 3D view to
 * turn its joint; the simulated robot follows live, and the real one too if asked) or by hand on
 * the robot (its servos limp); Capture (or Space) adds the pose to the list. The list, playback,
 * saving and "use on another group" are in {@link PoseTable} and {@link PoseOutput}. One list of
 * poses is kept per group, so choosing another group loses nothing. UI thread only; the posed
 * robot's physics runs on {@link PoseSim}'s thread.
 */
public final class PosePanel {
    /** The group made of the modules picked in the 3D view. */
    static final String PICKED = "picked";
    private static final int POLL_MS = 250;

    private final PoseHost host;
    private final Composite box;
    private final Combo groups;
    private final Combo source;
    private final Button follow;
    private final Button timed;
    private final PoseTable table;
    private final JointSliders sliders;
    private final PoseOutput output;
    private final PoseSim sim;
    /** The lists of every document; the one in the editor has its own (issue 23, item 10). */
    private final PoseDocuments documents = new PoseDocuments();
    private final Set<Integer> picked = new TreeSet<>();
    private Program program;
    private String robotChoice = "";
    private PoseList current;
    private long lastCapture;
    private volatile boolean shown;

    /** Creates the panel in {@code parent} and hooks it to the 3D view of {@code host}. */
    public PosePanel(Composite parent, PoseHost host) {
        this.host = host;
        box = new Composite(parent, SWT.NONE);
        box.setLayout(new GridLayout(1, false));
        // one row that wraps where the pane is narrow (a long language, the Diagram tab or the tutorial beside
        // it): the check boxes are in it rather than under the sliders, whose side is too narrow for them there
        Composite top = org.parpe.gui.panels.WrapRow.of(box);
        new Label(top, SWT.NONE).setText(PanelMsg.POSE_GROUP.text());
        groups = new Combo(top, SWT.READ_ONLY);
        groups.setToolTipText(PanelMsg.POSE_GROUP_TIP.text());
        groups.setLayoutData(new org.eclipse.swt.layout.RowData(110, SWT.DEFAULT));
        groups.addListener(SWT.Selection, e -> chooseGroup(groups.getText()));
        new Label(top, SWT.NONE).setText(PanelMsg.POSE_WITH.text());
        source = new Combo(top, SWT.READ_ONLY);
        source.setItems(PanelMsg.POSE_SIMULATOR.text(), PanelMsg.POSE_ROBOT_LIMP.text());
        source.setToolTipText(PanelMsg.POSE_SOURCE_TIP.text());
        source.select(0);
        source.addListener(SWT.Selection, e -> sourceChanged());
        Button capture = new Button(top, SWT.PUSH);
        capture.setText(PanelMsg.POSE_CAPTURE.text());
        capture.setToolTipText(PanelMsg.POSE_CAPTURE_TIP.text());
        capture.addListener(SWT.Selection, e -> capture());
        Button fromScript = new Button(top, SWT.PUSH);
        fromScript.setText(PanelMsg.POSE_FROM_SCRIPT.text());
        fromScript.setToolTipText(PanelMsg.POSE_FROM_SCRIPT_TIP.text());
        fromScript.addListener(SWT.Selection, e -> loadFromScript());
        // after the buttons, which keep their place on the first line (the Hardware dialog is placed to leave Capture free)
        follow = check(top, PanelMsg.POSE_FOLLOW.text(), PanelMsg.POSE_FOLLOW_TIP.text());
        timed = check(top, PanelMsg.POSE_REAL_TIME.text(), PanelMsg.POSE_REAL_TIME_TIP.text());

        SashForm middle = new SashForm(box, SWT.HORIZONTAL);
        middle.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
        table = new PoseTable(middle, new TableOwner());
        PoseDrag.from(table.table(), this::selectedAngles);
        sliders = new JointSliders(middle, this::jointChanged);
        middle.setWeights(55, 45);
        output = new PoseOutput(box, host, this);
        sim = new PoseSim(msg -> runOnUi(() -> say(msg)));
        PoseInput.attach(this, host);
        box.addListener(SWT.Dispose, e -> sim.close());
        poll();
    }

    private static Button check(Composite parent, String text, String tip) {
        Button b = new Button(parent, SWT.CHECK);
        b.setText(text);
        b.setToolTipText(tip);
        return b;
    }

    /** The panel's control (a tab's content). */
    public Control control() {
        return box;
    }

    /** Whether the panel is posing: shown, and no run has the 3D view. */
    boolean posing() {
        return shown && !host.running();
    }

    /** Follows the open script and keeps the posed robot stepping while the panel is shown. */
    private void poll() {
        if (box.isDisposed()) {
            return;
        }
        pollNow();
        if (posing() && sim.ready() && current != null) {
            int[] m = current.modules();
            double[] a = sliders.angles();
            for (int k = 0; k < m.length; k++) {
                sim.set(m[k], a[k]);
            }
        }
        box.getDisplay().timerExec(POLL_MS, this::poll);
    }

    private void programChanged(Program p) {
        program = p;
        sim.build(host.robotSpec(p), p.moduleIds());
        List<String> names = new ArrayList<>();
        for (Group g : p.robot().groups()) {
            names.add(g.name());
        }
        names.add(PICKED);
        String was = groups.getText();
        groups.setItems(names.toArray(new String[0]));
        int at = names.indexOf(was);
        if (at < 0) {
            at = defaultGroup(p);
        }
        groups.select(at);
        chooseGroup(groups.getText());
    }

    /** The smallest group that is not the whole robot (a leg rather than everything), else the first. */
    private static int defaultGroup(Program p) {
        List<Group> gs = p.robot().groups();
        int best = 0;
        for (int i = 0; i < gs.size(); i++) {
            if (gs.get(i).size() < gs.get(best).size() && gs.get(i).size() > 1) {
                best = i;
            }
        }
        return best;
    }

    /** Poses {@code name} (a group of the script, or {@link #PICKED}), with its own list of poses. */
    void chooseGroup(String name) {
        int[] modules;
        if (PICKED.equals(name)) {
            modules = picked.stream().mapToInt(Integer::intValue).toArray();
        } else {
            Group g = program == null ? null : program.group(name).orElse(null);
            if (g == null) {
                return;
            }
            modules = g.modules().stream().mapToInt(Integer::intValue).toArray();
        }
        String key = name + (PICKED.equals(name) ? picked.toString() : Arrays.toString(modules));
        if (current != null && current == documents.lists().get(key)) {
            return; // the script was validated again and this group did not change
        }
        if (groups.indexOf(name) >= 0 && groups.getSelectionIndex() != groups.indexOf(name)) {
            groups.select(groups.indexOf(name));
        }
        if (modules.length == 0) {
            current = null;
            table.show(null);
            sliders.show(new int[0], new double[0]);
            say(PanelMsg.POSE_CTRL_CLICK.text());
            return;
        }
        current = documents.lists().computeIfAbsent(key, k -> new PoseList(name, modules));
        double[] start = new double[modules.length];
        for (int k = 0; k < modules.length; k++) {
            start[k] = sim.target(modules[k]);
        }
        sliders.show(modules, start);
        table.show(current);
        if (source.getSelectionIndex() == 1) {
            limp(true);
        }
    }

    /** Ctrl+click in the 3D view: adds module {@code id} to (or removes it from) the picked modules. */
    void pick(int id) {
        PoseList was = documents.lists().get(PICKED + picked);
        if (was != null && was.size() > 0) {
            // Its poses have an angle per picked module: another set of modules would leave them behind.
            say(PanelMsg.POSE_PICKED_HAVE_POSES.text(picked, was.size()));
            return;
        }
        if (!picked.remove(id)) {
            picked.add(id);
        }
        groups.select(groups.indexOf(PICKED));
        chooseGroup(PICKED);
        say(PanelMsg.POSE_PICKED.text(picked));
    }

    private void jointChanged(int module, double degrees) {
        sim.set(module, degrees);
        if (follow.getSelection() && source.getSelectionIndex() == 0) {
            PoseHardware hw = host.hardware();
            if (hw != null) {
                hw.move(module, degrees);
            }
        }
    }

    private void sourceChanged() {
        if (source.getSelectionIndex() == 1 && host.hardware() == null) {
            say(PanelMsg.POSE_CONNECT_FIRST.text());
            source.select(0);
            return;
        }
        limp(source.getSelectionIndex() == 1);
    }

    private void limp(boolean on) {
        PoseHardware hw = host.hardware();
        if (hw != null && current != null) {
            hw.limp(current.modules(), on);
            say(on ? PanelMsg.POSE_LIMP.text() : PanelMsg.POSE_HOLDS.text());
        }
    }

    /** Adds the current pose (sliders, or the robot's angles when posing by hand) to the list; false if none. */
    boolean capture() {
        if (current == null) {
            say(PanelMsg.POSE_CHOOSE_GROUP.text());
            return false;
        }
        double[] angles = sliders.angles();
        if (source.getSelectionIndex() == 1) {
            PoseHardware hw = host.hardware();
            if (hw == null) {
                say(PanelMsg.POSE_NO_LONGER_CONNECTED.text());
                return false;
            }
            try {
                angles = hw.angles(current.modules());
            } catch (IllegalStateException e) {
                say(PanelMsg.POSE_CANNOT_CAPTURE.text(e.getMessage()));
                return false;
            }
            for (int k = 0; k < angles.length; k++) {
                angles[k] = Math.max(-90, Math.min(90, angles[k]));
            }
            sliders.setAll(angles);
        }
        long now = System.nanoTime();
        if (timed.getSelection() && lastCapture != 0 && current.size() > 0) {
            double s = (now - lastCapture) / 1e9;
            table.setInterval(Math.max(PoseList.MIN_INTERVAL, Math.min(PoseList.MAX_INTERVAL, s)));
        }
        Double interval = table.interval();
        if (interval == null) {
            return false;
        }
        lastCapture = now;
        int i = current.add(angles, interval);
        table.select(i);
        say(PanelMsg.POSE_CAPTURED.text(i + 1));
        return true;
    }

    /**
     * Adds the poses of the first gait table of plain numbers that the script plays on the group
     * (else on any group, which is then chosen) to the end of its list; false (and a message) if none.
     */
    public boolean loadFromScript() {
        if (program == null) {
            say(PanelMsg.POSE_NOT_LOADED.text());
            return false;
        }
        Optional<PoseList> found = PoseImport.read(program, current == null ? null : current.group());
        if (found.isEmpty()) {
            found = PoseImport.read(program, null);
        }
        if (found.isEmpty()) {
            say(PanelMsg.POSE_NO_GAIT_TABLE.text());
            return false;
        }
        PoseList in = found.get();
        chooseGroup(in.group());
        if (current == null) {
            return false;
        }
        int first = current.size();
        for (int i = 0; i < in.size(); i++) {
            current.add(in.get(i).angles(), in.get(i).interval());
        }
        if (first == 0) {
            markKept(current); // they are in the script already
        }
        table.select(first);
        say(PanelMsg.POSE_TAKEN_FROM_SCRIPT.text(in.size(), in.group()));
        return true;
    }

    void say(String text) {
        host.status(text);
    }

    private void runOnUi(Runnable r) {
        if (!box.isDisposed()) {
            box.getDisplay().asyncExec(() -> {
                if (!box.isDisposed()) {
                    r.run();
                }
            });
        }
    }

    /** Remembers that the poses of {@code list} as they are now are kept in a file or the script. */
    void markKept(PoseList list) {
        documents.markKept(list);
    }

    /**
     * Another document is in the editor ({@code file}, or null for a new untitled script): the
     * panel shows that document's poses, and the poses captured for the one before stay with it
     * (they are its poses, not the next file's). Save As keeps the document, so it is not a switch.
     */
    public void documentSwitched(java.nio.file.Path file) {
        if (!documents.switchTo(file)) {
            return;
        }
        current = null;
        program = null; // the next poll reads the new document's program and chooses its group
        table.show(null);
        pollNow();
    }

    /** The document a Save As gave a path to keeps its poses under that path. */
    public void documentRenamed(java.nio.file.Path file) {
        documents.renamed(file);
    }

    /**
     * Lists with poses that were changed since they were last saved or written into the script,
     * of every document, as "3 poses of front in lesson.xml".
     */
    public List<String> unsaved() {
        return documents.unsaved();
    }

    /** The sentence that says which poses quitting would lose ({@link #unsaved}), or null when none. */
    public String lossSentence() {
        return documents.lossSentence();
    }

    /**
     * Asks before the window closes with poses that were neither saved nor written into the
     * script; true to close.
     */
    public boolean confirmClose() {
        String lost = lossSentence();
        return lost == null || org.eclipse.jface.dialogs.MessageDialog.openQuestion(box.getShell(), PanelMsg.POSE_UNSAVED_TITLE.text(),
                PanelMsg.POSE_CLOSE_AND_LOSE.text(lost));
    }

    /**
     * The robot is gone (the Hardware dialog closed its bus): posing by hand falls back to the
     * simulator, and the panel says so, rather than showing "Robot (limp)" with nothing connected.
     */
    public void hardwareGone() {
        if (!box.isDisposed() && source.getSelectionIndex() == 1) {
            source.select(0);
            say(PanelMsg.POSE_DISCONNECTED.text());
        }
    }

    /** Whether "Robot (limp)" is the pose source (tests). */
    public boolean posingTheRobot() {
        return source.getSelectionIndex() == 1;
    }

    /** Whether the posed robot is built and shown (the 3D view follows the sliders). */
    public boolean posingReady() {
        return posing() && sim.ready();
    }

    /** The modules being posed (none before a group is chosen). */
    public Set<Integer> posedModules() {
        return current == null ? Set.of()
                : Arrays.stream(current.modules()).boxed().collect(java.util.stream.Collectors.toCollection(TreeSet::new));
    }

    /**
     * The selected pose as the angles attribute of a state: degrees in group order, comma
     * separated; null when no pose is selected. What the Diagram pane's "Use pose" writes.
     */
    public String selectedAngles() {
        int i = table.selection();
        return current == null || i < 0 || i >= current.size() ? null : PoseDrag.angles(current.get(i).angles());
    }

    /** The poses of the group being posed, or null. */
    PoseList poses() {
        return current;
    }

    /** The open script's program as the panel last saw it, or null. */
    Program program() {
        return program;
    }

    /** The push button or check box labelled {@code text} (mnemonics ignored), or null (tests press them). */
    Button button(String text) {
        return PoseTable.find(box, text);
    }

    /** Whether the joints are posed with the sliders and the 3D view (not by hand on the robot). */
    boolean posingInSimulator() {
        return source.getSelectionIndex() == 0;
    }

    /** Simulator or robot (tests choose as a user would). */
    Combo source() {
        return source;
    }

    JointSliders sliders() {
        return sliders;
    }

    PoseTable table() {
        return table;
    }

    PoseOutput output() {
        return output;
    }

    PoseSim sim() {
        return sim;
    }

    /** Shows the panel's own state at once instead of at the next poll (tests, automation). */
    public void pollNow() {
        shown = box.isVisible();
        Program p = host.program();
        if (p != null && p != program) {
            programChanged(p);
        }
        String choice = host.robotChoice();
        if (!choice.equals(robotChoice) && program != null) {
            sim.build(host.robotSpec(program), program.moduleIds());
        }
        robotChoice = choice;
        sim.setActive(posing());
    }

    private final class TableOwner implements PoseTable.Owner {
        @Override
        public double[] sliders() {
            return sliders.angles();
        }

        @Override
        public void mirror(int i) {
            int[] swap = MirrorMap.swap(program, current.modules());
            current.mirror(i, swap, MirrorMap.unpaired(swap));
            table.refresh();
            sliders.setAll(current.get(i).angles());
        }

        @Override
        public void selected(PoseList.Pose pose) {
            sliders.setAll(pose.angles());
        }

        @Override
        public void say(String text) {
            PosePanel.this.say(text);
        }
    }
}
