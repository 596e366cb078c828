package org.parpe.gui.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.eclipse.jface.text.ITextOperationTarget;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.FillLayout;
import org.eclipse.swt.widgets.Shell;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.lang.Numbers;
import org.parpe.gui.editor.ParslEditor;
import org.parpe.gui.editor.ScriptDocument;
import org.parpe.sim.sweep.Cancellation;
import org.parpe.sim.sweep.Constraints;
import org.parpe.sim.sweep.Evaluation;
import org.parpe.sim.sweep.Objective;
import org.parpe.sim.sweep.OptimizationResult;
import org.parpe.sim.sweep.OptimizeSpec;
import org.parpe.sim.sweep.Optimizer;
import org.parpe.sim.sweep.Evaluator;
import org.parpe.sim.sweep.SweepCsv;
import org.parpe.sim.sweep.SweepListener;
import org.parpe.sim.sweep.SweepResult;
import org.parpe.sim.sweep.SweepRow;
import org.parpe.sim.sweep.SweepSpec;
import org.parpe.sim.sweep.Sweep;
import org.parpe.sim.sweep.VarySpec;

/**
 * The Sweep/Optimise dialog on a real editor under Xvfb, on the tutorial's parameters snake
 * (lesson 7): a small grid fills the table with exactly the engine's rows, Stop ends a long
 * sweep and the dialog stays usable, "Apply best" edits the text as one undoable change, and
 * bad input is a message, not an exception. Buttons are pressed through their listeners on
 * the UI thread; every wait is bounded.
 */
class SweepDialogGuiTest {
    private static final String SCRIPT = "tutorial/07-parameters-snake.xml";

    private Shell window;
    private ParslEditor editor;
    private Path file;
    private ScriptDocument document;
    /** The path the "IDE" says its editor holds. */
    private Path shown;
    private String original;
    private final List<Diagnostic> problems = new ArrayList<>();
    private SweepDialog dialog;

    @BeforeEach
    void openEditorAndDialog() throws Exception {
        window = new Shell(Ui.display());
        window.setLayout(new FillLayout());
        window.setSize(700, 500);
        editor = new ParslEditor(window);
        Path examples = Path.of(System.getProperty("parpe.examples", "../examples"));
        file = examples.resolve(SCRIPT).toAbsolutePath().normalize();
        assertTrue(Files.isRegularFile(file), "example " + file + " not found");
        original = Files.readString(file);
        editor.setText(original);
        window.open();
        shown = file;
        document = new ScriptDocument(window.getDisplay(), editor.document(), () -> shown);
        dialog = SweepDialog.open(new SweepHost(window, editor, document, () -> "auto", () -> null, problems::addAll));
        dialog.setJobs(2);
    }

    @AfterEach
    void close() {
        Ui.close(dialog);
        window.dispose();
    }

    private void vary(String name, String from, String to, int values) {
        Ui.vary(dialog, name, from, to, values);
    }

    private void runToEnd() {
        Ui.click(dialog.startButton());
        assertTrue(dialog.running(), "the sweep did not start: " + dialog.message());
        Ui.pump(() -> !dialog.running(), "the sweep to finish");
    }

    /** The rows of the same sweep run directly on the engine, as parpe sweep would. */
    private List<SweepRow> direct(double seconds, List<String> vary) throws Exception {
        Evaluator ev = Evaluator.load(new Evaluator.Settings(file, original, Map.of(), "auto", seconds, 0.01, 90));
        List<org.parpe.sim.sweep.Axis> axes = new ArrayList<>();
        for (String v : vary) {
            axes.add(VarySpec.parse(v, ev.parameters()));
        }
        SweepResult r = new Sweep(ev, SweepSpec.grid(axes, 1, 0)).run(2, SweepListener.NONE, new Cancellation());
        assertFalse(r.cancelled());
        return r.rows();
    }

