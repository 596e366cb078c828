package org.parpe.gui.app;

import org.parpe.gui.editor.FindReplaceDialog;
import org.parpe.gui.files.Examples;
import org.parpe.gui.files.ExportProgramDialog;
import org.parpe.gui.files.ExportRobotDialog;
import org.parpe.gui.files.FileActions;
import org.parpe.gui.hardware.HardwareDialog;
import org.parpe.gui.help.HelpText;
import org.parpe.gui.help.QuickReference;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.eclipse.jface.dialogs.InputDialog;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.jface.text.ITextOperationTarget;
import org.eclipse.jface.text.source.ISourceViewer;
import org.eclipse.jface.window.Window;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Menu;
import org.eclipse.swt.widgets.MenuItem;
import org.eclipse.swt.widgets.Text;
import org.parpe.gui.help.TutorialWindow;
import org.parpe.gui.grade.ClassWindow;
import org.parpe.gui.sweep.SweepDialog;
import org.parpe.gui.sweep.SweepHost;
import org.parpe.core.edit.SectionEdits;
import org.parpe.core.edit.TextEdit;

/** The menu bar: File, Edit, Run, View and Help. Every item acts; none is a placeholder. */
final class MenuBar {
    private final IdeWindow ide;
    private FindReplaceDialog find;
    private SweepDialog sweep;
    private ClassWindow classWindow;
    private ExportRobotDialog exportRobot;
    private ExportProgramDialog exportProgram;

    MenuBar(IdeWindow ide) {
        this.ide = ide;
    }

    void install() {
        Menu bar = new Menu(ide.shell(), SWT.BAR);
        fileMenu(submenu(bar, "&File"));
        editMenu(submenu(bar, "&Edit"));
        runMenu(submenu(bar, "&Run"));
        viewMenu(submenu(bar, "&View"));
        helpMenu(submenu(bar, "&Help"));
        ide.shell().setMenuBar(bar);
    }

    private static Menu submenu(Menu parent, String text) {
        MenuItem it = new MenuItem(parent, SWT.CASCADE);
        it.setText(text);
        Menu m = new Menu(parent.getShell(), SWT.DROP_DOWN);
        it.setMenu(m);
        return m;
    }

    private static MenuItem item(Menu m, String text, int accelerator, Runnable action) {
        MenuItem it = new MenuItem(m, SWT.PUSH);
        it.setText(text);
        if (accelerator != 0) {
            it.setAccelerator(accelerator);
        }
        it.addListener(SWT.Selection, e -> action.run());
        return it;
    }

    private void fileMenu(Menu m) {
        FileActions f = ide.files();
        item(m, "&New\tCtrl+N", SWT.MOD1 + 'N', f::newFile);
        item(m, "&Open\u2026\tCtrl+O", SWT.MOD1 + 'O', f::open);
        Menu recent = submenu(m, "Open &Recent");
        recent.addListener(SWT.Show, e -> fillRecent(recent));
        Menu examples = submenu(m, "&Examples");
        examples.addListener(SWT.Show, e -> fillExamples(examples));
        new MenuItem(m, SWT.SEPARATOR);
        item(m, "&Save\tCtrl+S", SWT.MOD1 + 'S', f::save);
        item(m, "Save &As\u2026\tCtrl+Shift+S", SWT.MOD1 + SWT.SHIFT + 'S', f::saveAs);
        new MenuItem(m, SWT.SEPARATOR);
        item(m, "Export Ro&bot\u2026", 0, this::openExportRobot);
        item(m, "Export &Program as C/Arduino\u2026", 0, this::openExportProgram);
        new MenuItem(m, SWT.SEPARATOR);
        item(m, "E&xit\tCtrl+Q", SWT.MOD1 + 'Q', () -> ide.shell().close());
    }

