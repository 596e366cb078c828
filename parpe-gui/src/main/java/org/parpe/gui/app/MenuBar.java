package org.parpe.gui.app;

import org.parpe.gui.editor.FindReplaceDialog;
import org.parpe.gui.files.Examples;
import org.parpe.gui.files.ExportProgramDialog;
import org.parpe.gui.files.ExportRobotDialog;
import org.parpe.gui.files.FileActions;
import org.parpe.gui.hardware.HardwareDialog;
import org.parpe.gui.help.HelpText;
import org.parpe.gui.help.QuickReference;
import org.parpe.gui.text.IdeLanguage;
import org.parpe.gui.text.UiMsg;

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
        Menu bar = new Menu(ide.shell, SWT.BAR);
        fileMenu(submenu(bar, UiMsg.MENU_FILE.text()));
        editMenu(submenu(bar, UiMsg.MENU_EDIT.text()));
        runMenu(submenu(bar, UiMsg.MENU_RUN.text()));
        viewMenu(submenu(bar, UiMsg.MENU_VIEW.text()));
        helpMenu(submenu(bar, UiMsg.MENU_HELP.text()));
        ide.shell.setMenuBar(bar);
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
        FileActions f = ide.files;
        item(m, UiMsg.MENU_NEW.text() + "\tCtrl+N", SWT.MOD1 + 'N', f::newFile);
        item(m, UiMsg.MENU_OPEN.text() + "\tCtrl+O", SWT.MOD1 + 'O', f::open);
        Menu recent = submenu(m, UiMsg.MENU_OPEN_RECENT.text());
        recent.addListener(SWT.Show, e -> fillRecent(recent));
        Menu examples = submenu(m, UiMsg.MENU_EXAMPLES.text());
        examples.addListener(SWT.Show, e -> fillExamples(examples));
        new MenuItem(m, SWT.SEPARATOR);
        item(m, UiMsg.MENU_SAVE.text() + "\tCtrl+S", SWT.MOD1 + 'S', f::save);
        item(m, UiMsg.MENU_SAVE_AS.text() + "\tCtrl+Shift+S", SWT.MOD1 + SWT.SHIFT + 'S', f::saveAs);
        new MenuItem(m, SWT.SEPARATOR);
        item(m, UiMsg.MENU_EXPORT_ROBOT.text(), 0, this::openExportRobot);
        item(m, UiMsg.MENU_EXPORT_PROGRAM.text(), 0, this::openExportProgram);
        new MenuItem(m, SWT.SEPARATOR);
        item(m, UiMsg.MENU_EXIT.text() + "\tCtrl+Q", SWT.MOD1 + 'Q', () -> ide.shell.close());
    }

    /** File → Export Robot…: one window per IDE window, on the open script's robot choice. */
    ExportRobotDialog openExportRobot() {
        if (exportRobot == null || exportRobot.shell().isDisposed()) {
            exportRobot = ExportRobotDialog.open(ide.shell, ide::program, ide.robotChoice(), ide::showRunDiagnostics);
        } else {
            exportRobot.shell().setActive();
        }
        return exportRobot;
    }

    /** File → Export Program as C/Arduino…: one window per IDE window, on the open script. */
    ExportProgramDialog openExportProgram() {
        if (exportProgram == null || exportProgram.shell().isDisposed()) {
            exportProgram = ExportProgramDialog.open(ide.shell, ide::program, ide::showRunDiagnostics);
        } else {
            exportProgram.shell().setActive();
        }
        return exportProgram;
    }

    private void fillRecent(Menu recent) {
        for (MenuItem it : recent.getItems()) {
            it.dispose();
        }
        List<Path> files = ide.prefs.recentFiles();
        if (files.isEmpty()) {
            new MenuItem(recent, SWT.PUSH).setText(UiMsg.NO_RECENT_FILES.text());
            recent.getItem(0).setEnabled(false);
            return;
        }
        for (Path p : files) {
            item(recent, p.getFileName() + "  \u2014  " + p.getParent(), 0, () -> {
                if (Files.isRegularFile(p)) {
                    ide.files.openConfirmed(p);
                } else {
                    MessageDialog.openError(ide.shell, UiMsg.FILE_NOT_FOUND.text(), UiMsg.NO_LONGER_EXISTS.text(p));
                }
            });
        }
        new MenuItem(recent, SWT.SEPARATOR);
        item(recent, UiMsg.CLEAR_LIST.text(), 0, ide.prefs::clearRecent);
    }

    private void fillExamples(Menu examples) {
        for (MenuItem it : examples.getItems()) {
            it.dispose();
        }
        List<Path> list = Examples.list();
        if (list.isEmpty()) {
            MenuItem none = new MenuItem(examples, SWT.PUSH);
            none.setText(UiMsg.NO_EXAMPLES_FOLDER.text());
            none.setEnabled(false);
        }
        for (Path p : list) {
            item(examples, p.getFileName().toString(), 0, () -> ide.files.openExample(p));
        }
        List<Path> lessons = Examples.lessons();
        if (!lessons.isEmpty()) {
            new MenuItem(examples, SWT.SEPARATOR);
            Menu tutorial = submenu(examples, UiMsg.MENU_TUTORIAL_LESSONS.text());
            for (Path p : lessons) {
                item(tutorial, p.getFileName().toString(), 0, () -> ide.files.openExample(p));
            }
        }
    }

    private void editMenu(Menu m) {
        item(m, UiMsg.MENU_UNDO.text() + "\tCtrl+Z", SWT.MOD1 + 'Z', () -> ide.editor.run(ITextOperationTarget.UNDO));
        item(m, UiMsg.MENU_REDO.text() + "\tCtrl+Y", SWT.MOD1 + 'Y', () -> ide.editor.run(ITextOperationTarget.REDO));
        new MenuItem(m, SWT.SEPARATOR);
        item(m, UiMsg.MENU_CUT.text() + "\tCtrl+X", SWT.MOD1 + 'X', () -> textOp(ITextOperationTarget.CUT));
        item(m, UiMsg.MENU_COPY.text() + "\tCtrl+C", SWT.MOD1 + 'C', () -> textOp(ITextOperationTarget.COPY));
        item(m, UiMsg.MENU_PASTE.text() + "\tCtrl+V", SWT.MOD1 + 'V', () -> textOp(ITextOperationTarget.PASTE));
        item(m, UiMsg.MENU_SELECT_ALL.text() + "\tCtrl+A", SWT.MOD1 + 'A', () -> textOp(ITextOperationTarget.SELECT_ALL));
        new MenuItem(m, SWT.SEPARATOR);
        item(m, UiMsg.MENU_FIND_REPLACE.text() + "\tCtrl+F", SWT.MOD1 + 'F', this::openFind);
        // The editor's key (ParslEditor); GTK would not show "Ctrl+Space" after a tab.
        item(m, UiMsg.MENU_CONTENT_ASSIST.text(), 0, () -> {
            ide.editor.widget().setFocus();
            ide.editor.run(ISourceViewer.CONTENTASSIST_PROPOSALS);
        });
        item(m, UiMsg.MENU_GO_TO_LINE.text() + "\tCtrl+L", SWT.MOD1 + 'L', this::gotoLine);
    }

    /** Clipboard operations go to the text field that has the focus, else to the editor. */
    private void textOp(int op) {
        Control focus = ide.shell.getDisplay().getFocusControl();
        if (ide.grid.hasFocus() && (op == ITextOperationTarget.COPY || op == ITextOperationTarget.PASTE)) {
            if (op == ITextOperationTarget.COPY) {
                ide.grid.copy();
            } else {
                ide.grid.paste();
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
        ide.editor.run(op);
    }

    private void openFind() {
        if (find == null || find.getShell() == null || find.getShell().isDisposed()) {
            find = new FindReplaceDialog(ide.shell, ide.editor.viewer().getFindReplaceTarget(),
                    () -> ide.editor.widget().showSelection());
            find.open();
        } else {
            find.getShell().setActive();
        }
    }

    private void gotoLine() {
        int lines = ide.editor.document().getNumberOfLines();
        InputDialog d = new InputDialog(ide.shell, UiMsg.GO_TO_LINE.text(), UiMsg.LINE_RANGE.text(lines), "", s -> {
            try {
                int n = Integer.parseInt(s.trim());
                return n >= 1 && n <= lines ? null : UiMsg.ENTER_LINE_BETWEEN.text(lines);
            } catch (NumberFormatException e) {
                return UiMsg.ENTER_LINE_NUMBER.text();
            }
        });
        if (d.open() == Window.OK) {
            ide.editor.reveal(Integer.parseInt(d.getValue().trim()), 1);
        }
    }

    private void runMenu(Menu m) {
        RunActions r = ide.runs;
        item(m, UiMsg.MENU_RUN_RUN.text() + "\tF5", SWT.F5, () -> r.run(true, -1, null));
        item(m, UiMsg.MENU_PAUSE_RESUME.text() + "\tF6", SWT.F6, r::pause);
        item(m, UiMsg.MENU_STOP.text() + "\tShift+F5", SWT.SHIFT + SWT.F5, r::stop);
        // Esc is the window's (IdeWindow's key filter: anywhere, dialogs too), not a menu accelerator, and GTK shows
        // the text after a tab only for a key it can read (not Esc): the key is named in the label, as on the tool bar.
        item(m, UiMsg.MENU_EMERGENCY_STOP.text(), 0, r::emergencyStop);
        new MenuItem(m, SWT.SEPARATOR);
        item(m, UiMsg.MENU_HARDWARE.text(), 0, () -> HardwareDialog.open(ide.hardware));
        item(m, UiMsg.MENU_SWEEP.text(), 0, this::openSweep);
        item(m, UiMsg.MENU_GRADE_CLASS.text(), 0, this::openClass);
    }

    /** Run → Grade a Class…: one Class window per IDE window. */
    private void openClass() {
        if (classWindow == null || classWindow.shell().isDisposed()) {
            classWindow = ClassWindow.open(ide.shell);
        } else {
            classWindow.activate();
        }
    }

    /** Run → Sweep / Optimise…: one dialog per window, on the editor's script. */
    private void openSweep() {
        if (sweep == null || sweep.shell().isDisposed()) {
            sweep = SweepDialog.open(new SweepHost(ide.shell, ide.editor, ide.document,
                    ide::robotChoice, () -> ide.viewBar.world().file(), ide::showRunDiagnostics));
        } else {
            sweep.activate();
        }
    }

    private void viewMenu(Menu m) {
        // The keys are the window's own (a filter catches them wherever the focus is, the keypad's
        // too); the accelerators only show them, so that a key press is one step, not two.
        item(m, UiMsg.MENU_ZOOM_IN.text() + "\tCtrl++", SWT.MOD1 + '+', () -> ide.zoom(1));
        item(m, UiMsg.MENU_ZOOM_OUT.text() + "\tCtrl+\u2212", SWT.MOD1 + '-', () -> ide.zoom(-1));
        item(m, UiMsg.MENU_RESET_ZOOM.text() + "\tCtrl+0", SWT.MOD1 + '0', () -> ide.zoom(0));
        new MenuItem(m, SWT.SEPARATOR);
        item(m, UiMsg.MENU_RESET_3D.text(), 0, () -> ide.view.resetView());
        item(m, UiMsg.MENU_CLEAR_LOG.text(), 0, () -> ide.bottom.clearLog());
        new MenuItem(m, SWT.SEPARATOR);
        languageMenu(submenu(m, UiMsg.MENU_LANGUAGE.text()));
    }

    /**
     * View → Language: as the system, or one of the languages PARPE speaks, each named in itself;
     * kept in the preferences, spoken from the next start (docs/ide.md, "Language").
     */
    private void languageMenu(Menu m) {
        String chosen = ide.prefs.get(IdeLanguage.PREFERENCE, "");
        language(m, UiMsg.LANGUAGE_SYSTEM.text(), "", chosen);
        new MenuItem(m, SWT.SEPARATOR);
        for (java.util.Locale l : org.parpe.core.text.Lang.SUPPORTED) {
            String name = l.getDisplayLanguage(l);
            language(m, name.substring(0, 1).toUpperCase(l) + name.substring(1), l.getLanguage(), chosen);
        }
    }

    private void language(Menu m, String text, String code, String chosen) {
        MenuItem it = new MenuItem(m, SWT.RADIO);
        it.setText(text);
        it.setSelection(code.equals(chosen));
        it.addListener(SWT.Selection, e -> {
            if (it.getSelection() && !code.equals(ide.prefs.get(IdeLanguage.PREFERENCE, ""))) {
                ide.prefs.put(IdeLanguage.PREFERENCE, code);
                MessageDialog.openInformation(ide.shell, UiMsg.LANGUAGE_TITLE.text(), UiMsg.LANGUAGE_AFTER_RESTART.text());
            }
        });
    }

    private void helpMenu(Menu m) {
        item(m, UiMsg.MENU_TUTORIAL.text(), 0, this::openTutorial);
        MenuItem atStart = new MenuItem(m, SWT.CHECK);
        atStart.setText(UiMsg.MENU_TUTORIAL_AT_START.text());
        atStart.setSelection(IdeWindow.tutorialAtStart(ide.prefs));
        atStart.addListener(SWT.Selection, e -> ide.prefs.put(IdeWindow.TUTORIAL_AT_START, atStart.getSelection() ? "yes" : "no"));
        item(m, UiMsg.MENU_QUICK_REFERENCE.text(), SWT.F1, () -> QuickReference.open(ide.shell));
        item(m, UiMsg.MENU_ABOUT.text(), 0, () -> MessageDialog.openInformation(ide.shell, UiMsg.ABOUT_TITLE.text(), HelpText.about()));
    }

    /**
     * Help → Tutorial: the lessons beside the examples ({@code docs/tutorial}), docked beside the
     * outline where the screen has no room for their own window beside the IDE, else in that window
     * (null: not found).
     */
    TutorialWindow openTutorial() {
        Path folder = Examples.tutorialFolder();
        if (folder == null) {
            MessageDialog.openInformation(ide.shell, UiMsg.TUTORIAL_TITLE.text(), UiMsg.TUTORIAL_NOT_FOUND.text());
            return null;
        }
        java.util.function.Consumer<Path> open = p -> ide.files.openExample(p);
        if (TutorialDock.wanted(ide.shell)) {
            return ide.tutorialDock.open(dock -> {
                TutorialWindow t = TutorialWindow.docked(dock, folder, open, this::insertLessonCode);
                t.showInstalledCommands(Examples.installed());
                return t;
            });
        }
        TutorialWindow tutorial = new TutorialWindow(ide.shell, folder, open, this::insertLessonCode);
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
        var w = ide.editor.widget();
        String text = ide.editor.document().get();
        TextEdit edit;
        try {
            edit = SectionEdits.placeSections(text, ide.files.name(), code);
        } catch (IllegalArgumentException e) {
            ide.status.setMessage(UiMsg.LESSON_CODE_NOT_INSERTED.text(e.getMessage()));
            return;
        }
        if (edit == null) {
            edit = TextEdit.of(w.getOffsetAtLine(w.getLineAtOffset(w.getCaretOffset())), 0, code.strip() + "\n");
        }
        int at;
        try {
            at = ide.editor.apply(edit);
        } catch (org.eclipse.jface.text.BadLocationException e) {
            ide.status.setMessage(UiMsg.LESSON_CODE_NOT_INSERTED.text(e.getMessage()));
            return;
        }
        if (at < 0) {
            ide.status.setMessage(UiMsg.LESSON_CODE_ADDS_NOTHING.text());
            return;
        }
        String now = ide.editor.document().get();
        while (at < now.length() && Character.isWhitespace(now.charAt(at))) {
            at++;
        }
        ide.shell.forceActive();
        ide.status.setMessage(UiMsg.LESSON_CODE_INSERTED.text(w.getLineAtOffset(at) + 1));
    }
}