    @Test
    void aSmallGridFillsTheTableWithTheEngineRows() throws Exception {
        dialog.setDuration("1.5");
        vary("amp", "20", "40", 2);
        vary("period", "1", "2", 2);
        runToEnd();
        assertTrue(dialog.message().startsWith("Finished 4 runs."), dialog.message());
        List<SweepRow> expected = direct(1.5, List.of("amp=20..40:2", "period=1..2:2"));
        assertEquals(expected, dialog.results().rows());
        assertEquals(4, dialog.table().control().getItemCount());
        for (int i = 0; i < 4; i++) {
            SweepRow e = expected.get(i);
            assertEquals(Integer.toString(i), dialog.table().cell(i, 0), "runs are numbered from 0, as in the CSV");
            assertEquals(Numbers.format(e.values().get("amp")), dialog.table().cell(i, 1));
            assertEquals(Numbers.format(e.values().get("period")), dialog.table().cell(i, 2));
            assertEquals(String.format(java.util.Locale.ROOT, "%.4f", e.forwardSpeed()), dialog.table().cell(i, 3));
        }
        // The runs differ: the values reached the simulations.
        assertEquals(4, expected.stream().map(SweepRow::distance).distinct().count());

        // A click on the forward-speed header sorts by it, best first.
        dialog.table().control().getColumn(3).notifyListeners(SWT.Selection, new org.eclipse.swt.widgets.Event());
        SweepRow best = expected.stream().max(java.util.Comparator.comparingDouble(SweepRow::forwardSpeed)).orElseThrow();
        assertEquals(Integer.toString(best.point().index()), dialog.table().cell(0, 0));

        Path csv = Files.createTempDirectory("parpe-sweep-csv").resolve("out.csv");
        dialog.saveCsv(csv);
        Ui.pump(() -> dialog.message().startsWith("Saved"), "the CSV to be saved");
        List<String> lines = new ArrayList<>();
        lines.add("run,runs,combination,repeat,seed,amp,period,duration_s,distance_m,forward_m,forward_speed_mps,speed_mps,"
                + "max_tilt_deg,joint_travel_deg,fell,error");
        expected.forEach(r -> lines.add(SweepCsv.line(r, 4)));
        assertEquals(lines, Files.readAllLines(csv));
        Ui.settle();
        Ui.screenshot(dialog.shell(), "sweep-dialog-small.png");
    }

    /**
     * Issue 31, item 2: the dialog offered the objective score but had no world, so every run's
     * score was empty and the dialog blamed falls and errors whose columns were empty. Without a
     * world, score is now a message and no run; with one, the runs are in it and have a score.
     */
    @Test
    void scoreNeedsAWorldAndInOneEachRunHasItsScore() throws Exception {
        dialog.setDuration("1");
        vary("amp", "20", "40", 2);
        dialog.selectObjective(Objective.SCORE);
        assertNull(dialog.world().world(), "the IDE's runs are on the flat floor here, so is the dialog's");
        Ui.click(dialog.startButton());
        assertFalse(dialog.running(), "a sweep for the score started on the flat floor");
        assertTrue(dialog.message().startsWith("the objective score needs a world: choose one in World"), dialog.message());
        assertNull(dialog.results(), "no table of runs without scores");

        Path world = file.getParent().resolveSibling("worlds").resolve("race-track.xml");
        dialog.world().choose(world);
        runToEnd();
        assertTrue(dialog.message().startsWith("Finished 2 runs."), dialog.message());
        Evaluator ev = Evaluator.load(new Evaluator.Settings(file, original, Map.of(), "auto", 1, 0.01, 90, world));
        SweepResult direct = new Sweep(ev, SweepSpec.grid(List.of(VarySpec.parse("amp=20..40:2", ev.parameters())), 1, 0))
                .run(2, SweepListener.NONE, new Cancellation());
        assertEquals(direct.rows(), dialog.results().rows(), "the dialog's runs are the engine's runs in the world");
        int scoreColumn = dialog.table().control().getColumnCount() - 3; // before fell and error
        assertEquals("score", dialog.table().control().getColumn(scoreColumn).getText());
        for (int i = 0; i < 2; i++) {
            assertEquals(String.format(java.util.Locale.ROOT, "%.4f", direct.rows().get(i).score()),
                    dialog.table().cell(i, scoreColumn), "run " + i + "'s score is in the table");
        }
        assertFalse(dialog.message().contains("fell and error columns"), dialog.message());
        Path csv = Files.createTempDirectory("parpe-sweep-world").resolve("out.csv");
        dialog.saveCsv(csv);
        Ui.pump(() -> dialog.message().startsWith("Saved"), "the CSV to be saved");
        assertTrue(SweepCsv.scored(Files.readAllLines(csv).get(0)), "the CSV has the score column, as parpe sweep --world writes");
    }