    /** File → Export Robot…: one window per IDE window, on the open script's robot choice. */
    ExportRobotDialog openExportRobot() {
        if (exportRobot == null || exportRobot.shell().isDisposed()) {
            exportRobot = ExportRobotDialog.open(ide.shell(), ide::program, ide.robotChoice(), ide::showRunDiagnostics);
        } else {
            exportRobot.shell().setActive();
        }
        return exportRobot;
    }

    /** File → Export Program as C/Arduino…: one window per IDE window, on the open script. */
    ExportProgramDialog openExportProgram() {
        if (exportProgram == null || exportProgram.shell().isDisposed()) {
            exportProgram = ExportProgramDialog.open(ide.shell(), ide::program, ide::showRunDiagnostics);
        } else {
            exportProgram.shell().setActive();
        }
        return exportProgram;
    }

    private void fillRecent(Menu recent) {
        for (MenuItem it : recent.getItems()) {
            it.dispose();
        }
        List<Path> files = ide.prefs().recentFiles();
        if (files.isEmpty()) {
            new MenuItem(recent, SWT.PUSH).setText("(no recent files)");
            recent.getItem(0).setEnabled(false);
            return;
        }
        for (Path p : files) {
            item(recent, p.getFileName() + "  \u2014  " + p.getParent(), 0, () -> {
                if (Files.isRegularFile(p)) {
                    ide.files().openConfirmed(p);
                } else {
                    MessageDialog.openError(ide.shell(), "File not found", p + " no longer exists.");
                }
            });
        }
        new MenuItem(recent, SWT.SEPARATOR);
        item(recent, "Clear list", 0, ide.prefs()::clearRecent);
    }

    private void fillExamples(Menu examples) {
        for (MenuItem it : examples.getItems()) {
            it.dispose();
        }
        List<Path> list = Examples.list();
        if (list.isEmpty()) {
            MenuItem none = new MenuItem(examples, SWT.PUSH);
            none.setText("(no examples folder found; set -Dparpe.examples=DIR)");
            none.setEnabled(false);
        }
        for (Path p : list) {
            item(examples, p.getFileName().toString(), 0, () -> ide.files().openExample(p));
        }
        List<Path> lessons = Examples.lessons();
        if (!lessons.isEmpty()) {
            new MenuItem(examples, SWT.SEPARATOR);
            Menu tutorial = submenu(examples, "&Tutorial lessons");
            for (Path p : lessons) {
                item(tutorial, p.getFileName().toString(), 0, () -> ide.files().openExample(p));
            }
        }
    }

    private void editMenu(Menu m) {
        item(m, "&Undo\tCtrl+Z", SWT.MOD1 + 'Z', () -> ide.editor().run(ITextOperationTarget.UNDO));
        item(m, "&Redo\tCtrl+Y", SWT.MOD1 + 'Y', () -> ide.editor().run(ITextOperationTarget.REDO));
        new MenuItem(m, SWT.SEPARATOR);
        item(m, "Cu&t\tCtrl+X", SWT.MOD1 + 'X', () -> textOp(ITextOperationTarget.CUT));
        item(m, "&Copy\tCtrl+C", SWT.MOD1 + 'C', () -> textOp(ITextOperationTarget.COPY));
        item(m, "&Paste\tCtrl+V", SWT.MOD1 + 'V', () -> textOp(ITextOperationTarget.PASTE));
        item(m, "Select &All\tCtrl+A", SWT.MOD1 + 'A', () -> textOp(ITextOperationTarget.SELECT_ALL));
        new MenuItem(m, SWT.SEPARATOR);
        item(m, "&Find/Replace\u2026\tCtrl+F", SWT.MOD1 + 'F', this::openFind);
        // The editor's key (ParslEditor); GTK would not show "Ctrl+Space" after a tab.
        item(m, "Content &Assist (Ctrl+Space)", 0, () -> {
            ide.editor().widget().setFocus();
            ide.editor().run(ISourceViewer.CONTENTASSIST_PROPOSALS);
        });
        item(m, "&Go to Line\u2026\tCtrl+L", SWT.MOD1 + 'L', this::gotoLine);
    }

