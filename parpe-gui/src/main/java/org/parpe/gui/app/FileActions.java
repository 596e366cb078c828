package org.parpe.gui.app;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.FileDialog;
import org.eclipse.swt.widgets.Shell;
import org.parpe.gui.editor.ParslEditor;

/**
 * The document behind the editor: which file it is, whether it has unsaved changes, and the
 * file commands (new, open, save, save as, recent files, examples). Unsaved text is copied to
 * the autosave folder every few seconds and offered back after a crash. UI thread only.
 */
final class FileActions {
    static final String TEMPLATE = String.join("\n",
            "<?xml version=\"1.0\"?>",
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
    private static final int AUTOSAVE_MS = 3000;

    private final Shell shell;
    private final ParslEditor editor;
    private final Prefs prefs;
    private final Autosave autosave;
    private final Runnable changed;
    private final Runnable switched;
    private Path file;
    private String savedText = "";
    private String autosavedText;
    private boolean loading;

    /** {@code changed} runs after the file, the text or the dirty state changed. */
    FileActions(Shell shell, ParslEditor editor, Prefs prefs, Runnable changed, Runnable switched) {
        this.switched = switched;
        this.shell = shell;
        this.editor = editor;
        this.prefs = prefs;
        this.autosave = new Autosave(prefs.home());
        this.changed = changed;
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
    Path file() {
        return file;
    }

    /** The path given to the loader: the file, or an untitled name in the working directory. */
    Path pathForLoading() {
        return file != null ? file : Path.of("untitled.xml").toAbsolutePath();
    }

    String name() {
        return file == null ? "untitled.xml" : file.getFileName().toString();
    }

    boolean dirty() {
        return !editor.document().get().equals(savedText);
    }

    void newFile() {
        if (confirmDiscard()) {
            show(null, TEMPLATE, TEMPLATE);
        }
    }

    void open() {
        if (!confirmDiscard()) {
            return;
        }
        FileDialog d = new FileDialog(shell, SWT.OPEN);
        d.setFilterExtensions(new String[] {"*.xml", "*"});
        d.setFilterNames(new String[] {"PARSL scripts (*.xml)", "All files"});
        if (file != null && file.getParent() != null) {
            d.setFilterPath(file.getParent().toString());
        }
        String p = d.open();
        if (p != null) {
            openPath(Path.of(p));
        }
    }

    /** Opens {@code p} without asking (the caller has confirmed); false with a message if it cannot be read. */
    boolean openPath(Path p) {
        try {
            String text = Files.readString(p, StandardCharsets.UTF_8);
            show(p.toAbsolutePath().normalize(), text, text);
            prefs.addRecent(p);
            return true;
        } catch (IOException | RuntimeException e) {
            MessageDialog.openError(shell, "Cannot open file", "Cannot read " + p + ":\n" + describe(e));
            return false;
        }
    }

    /** Asks first if there are unsaved changes, then opens {@code p}. */
    void openConfirmed(Path p) {
        if (confirmDiscard()) {
            openPath(p);
        }
    }

    private void show(Path p, String text, String saved) {
        loading = true;
        try {
            editor.setText(text);
        } finally {
            loading = false;
        }
        file = p;
        savedText = saved;
        autosavedText = null;
        switched.run();
        changed.run();
    }

    boolean save() {
        return file == null ? saveAs() : write(file);
    }

    boolean saveAs() {
        FileDialog d = new FileDialog(shell, SWT.SAVE);
        d.setFilterExtensions(new String[] {"*.xml", "*"});
        d.setOverwrite(true);
        d.setFileName(name());
        if (file != null && file.getParent() != null) {
            d.setFilterPath(file.getParent().toString());
        }
        String p = d.open();
        if (p == null) {
            return false;
        }
        Path target = Path.of(p).toAbsolutePath().normalize();
        if (write(target)) {
            file = target;
            prefs.addRecent(target);
            changed.run();
            return true;
        }
        return false;
    }

    private boolean write(Path target) {
        String text = editor.document().get();
        try {
            Path dir = target.toAbsolutePath().getParent();
            Path tmp = Files.createTempFile(dir, "." + target.getFileName(), ".tmp");
            Files.writeString(tmp, text, StandardCharsets.UTF_8);
            Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            savedText = text;
            autosave.clear();
            changed.run();
            return true;
        } catch (IOException | RuntimeException e) {
            MessageDialog.openError(shell, "Cannot save", "Cannot write " + target + ":\n" + describe(e)
                    + "\n\nYour text is still in the editor (and in the autosave copy). Try Save As.");
            return false;
        }
    }

    /** True if there is nothing unsaved, or the user saved or chose to discard it. */
    boolean confirmDiscard() {
        if (!dirty()) {
            return true;
        }
        MessageDialog d = new MessageDialog(shell, "Unsaved changes", null,
                name() + " has unsaved changes. Save them?", MessageDialog.QUESTION,
                new String[] {"Save", "Don't Save", "Cancel"}, 0);
        return switch (d.open()) {
            case 0 -> save();
            case 1 -> true;
            default -> false;
        };
    }

    /** Clears the autosave copy (normal exit after the user saved or discarded). */
    void closedNormally() {
        autosave.clear();
    }

    /** Offers the text an earlier session left unsaved; true if it was restored. */
    boolean offerRecovery(boolean ask) {
        Autosave.Recovered r = autosave.find();
        if (r == null) {
            return false;
        }
        String where = r.file() == null ? "an untitled script" : r.file().getFileName().toString();
        if (ask && !MessageDialog.openQuestion(shell, "Recover unsaved work",
                "PARPE did not close normally last time. Recover the unsaved text of " + where + "?")) {
            autosave.clear();
            return false;
        }
        String saved = "";
        if (r.file() != null && Files.isRegularFile(r.file())) {
            try {
                saved = Files.readString(r.file(), StandardCharsets.UTF_8);
            } catch (IOException e) {
                saved = "";
            }
        }
        show(r.file(), r.text(), saved);
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
    void autosaveNow() {
        String text = editor.document().get();
        if (!dirty() || text.equals(autosavedText)) {
            return;
        }
        try {
            autosave.write(file, text);
            autosavedText = text;
        } catch (IOException e) {
            // Keep editing; the next attempt may succeed (disk full, folder removed).
        }
    }

    private static String describe(Exception e) {
        return e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
    }
}
