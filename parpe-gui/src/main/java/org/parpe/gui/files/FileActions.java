package org.parpe.gui.files;

import org.parpe.gui.text.UiMsg;
import org.parpe.gui.prefs.Prefs;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.Consumer;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Shell;
import org.parpe.gui.editor.ParslEditor;

/**
 * The document behind the editor: which file it is, whether it has unsaved changes, and the
 * file commands (new, open, save, save as, recent files, examples). Unsaved text is copied to
 * the autosave folder every few seconds and offered back after a crash. Files are read on a
 * background thread, so opening a large one never freezes the window. UI thread only.
 */
public final class FileActions {
    /** The text of File > New: a crawling snake, its first line pointing to the tutorial in the IDE's language. */
    public static String template() {
        return String.join("\n",
            "<?xml version=\"1.0\"?>",
            "<!-- " + UiMsg.NEW_SCRIPT_COMMENT.text() + " -->",
            "<program>",
            "  <robot>",
            "    <structure>",
            "      <body elements=\"0..7\"/>",
            "    </structure>",
            "  </robot>",
            "  <main>",
            "    <crawl/>",
            "  </main>",
            "  <behaviors>",
            "    <crawl>",
            "      <wave group=\"body\" phase=\"0.25\" period=\"2\"/>",
            "    </crawl>",
            "  </behaviors>",
            "  <automata>",
            "    <wave states=\"up, down\"/>",
            "  </automata>",
            "  <states>",
            "    <up angles=\"30\"/>",
            "    <down angles=\"-30\"/>",
            "  </states>",
            "</program>",
            "");
    }

    private static final int AUTOSAVE_MS = 3000;

    /** Asks a question with buttons and returns the index of the answer (-1: dialog closed); tests answer without a dialog. */
    @FunctionalInterface
    public interface Questions {
        int ask(String title, String message, String... buttons);
    }

    private final Shell shell;
    private final ParslEditor editor;
    private final Prefs prefs;
    private final Autosave autosave;
    private final Runnable changed;
    private final Runnable switched;
    private final Consumer<String> message;
    private final BackgroundRead reader;
    private Path file;
    /** The example this untitled document is a copy of, or null. */
    private Path example;
    private String savedText = "";
    private String autosavedText;
    /** The text the user chose not to save ("Don't Save"), or null: not copied unless edited again. */
    private String discardedText;
    private String slot;
    private boolean recovered;
    private boolean loading;
    private Questions questions;
    private SaveTarget saveTarget;
    /** The file as it was on disk when it was opened or saved (time, size, file): a change means another program wrote it. */
    private DiskStamp disk;

    /**
     * {@code changed} runs after the file, the text or the dirty state changed, {@code switched}
     * when another document is shown; {@code message} shows a line in the status bar.
     */
    public FileActions(Shell shell, ParslEditor editor, Prefs prefs, Runnable changed, Runnable switched, Consumer<String> message) {
        this.message = message;
        this.switched = switched;
        this.shell = shell;
        this.editor = editor;
        this.prefs = prefs;
        this.autosave = new Autosave(prefs.home());
        this.changed = changed;
        this.slot = autosave.untitledSlot();
        this.reader = new BackgroundRead(shell.getDisplay());
        this.questions = (title, text, buttons) -> new MessageDialog(shell, title, null, text, MessageDialog.QUESTION,
                buttons, 0).open();
        this.saveTarget = (folder, name) -> SafeSave.ask(shell, folder, name);
        // another program (or another part of PARPE) may have written the file while the window was in the background
        shell.addListener(SWT.Activate, e -> noticeDiskChange());
        shell.addListener(SWT.Dispose, e -> {
            autosave.close();
            reader.close();
        });
        editor.document().addDocumentListener(new org.eclipse.jface.text.IDocumentListener() {
            @Override
            public void documentAboutToBeChanged(org.eclipse.jface.text.DocumentEvent event) {
            }

            @Override
            public void documentChanged(org.eclipse.jface.text.DocumentEvent event) {
                if (!loading) {
                    changed.run();
                }
            }
        });
        scheduleAutosave();
    }