    @Test
    void applyBestWritesTheDefaultsAndUndoRestoresTheText() throws Exception {
        dialog.setDuration("1.5");
        vary("amp", "20", "40", 2);
        vary("period", "1", "2", 2);
        runToEnd();
        SweepRow best = dialog.results().best();
        assertNotNull(best);
        shown = file.resolveSibling("another.xml");
        Ui.click(dialog.applyButton());
        assertEquals(original, editor.document().get(), "results are not applied to another file");
        assertTrue(dialog.message().startsWith("these results are of 07-parameters-snake.xml, but the editor holds another.xml"),
                dialog.message());
        shown = file;
        document = new ScriptDocument(window.getDisplay(), editor.document(), () -> shown);
        Ui.click(dialog.applyButton());
        String text = editor.document().get();
        assertNotEquals(original, text);
        String amp = Numbers.format(best.values().get("amp"));
        String period = Numbers.format(best.values().get("period"));
        assertTrue(text.contains("<amp    value=\"" + amp + "\"  min=\"0\"   max=\"60\""), text);
        assertTrue(text.contains("<period value=\"" + period + "\" min=\"0.5\" max=\"5\""), text);
        assertEquals(original.replace("<amp    value=\"35\"", "<amp    value=\"" + amp + "\"")
                .replace("<period value=\"1.5\"", "<period value=\"" + period + "\""), text);
        assertTrue(dialog.message().startsWith("Applied to the editor: amp = " + amp + ", period = " + period),
                dialog.message());
        editor.run(ITextOperationTarget.UNDO);
        assertEquals(original, editor.document().get());
    }

    @Test
    void stopEndsALongSweepAndTheDialogStaysUsable() throws Exception {
        dialog.setDuration("60");
        dialog.setJobs(1);
        vary("amp", "0", "60", 40);
        Ui.click(dialog.startButton());
        assertTrue(dialog.running(), dialog.message());
        assertFalse(dialog.startButton().isEnabled());
        // The table fills while the sweep goes on (40 runs of 60 s take far longer than the first).
        Ui.pump(() -> dialog.table().control().getItemCount() > 0 || !dialog.running(), "the first row");
        assertTrue(dialog.running(), "the sweep ended before Stop: " + dialog.message());
        assertEquals(dialog.results().rows().get(0), dialog.table().rowAt(0));
        int shown = dialog.results().rows().size();
        Ui.click(dialog.stopButton());
        Ui.pump(() -> !dialog.running(), "Stop to end the sweep");
        assertTrue(dialog.message().startsWith("Stopped after "), dialog.message());
        assertTrue(dialog.results().rows().size() >= shown, "Stop threw finished runs away (issue 23, item 13)");
        assertFalse(dialog.message().contains("No run was acceptable"), dialog.message());
        assertTrue(dialog.results().rows().size() < 40);
        assertTrue(dialog.startButton().isEnabled());

        dialog.setDuration("0.5");
        vary("amp", "10", "30", 3);
        runToEnd();
        assertEquals(3, dialog.results().rows().size());
        assertTrue(dialog.message().startsWith("Finished 3 runs."), dialog.message());
    }

    @Test
    void aRandomSweepDrawsWhatTheEngineDraws() throws Exception {
        dialog.setDuration("0.5");
        vary("period", "1", "2", 2);
        dialog.sweepTab().setRandom(3);
        runToEnd();
        Evaluator ev = Evaluator.load(new Evaluator.Settings(file, original, Map.of(), "auto", 0.5, 0.01, 90));
        SweepSpec spec = SweepSpec.random(List.of(org.parpe.sim.sweep.Axis.continuous("period", 1, 2)), 3, 1, 0);
        List<SweepRow> expected = new Sweep(ev, spec).run(1, SweepListener.NONE, new Cancellation()).rows();
        assertEquals(expected, dialog.results().rows());
        // period (default 1.5) is not a count: whole ends still draw anywhere between them.
        assertTrue(expected.stream().anyMatch(r -> r.values().get("period") != Math.rint(r.values().get("period"))));
    }