    /** Clipboard operations go to the text field that has the focus, else to the editor. */
    private void textOp(int op) {
        Control focus = ide.shell().getDisplay().getFocusControl();
        if (ide.grid().hasFocus() && (op == ITextOperationTarget.COPY || op == ITextOperationTarget.PASTE)) {
            if (op == ITextOperationTarget.COPY) {
                ide.grid().copy();
            } else {
                ide.grid().paste();
            }
            return;
        }
        if (focus instanceof Text t) {
            switch (op) {
                case ITextOperationTarget.CUT -> t.cut();
                case ITextOperationTarget.COPY -> t.copy();
                case ITextOperationTarget.PASTE -> t.paste();
                default -> t.selectAll();
            }
            return;
        }
        ide.editor().run(op);
    }

    private void openFind() {
        if (find == null || find.getShell() == null || find.getShell().isDisposed()) {
            find = new FindReplaceDialog(ide.shell(), ide.editor().viewer().getFindReplaceTarget(),
                    () -> ide.editor().widget().showSelection());
            find.open();
        } else {
            find.getShell().setActive();
        }
    }

    private void gotoLine() {
        int lines = ide.editor().document().getNumberOfLines();
        InputDialog d = new InputDialog(ide.shell(), "Go to Line", "Line (1\u2013" + lines + "):", "", s -> {
            try {
                int n = Integer.parseInt(s.trim());
                return n >= 1 && n <= lines ? null : "Enter a line between 1 and " + lines;
            } catch (NumberFormatException e) {
                return "Enter a line number";
            }
        });
        if (d.open() == Window.OK) {
            ide.editor().reveal(Integer.parseInt(d.getValue().trim()), 1);
        }
    }

    private void runMenu(Menu m) {
        RunActions r = ide.runs();
        item(m, "&Run\tF5", SWT.F5, () -> r.run(true, -1, null));
        item(m, "&Pause/Resume\tF6", SWT.F6, r::pause);
        item(m, "&Stop\tShift+F5", SWT.SHIFT + SWT.F5, r::stop);
        // Esc is the window's (IdeWindow's key filter: anywhere, dialogs too), not a menu accelerator, and GTK shows
        // the text after a tab only for a key it can read (not Esc): the key is named in the label, as on the tool bar.
        item(m, "&Emergency Stop (Esc)", 0, r::emergencyStop);
        new MenuItem(m, SWT.SEPARATOR);
        item(m, "&Hardware\u2026", 0, () -> HardwareDialog.open(ide));
        item(m, "S&weep / Optimise\u2026", 0, this::openSweep);
        item(m, "Grade a &Class\u2026", 0, this::openClass);
    }

    /** Run → Grade a Class…: one Class window per IDE window. */
    private void openClass() {
        if (classWindow == null || classWindow.shell().isDisposed()) {
            classWindow = ClassWindow.open(ide.shell());
        } else {
            classWindow.activate();
        }
    }

    /** Run → Sweep / Optimise…: one dialog per window, on the editor's script. */
    private void openSweep() {
        if (sweep == null || sweep.shell().isDisposed()) {
            sweep = SweepDialog.open(new SweepHost(ide.shell(), ide.editor(), ide.files()::pathForLoading,
                    ide::robotChoice, () -> ide.viewBar().world().file(), ide::showRunDiagnostics));
        } else {
            sweep.activate();
        }
    }

