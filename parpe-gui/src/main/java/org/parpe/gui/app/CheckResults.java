package org.parpe.gui.app;

import java.nio.file.Path;
import java.util.List;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.SourcePos;
import org.parpe.core.edit.SectionEdits;
import org.parpe.core.load.LoadResult;
import org.parpe.core.model.Program;
import org.parpe.gui.editor.ParslEditor;
import org.parpe.gui.panels.ProblemsView;
import org.parpe.gui.text.UiMsg;

/**
 * What the window shows of each check of the open script: the markers, Problems, the outline,
 * the gait table, the controls, the plots' modules and the robot preview, and the status bar's
 * problem counts, kept in step with Problems. Holds the last program that loaded. UI thread only.
 */
final class CheckResults {
    private final IdeWindow ide;
    private Program program;
    private int validations;
    /** The problem counts the status bar says now (renewed when Problems changes), or null. */
    private String shownCounts;

    CheckResults(IdeWindow ide) {
        this.ide = ide;
    }

    /** The last program that loaded, or null. */
    Program program() {
        return program;
    }

    /** How many results have been shown (automation waits for the first). */
    int validations() {
        return validations;
    }

    /** Another file is in the editor: nothing of the previous one's program is kept. */
    void forget() {
        program = null;
        ide.grid.setProgram(null);
        ide.outline.show(null);
        ide.controls.show(null);
        ide.problems().setLoadDiagnostics(List.of());
        ide.problems().clearRunDiagnostics();
    }

    /** Shows a load result: markers, Problems, outline, controls, plots and the robot preview. */
    void show(LoadResult r) {
        validations++;
        if (ide.robotTab.documentChecked(r.program())) { // a robot configuration: its own problems
            ide.problems().setLoadDiagnostics(ide.robotTab.problems());
            showProblemCounts("");
            return;
        }
        if (emptyScript()) {
            showEmpty();
            return;
        }
        ide.problems().setLoadDiagnostics(r.diagnostics());
        RunActions runs = ide.runs;
        if (r.program() != null) {
            program = r.program();
            ide.grid.setProgram(program);
            ide.outline.show(program);
            if (!runs.running()) {
                ide.controls.show(program);
            }
            ide.plots.setModules(program.moduleIds());
            runs.updatePreview(program);
        }
        if (!runs.running()) {
            showProblemCounts(ide.editor.plain() ? UiMsg.NO_COLOURING.text(ParslEditor.COLOUR_LIMIT / 1_000_000) : "");
        }
    }

    /** Whether the editor holds no script yet (nothing, white space, or a declaration and comments): the Diagram's "Start a robot". */
    boolean emptyScript() {
        return SectionEdits.blank(ide.editor.document().get());
    }

    /**
     * An empty file is a beginning, not a mistake: no problem listed, and nothing left of the
     * script shown before (outline, table, controls, robot); the status bar says how to begin.
     */
    private void showEmpty() {
        ide.problems().setLoadDiagnostics(List.of());
        program = null;
        ide.grid.setProgram(null);
        ide.outline.show(null);
        if (!ide.runs.running()) {
            ide.controls.show(null);
            ide.runs.forgetPreview();
            ide.view.clear();
            ide.status.setMessage(empty());
        }
    }

    /** What the status bar says of an empty file. */
    static String empty() {
        return UiMsg.FILE_EMPTY.text();
    }

    /**
     * What Problems holds, in words: "No problems" only when it is empty. The status bar says this
     * after each check of the text and whenever Problems changes, so the two never disagree.
     */
    String problemCounts() {
        ProblemsView problems = ide.problems();
        long errors = problems.errorCount();
        long warnings = problems.shown().size() - errors;
        if (errors == 0 && warnings == 0) {
            return UiMsg.NO_PROBLEMS.text();
        }
        String e = errors == 1 ? UiMsg.ERRORS_ONE.text() : UiMsg.ERRORS_N.text(errors);
        String w = warnings == 1 ? UiMsg.WARNINGS_ONE.text() : UiMsg.WARNINGS_N.text(warnings);
        return UiMsg.SEE_PROBLEMS.text(warnings == 0 ? e : errors == 0 ? w : UiMsg.ERRORS_AND_WARNINGS.text(e, w));
    }

    /** Says {@link #problemCounts()} in the status bar, then {@code more}; {@link #problemsChanged} renews it. */
    private void showProblemCounts(String more) {
        shownCounts = problemCounts() + more;
        ide.status.setMessage(shownCounts);
    }

    /** The Problems view changed: mark this file's problems in the editor and the gait table. */
    void problemsChanged() {
        if (ide.status.message().equals(shownCounts)) {
            showProblemCounts("");
        }
        ProblemsView problems = ide.problems();
        ide.status.setProblems(problems.errorCount(), problems.shown().size() - problems.errorCount());
        Path mine = ide.files.pathForLoading().toAbsolutePath().normalize();
        List<Diagnostic> mineOnly = problems.shown().stream().filter(d -> sameFile(d.pos(), mine))
                .limit(ParslEditor.MARKER_LIMIT).toList();
        ide.editor.setDiagnostics(mineOnly);
        ide.grid.setDiagnostics(mineOnly);
    }

    /** Whether {@code p} is in the file {@code mine}. */
    static boolean sameFile(SourcePos p, Path mine) {
        try {
            Path f = Path.of(p.file());
            return f.toAbsolutePath().normalize().equals(mine) || !f.isAbsolute() && mine.endsWith(f);
        } catch (RuntimeException e) {
            return false;
        }
    }
}