    /** The editor's text as the dialog reads it now. */
    private ScriptDocument.Loaded loaded() {
        return document.loaded();
    }

    @Test
    void applyBestRefusesValuesThatNoLongerFitTheScript() {
        org.parpe.sim.sweep.SweepException gone = org.junit.jupiter.api.Assertions.assertThrows(
                org.parpe.sim.sweep.SweepException.class, () -> ApplyBest.apply(editor, loaded(), Map.of("stride", 3.0)));
        assertEquals("parameter 'stride' is no longer in the script", gone.getMessage());
        editor.document().set(original.replace("value=\"35\"  min=\"0\"   max=\"60\"", "value=\"25\"  min=\"0\"   max=\"30\""));
        org.parpe.sim.sweep.SweepException narrowed = org.junit.jupiter.api.Assertions.assertThrows(
                org.parpe.sim.sweep.SweepException.class, () -> ApplyBest.apply(editor, loaded(), Map.of("amp", 40.0)));
        assertEquals("parameter 'amp' must be <= 30, got 40 (the script's bounds changed since the run)", narrowed.getMessage());
        editor.document().set(original.replace("<main>", "<main"));
        org.parpe.sim.sweep.SweepException broken = org.junit.jupiter.api.Assertions.assertThrows(
                org.parpe.sim.sweep.SweepException.class, () -> ApplyBest.apply(editor, loaded(), Map.of("amp", 40.0)));
        assertTrue(broken.getMessage().startsWith("the script has errors now"), broken.getMessage());
        assertEquals(original.replace("<main>", "<main"), editor.document().get(), "nothing was written");
    }

    @Test
    void badInputIsAMessageNotAnException() {
        vary("amp", "70", "80", 2);
        Ui.click(dialog.startButton());
        assertFalse(dialog.running());
        assertEquals("amp=70..80:2: parameter 'amp' must be <= 60, got 70 (its bounds are 0..60)", dialog.message());

        vary("amp", "abc", "20", 2);
        Ui.click(dialog.startButton());
        assertEquals("amp=abc..20:2: 'abc' is not a number", dialog.message());

        dialog.sweepTab().line("amp").vary().setSelection(false);
        Ui.click(dialog.startButton());
        assertEquals("nothing to vary: tick Vary for at least one parameter", dialog.message());

        vary("amp", "10", "20", 2);
        dialog.setDuration("-1");
        Ui.click(dialog.startButton());
        assertEquals("the seconds per run must be a number >= 0.01, got '-1'", dialog.message());

        dialog.setDuration("1");
        editor.document().set(original.replace("<main>", "<main><nosuch/>"));
        Ui.click(dialog.startButton());
        assertFalse(dialog.running());
        assertTrue(dialog.message().matches("\\Q" + file + "\\E:\\d+:\\d+: error: .*"), dialog.message());
        editor.document().set(original);

        dialog.robot().useFile(file.resolveSibling("no-such-robot.xml").toString());
        Ui.click(dialog.startButton());
        Ui.pump(() -> !dialog.running(), "the sweep to refuse the robot");
        assertTrue(dialog.message().contains("no-such-robot.xml"), dialog.message());
        assertFalse(dialog.message().contains("Exception"), dialog.message());
        assertNull(dialog.results().best());
        Ui.pump(() -> !problems.isEmpty(), "the robot's problem in Problems");
        assertTrue(problems.get(0).format().contains("no-such-robot.xml"), problems.get(0).format());
    }