    private void viewMenu(Menu m) {
        // The keys are the window's own (a filter catches them wherever the focus is, the keypad's
        // too); the accelerators only show them, so that a key press is one step, not two.
        item(m, "Zoom &In\tCtrl++", SWT.MOD1 + '+', () -> ide.zoom(1));
        item(m, "Zoom &Out\tCtrl+\u2212", SWT.MOD1 + '-', () -> ide.zoom(-1));
        item(m, "Reset &Zoom\tCtrl+0", SWT.MOD1 + '0', () -> ide.zoom(0));
        new MenuItem(m, SWT.SEPARATOR);
        item(m, "Reset &3D View", 0, () -> ide.view().resetView());
        item(m, "Clear Run &Log", 0, ide::clearLog);
    }

    private void helpMenu(Menu m) {
        item(m, "&Tutorial", 0, this::openTutorial);
        MenuItem atStart = new MenuItem(m, SWT.CHECK);
        atStart.setText("Open the Tutorial at &Every Start");
        atStart.setSelection(IdeWindow.tutorialAtStart(ide.prefs()));
        atStart.addListener(SWT.Selection, e -> ide.prefs().put(IdeWindow.TUTORIAL_AT_START, atStart.getSelection() ? "yes" : "no"));
        item(m, "PARSL &Quick Reference", SWT.F1, () -> QuickReference.open(ide.shell()));
        item(m, "&About PARPE", 0, () -> MessageDialog.openInformation(ide.shell(), "About PARPE", HelpText.ABOUT));
    }

    /**
     * Help → Tutorial: the lessons beside the examples ({@code docs/tutorial}), docked beside the
     * outline where the screen has no room for their own window beside the IDE, else in that window
     * (null: not found).
     */
    TutorialWindow openTutorial() {
        Path folder = Examples.tutorialFolder();
        if (folder == null) {
            MessageDialog.openInformation(ide.shell(), "Tutorial", "The tutorial (docs/tutorial) was not found next to the"
                    + " examples. It is also online with the PARPE sources, in docs/tutorial/index.md.");
            return null;
        }
        java.util.function.Consumer<Path> open = p -> ide.files().openExample(p);
        if (TutorialDock.wanted(ide.shell())) {
            return ide.tutorialDock().open(dock -> {
                TutorialWindow t = TutorialWindow.docked(dock, folder, open, this::insertLessonCode);
                t.showInstalledCommands(Examples.installed());
                return t;
            });
        }
        TutorialWindow tutorial = new TutorialWindow(ide.shell(), folder, open, this::insertLessonCode);
        tutorial.showInstalledCommands(Examples.installed());
        tutorial.open();
        return tutorial;
    }

    /**
     * The tutorial's "Insert this code": sections go where they belong, into the script's section
     * of that name or at the top level ({@link SectionEdits#placeSections}), never into the
     * element the caret is in; an element of a section goes on a line of its own at the caret's
     * line, where the student chose. One change: Edit > Undo takes it back.
     */
    void insertLessonCode(String code) {
        var w = ide.editor().widget();
        String text = ide.editor().document().get();
        TextEdit edit;
        try {
            edit = SectionEdits.placeSections(text, ide.files().name(), code);
        } catch (IllegalArgumentException e) {
            ide.status().setMessage("The lesson's code was not inserted: " + e.getMessage());
            return;
        }
        if (edit == null) {
            edit = TextEdit.of(w.getOffsetAtLine(w.getLineAtOffset(w.getCaretOffset())), 0, code.strip() + "\n");
        }
        int at;
        try {
            at = ide.editor().apply(edit);
        } catch (org.eclipse.jface.text.BadLocationException e) {
            ide.status().setMessage("The lesson's code was not inserted: " + e.getMessage());
            return;
        }
        if (at < 0) {
            ide.status().setMessage("The lesson's code adds nothing: its sections are empty.");
            return;
        }
        String now = ide.editor().document().get();
        while (at < now.length() && Character.isWhitespace(now.charAt(at))) {
            at++;
        }
        ide.shell().forceActive();
        ide.status().setMessage("The lesson's code is in the editor from line " + (w.getLineAtOffset(at) + 1)
                + " (Edit > Undo takes it back).");
    }
}