    /** The file edited, or null for an untitled document. */
    public Path file() {
        return file;
    }

    /** The files open in the editor (none for an untitled document): what other saves of the IDE must not replace. */
    public java.util.List<Path> openFiles() {
        return file == null ? java.util.List.of() : java.util.List.of(file);
    }

    /** The path given to the loader: the file, or an untitled name in the working directory. */
    public Path pathForLoading() {
        return file != null ? file : example != null ? example : Path.of("untitled.xml").toAbsolutePath();
    }

    public String name() {
        return file == null && example != null ? UiMsg.EXAMPLE_COPY_NAME.text(fileName()) : fileName();
    }

    /** The file's name, or the name Save As proposes for an untitled document. */
    private String fileName() {
        return file != null ? file.getFileName().toString() : example != null ? example.getFileName().toString() : "untitled.xml";
    }

    /** The example the untitled document is a copy of, or null. */
    public Path example() {
        return example;
    }

    /** Whether the text is not saved: it differs from the file, or it was recovered and not saved since. */
    public boolean dirty() {
        return recovered || !editor.document().get().equals(savedText);
    }

    /** Asks where to save: the folder to start in and the name proposed; returns the chosen file or null (cancelled). */
    @FunctionalInterface
    public interface SaveTarget {
        Path ask(Path folder, String name);
    }

    /** Chooses where to save with {@code t} instead of the file dialog (tests). */
    public void chooseSaveTargetWith(SaveTarget t) {
        saveTarget = t;
    }

    /** Answers the questions of this class with {@code q} instead of dialogs (tests). */
    public void answerWith(Questions q) {
        questions = q;
    }

    public Autosave autosave() {
        return autosave;
    }

    public void newFile() {
        if (confirmDiscard()) {
            show(null, template(), template(), null);
        }
    }

    public void open() {
        if (!confirmDiscard()) {
            return;
        }
        Path p = org.parpe.gui.panels.FileDialogs.ask(shell, SWT.OPEN, UiMsg.OPEN_SCRIPT_TITLE.text(), "*.xml;*.parsl", null, null);
        if (p != null) {
            openPath(p);
        }
    }

    /**
     * Opens {@code p} without asking (the caller has confirmed). The file is read on a background
     * thread and then shown; meanwhile the window works and the editor is read-only. A message
     * if it cannot be read. A later open, New or recovery wins over one still being read.
     */
    public void openPath(Path p) {
        read(p, false);
    }

    /**
     * File → Examples and the tutorial's lessons: asks first if there are unsaved changes, then
     * opens an untitled copy of the example {@code p}. Its first Save asks where (in the
     * Documents folder), so the example itself is never written. The copy is loaded as if it
     * were at {@code p}, so that the files it names are found beside it.
     */
    public void openExample(Path p) {
        if (confirmDiscard()) {
            read(p, true);
        }
    }

    private void read(Path p, boolean copy) {
        Path abs = p.toAbsolutePath().normalize();
        editor.viewer().setEditable(false);
        message.accept(UiMsg.OPENING.text(abs.getFileName()));
        reader.read(abs, (text, error) -> {
            if (!shell.isDisposed()) {
                opened(abs, text, error, copy);
            }
        });
    }

    private void opened(Path abs, String text, String error, boolean copy) {
        if (text == null) {
            stopReading();
            message.accept("");
            MessageDialog.openError(shell, UiMsg.CANNOT_OPEN_FILE.text(), UiMsg.CANNOT_READ_ERROR.text(abs, error));
            return;
        }
        if (copy) {
            show(null, text, text, null, abs);
            message.accept(UiMsg.EXAMPLE_COPY_OPENED.text(abs.getFileName()));
            return;
        }
        show(abs, text, text, null);
        prefs.addRecent(abs);
    }

    private void stopReading() {
        reader.cancel();
        editor.viewer().setEditable(true);
    }

    /** Whether a file is being read (the editor is read-only meanwhile). */
    public boolean reading() {
        return reader.busy();
    }

    /** Asks first if there are unsaved changes, then opens {@code p}. */
    public void openConfirmed(Path p) {
        if (confirmDiscard()) {
            openPath(p);
        }
    }