    /**
     * The engine's messages that name an option of {@code parpe optimize} ({@code --budget}) come
     * in the dialog's words and in the user's language. Before, the dialog replaced the English
     * option names in the English text, so in German it showed {@code --budget muss ...}.
     */
    @Test
    void theEnginesRefusalNamesTheBoxesInTheUsersLanguage() {
        dialog.setDuration("1");
        dialog.selectTab(1);
        dialog.optimiseTab().setBudget(3, 2);
        Ui.click(dialog.startButton());
        assertFalse(dialog.running());
        assertEquals("the budget must be at least 2 simulations per independent search (4), got 3", dialog.message());
        org.parpe.core.text.Lang.use(java.util.Locale.GERMAN);
        try {
            Ui.click(dialog.startButton());
            assertEquals("das Budget muss mindestens 2 Simulationen je unabhängiger Suche haben (4), ist aber 3",
                    dialog.message());
        } finally {
            org.parpe.core.text.Lang.use(java.util.Locale.ENGLISH);
        }
    }

    @Test
    void editsToTheParametersShowWhenTheDialogIsActivated() {
        vary("amp", "10", "20", 4);
        editor.document().set(original.replace("  </parameters>", "    <lean value=\"0\" min=\"-5\" max=\"5\"/>\n  </parameters>"));
        dialog.activate();
        assertNotNull(dialog.sweepTab().line("lean"), "the new parameter has a line");
        SweepTab.Line amp = dialog.sweepTab().line("amp");
        assertTrue(amp.vary().getSelection());
        assertEquals("10", amp.from().getText());
        assertEquals("4", amp.values().getText());
    }

    @Test
    void anOptimisationGivesTheEngineEvaluationsAndItsBestCanBeApplied() throws Exception {
        dialog.setDuration("1");
        dialog.selectTab(1);
        dialog.optimiseTab().setBudget(6, 2);
        runToEnd();
        assertTrue(dialog.message().startsWith("Finished 6 runs."), dialog.message());
        Evaluator ev = Evaluator.load(new Evaluator.Settings(file, original, Map.of(), "auto", 1, 0.01, 90));
        OptimizationResult direct = new Optimizer(ev, new OptimizeSpec(Objective.FORWARD_SPEED,
                new Constraints(Double.POSITIVE_INFINITY, true), 6, 2, 0)).run(2, SweepListener.NONE, new Cancellation());
        assertEquals(direct.evaluations().stream().map(Evaluation::row).toList(), dialog.results().rows());
        assertEquals(6, dialog.table().control().getItemCount());
        assertEquals("N", dialog.table().control().getColumn(1).getText());
        for (int i = 0; i < 6; i++) {
            assertEquals(Integer.toString(i), dialog.table().cell(i, 0), "evaluations are numbered in the engine's order");
        }
        Ui.settle();
        Ui.screenshot(dialog.shell(), "sweep-dialog-optimise.png");
        Evaluation best = direct.best().orElseThrow();
        assertEquals(best.row(), dialog.results().best());
        Ui.click(dialog.applyButton());
        String text = editor.document().get();
        for (var v : best.row().values().entrySet()) {
            assertTrue(text.matches("(?s).*<" + v.getKey() + " +value=\"" + java.util.regex.Pattern.quote(Numbers.format(v.getValue()))
                    + "\".*"), v.getKey() + " = " + v.getValue() + " not written:\n" + text);
        }
        editor.run(ITextOperationTarget.UNDO);
        assertEquals(original, editor.document().get());
    }

    /** Types {@code text} into {@code box} with real key presses, over what it held (Ctrl+A first). */
    private static void typeInto(org.eclipse.swt.widgets.Control box, String text) {
        box.getShell().forceActive();
        box.setFocus();
        Ui.pump(box::isFocusControl, "the box to have the focus");
        org.eclipse.swt.widgets.Display d = box.getDisplay();
        java.util.List<org.eclipse.swt.widgets.Event> keys = new ArrayList<>();
        keys.add(key(SWT.KeyDown, SWT.CTRL, (char) 0));
        keys.add(key(SWT.KeyDown, 'a', 'a'));
        keys.add(key(SWT.KeyUp, 'a', 'a'));
        keys.add(key(SWT.KeyUp, SWT.CTRL, (char) 0));
        for (char c : text.toCharArray()) {
            keys.add(key(SWT.KeyDown, c, c));
            keys.add(key(SWT.KeyUp, c, c));
        }
        for (org.eclipse.swt.widgets.Event e : keys) {
            assertTrue(d.post(e), "the key could not be posted");
            Ui.settle();
        }
    }