    /** Puts a document in the editor; {@code recoveredSlot} is the autosave slot of recovered text, else null. */
    private void show(Path p, String text, String saved, String recoveredSlot) {
        show(p, text, saved, recoveredSlot, null);
    }

    private void show(Path p, String text, String saved, String recoveredSlot, Path exampleOf) {
        stopReading();
        example = exampleOf;
        discardedText = null;
        loading = true;
        try {
            editor.setText(text);
        } finally {
            loading = false;
        }
        file = p;
        disk = p == null ? null : DiskStamp.of(p);
        savedText = saved;
        recovered = recoveredSlot != null;
        slot = recovered ? recoveredSlot : p == null ? autosave.untitledSlot() : Autosave.slotFor(p);
        autosavedText = recovered ? text : null;
        switched.run();
        changed.run();
    }

    public boolean save() {
        if (file != null && changedOnDisk()) {
            int a = questions.ask(UiMsg.FILE_CHANGED_TITLE.text(), UiMsg.FILE_CHANGED_REPLACE.text(name()),
                    UiMsg.BUTTON_REPLACE.text(), org.eclipse.jface.dialogs.IDialogConstants.CANCEL_LABEL);
            if (a != 0) {
                return false;
            }
        }
        return file == null ? saveAs() : write(file);
    }

    /** Whether the file on disk differs from what was opened or last saved (not just touched). */
    private boolean changedOnDisk() {
        if (file == null || disk == null || DiskStamp.of(file).equals(disk)) {
            return false;
        }
        return !savedText.equals(readOrNull(file));
    }

    private static String readOrNull(Path p) {
        try {
            return Files.readString(p, StandardCharsets.UTF_8);
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    /**
     * When the window comes to the front: if another program changed the file, offers to reload
     * it; if the user keeps the editor's text (or the file is gone), that text is marked unsaved,
     * so that it is autosaved and quitting asks before it is lost. Asks once per change.
     */
    void noticeDiskChange() {
        if (reader.busy() || !changedOnDisk()) {
            return;
        }
        disk = DiskStamp.of(file);
        String now = readOrNull(file);
        if (now == null) {
            savedText = "\u0000"; // nothing on disk equals the editor's text: it is unsaved
            message.accept(UiMsg.FILE_DELETED_ON_DISK.text(name()));
            changed.run();
            return;
        }
        String why = UiMsg.FILE_CHANGED_BY_OTHER.text(name());
        int a = questions.ask(UiMsg.FILE_CHANGED_TITLE.text(), (dirty() ? UiMsg.RELOAD_LOSE_CHANGES : UiMsg.RELOAD_OR_KEEP).text(why),
                UiMsg.BUTTON_RELOAD.text(), UiMsg.BUTTON_KEEP_EDITOR.text());
        if (a == 0) {
            show(file, now, now, null);
            message.accept(UiMsg.RELOADED.text(name()));
        } else {
            savedText = now; // the editor's text no longer is what is on disk: it is unsaved
            changed.run();
        }
    }

    public boolean saveAs() {
        Path chosen = saveTarget.ask(org.parpe.gui.panels.FileDialogs.start(), fileName());
        if (chosen == null) {
            return false;
        }
        Path target = chosen.toAbsolutePath().normalize();
        if (example != null && target.equals(example)) {
            MessageDialog.openError(shell, UiMsg.CANNOT_SAVE_OVER_EXAMPLE.text(), UiMsg.EXAMPLE_NEVER_OVERWRITTEN.text(target));
            return false;
        }
        if (write(target)) {
            file = target;
            example = null;
            prefs.addRecent(target);
            changed.run();
            return true;
        }
        return false;
    }

    private boolean write(Path target) {
        String text = editor.document().get();
        try {
            SafeSave.write(target, text);
            savedText = text;
            disk = DiskStamp.of(target);
            recovered = false;
            autosave.clear(slot);
            slot = Autosave.slotFor(target);
            autosave.clear(slot);
            changed.run();
            return true;
        } catch (IOException | RuntimeException e) {
            MessageDialog.openError(shell, UiMsg.CANNOT_SAVE.text(), UiMsg.CANNOT_WRITE_KEPT.text(target, describe(e)));
            return false;
        }
    }

    /**
     * True if there is nothing unsaved, or the user saved it or chose not to. "Don't Save"
     * deletes the autosave copy of edited text, but keeps that of recovered text (it is offered
     * again at the next start): only saving it, or "Discard" when offered, removes it.
     */
    public boolean confirmDiscard() {
        return confirmDiscard(null);
    }

    /** As {@link #confirmDiscard()}, the question also saying {@code alsoLost} (what else quitting loses; null: nothing). */
    public boolean confirmDiscard(String alsoLost) {
        if (!dirty()) {
            return true;
        }
        String message = (recovered ? UiMsg.RECOVERED_NOT_SAVED : UiMsg.UNSAVED_CHANGES_SAVE).text(name())
                + (alsoLost == null ? "" : "\n\n" + alsoLost);
        return switch (questions.ask(UiMsg.UNSAVED_CHANGES_TITLE.text(), message, UiMsg.BUTTON_SAVE.text(),
                UiMsg.BUTTON_DONT_SAVE.text(), org.eclipse.jface.dialogs.IDialogConstants.CANCEL_LABEL)) {
            case 0 -> save();
            case 1 -> {
                if (!recovered) {
                    autosave.clear(slot);
                    autosavedText = null;
                    // Not copied again while another question is open (the timer runs on): only
                    // when the text stays after all and is edited (Open cancelled).
                    discardedText = editor.document().get();
                }
                yield true;
            }
            default -> false;
        };
    }

    /**
     * Offers the copies left by IDEs that are gone (killed, crashed), newest first, until one is
     * recovered or the user says "Not Now"; "Discard" deletes a copy. True if one was recovered:
     * it is then in the editor as unsaved text.
     */
    public boolean offerRecovery() {
        for (Autosave.Copy c : autosave.orphans()) {
            String where = c.describe();
            int answer = questions.ask(UiMsg.RECOVER_TITLE.text(), UiMsg.RECOVER_QUESTION.text(where),
                    UiMsg.BUTTON_RECOVER.text(), UiMsg.BUTTON_DISCARD.text(), UiMsg.BUTTON_NOT_NOW.text());
            if (answer == 1) {
                autosave.discard(c);
            } else if (answer == 0) {
                return recover(c);
            } else {
                return false;
            }
        }
        return false;
    }

    private boolean recover(Autosave.Copy c) {
        String adopted;
        try {
            adopted = autosave.adopt(c);
        } catch (IOException e) {
            MessageDialog.openError(shell, UiMsg.CANNOT_RECOVER.text(), UiMsg.CANNOT_TAKE_OVER.text(describe(e)));
            return false;
        }
        String saved = "";
        if (c.file() != null && Files.isRegularFile(c.file())) {
            try {
                saved = Files.readString(c.file(), StandardCharsets.UTF_8);
            } catch (IOException e) {
                saved = "";
            }
        }
        show(c.file(), c.text(), saved, adopted, c.file() == null ? c.example() : null);
        return true;
    }

    private void scheduleAutosave() {
        shell.getDisplay().timerExec(AUTOSAVE_MS, () -> {
            if (shell.isDisposed()) {
                return;
            }
            autosaveNow();
            scheduleAutosave();
        });
    }

    /** Writes the autosave copy if the text is unsaved and changed since the last copy. */
    public void autosaveNow() {
        String text = editor.document().get();
        if (!dirty()) {
            if (autosavedText != null) {
                // Undone back to the saved text: a copy of it would be offered after a crash for nothing.
                autosave.clear(slot);
                autosavedText = null;
            }
            return;
        }
        if (text.equals(autosavedText) || text.equals(discardedText)) {
            return;
        }
        discardedText = null;
        try {
            autosave.write(slot, file, file == null ? example : null, text);
            autosavedText = text;
        } catch (IOException e) {
            // Keep editing; the next attempt may succeed (disk full, folder removed).
        }
    }

    private static String describe(Throwable e) {
        return org.parpe.core.io.IoReasons.of(e);
    }
}