    private static org.eclipse.swt.widgets.Event key(int type, int code, char c) {
        org.eclipse.swt.widgets.Event e = new org.eclipse.swt.widgets.Event();
        e.type = type;
        e.keyCode = code;
        e.character = c;
        return e;
    }

    /** Issue 23, item 13: "2.5" typed into Values ran 25 values (a spin box dropped the point); it is the one value 2.5. */
    @Test
    void aFractionTypedIntoValuesIsOneValueNotACount() {
        dialog.setDuration("0.5");
        vary("amp", "10", "60", 3);
        typeInto(dialog.sweepTab().line("amp").values(), "2.5");
        Ui.pump(() -> "2.5".equals(Ui.text(dialog.sweepTab().line("amp").values())), "the typed value");
        runToEnd();
        assertEquals(1, dialog.results().rows().size(), "runs of amp for Values '2.5': " + dialog.results().rows());
        assertEquals(2.5, dialog.results().rows().get(0).values().get("amp"));
    }

    /** The Values box read in a locale with a decimal point and in one with a decimal comma. */
    @Test
    void valuesAreACountOrTheValuesInTheUsersLocale() throws Exception {
        assertEquals(new SweepTab.Values(3, List.of()), SweepTab.Values.read("3", java.util.Locale.ENGLISH));
        assertEquals(List.of(2.5), SweepTab.Values.read("2.5", java.util.Locale.ENGLISH).list());
        assertEquals(List.of(2.5), SweepTab.Values.read(" 2,5 ", java.util.Locale.GERMANY).list());
        assertEquals(List.of(2.5), SweepTab.Values.read("2.5", java.util.Locale.GERMANY).list());
        assertEquals(List.of(0.5, 1.0, 2.0), SweepTab.Values.read("0.5; 1; 2", java.util.Locale.ENGLISH).list());
        assertEquals(List.of(0.5, 1.0, 2.0), SweepTab.Values.read("0,5; 1; 2", java.util.Locale.FRANCE).list());
        assertEquals(List.of(10.0, 20.0), SweepTab.Values.read("10,20", java.util.Locale.ENGLISH).list());
        org.junit.jupiter.api.Assertions.assertThrows(org.parpe.sim.sweep.SweepException.class,
                () -> SweepTab.Values.read("many", java.util.Locale.ENGLISH));
        org.junit.jupiter.api.Assertions.assertThrows(org.parpe.sim.sweep.SweepException.class,
                () -> SweepTab.Values.read("0", java.util.Locale.ENGLISH));
    }

    /** Issue 23, item 13: when no run beat the script's own values the dialog said only "Best: run 0". */
    @Test
    void whenNothingBeatsTheScriptsOwnValuesTheDialogSaysSo() {
        dialog.setDuration("0.5");
        vary("amp", "35", "35", 1);
        runToEnd();
        assertTrue(dialog.message().contains("Nothing beat the script's own values"), dialog.message());
        assertTrue(dialog.message().contains("run 0"), dialog.message());
        vary("amp", "30", "35", 2);
        runToEnd();
        SweepRow best = dialog.results().best();
        assertNotNull(best);
        assertEquals(best.values().get("amp") == 35.0, dialog.message().contains("Nothing beat the script's own values"),
                dialog.message());
    }

    @Test
    void aFinishedSweepForTheManual() throws Exception {
        dialog.setDuration("4");
        vary("amp", "10", "60", 6);
        vary("period", "1", "3", 3);
        runToEnd();
        assertEquals(18, dialog.table().control().getItemCount());
        dialog.table().control().getColumn(3).notifyListeners(SWT.Selection, new org.eclipse.swt.widgets.Event());
        Ui.settle();
        // docs/images/sweep-dialog.png is this picture (see docs/ide.md).
        Ui.screenshot(dialog.shell(), "sweep-dialog.png");
    }
}
