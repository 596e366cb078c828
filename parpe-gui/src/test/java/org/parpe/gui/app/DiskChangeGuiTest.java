package org.parpe.gui.app;

import org.parpe.gui.prefs.Prefs;

import org.parpe.gui.hardware.HardwareDialog;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.List;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Event;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 18 item 4 in the real window: a file that another program (or the Pose panel, before
 * it refused) wrote while it was open was not noticed: the editor was not marked modified,
 * quitting did not ask, and Save silently replaced the other program's text. Each part failed
 * before.
 */
class DiskChangeGuiTest {
    @TempDir
    Path dir;
    private IdeWindow ide;
    private final List<String> asked = new ArrayList<>();
    private final List<Integer> answers = new ArrayList<>();

    @AfterEach
    void closeWindow() {
        if (ide != null && !ide.shell.isDisposed()) {
            ide.shell.dispose();
        }
    }

    private Path openScript() throws Exception {
        Path script = dir.resolve("walk.xml");
        Files.writeString(script, Files.readString(Gui.example("hello-snake.xml")));
        ide = new IdeWindow(Gui.display(), new Prefs(dir.resolve("home")));
        ide.files.answerWith((title, message, buttons) -> {
            asked.add(title + ": " + message);
            return answers.isEmpty() ? -1 : answers.remove(0);
        });
        ide.open(null, false);
        Gui.open(ide, script);
        return script;
    }

    /** Another program writes {@code text} into {@code file} (a later time, as a real write has). */
    private static void writtenElsewhere(Path file, String text) throws Exception {
        FileTime before = Files.getLastModifiedTime(file);
        Files.writeString(file, text);
        Files.setLastModifiedTime(file, FileTime.fromMillis(before.toMillis() + 2000));
    }

    private void activate() {
        ide.shell.notifyListeners(SWT.Activate, new Event());
        Gui.settle();
    }

    @Test
    void keepingTheEditorsTextMarksItUnsavedAndReloadShowsTheFile() throws Exception {
        Path script = openScript();
        String mine = ide.editor.document().get();
        String theirs = mine.replace("period=\"1\"", "period=\"3\"");
        assertFalse(mine.equals(theirs), "the example has a period to change");
        writtenElsewhere(script, theirs);
        answers.add(1); // Keep Editor Text
        activate();
        assertEquals(1, asked.size(), "asked once: " + asked);
        assertTrue(asked.get(0).startsWith("File changed on disk: walk.xml was changed on disk"), asked.get(0));
        assertTrue(ide.files.dirty(), "the editor's text is no longer what is on disk");
        assertEquals(mine, ide.editor.document().get());
        activate();
        assertEquals(1, asked.size(), "the same change is not asked about again");
        writtenElsewhere(script, theirs + "<!-- again -->\n");
        answers.add(0); // Reload
        activate();
        assertEquals(theirs + "<!-- again -->\n", ide.editor.document().get());
        assertFalse(ide.files.dirty());
    }

    @Test
    void saveAsksBeforeReplacingAFileChangedOnDisk() throws Exception {
        Path script = openScript();
        String theirs = ide.editor.document().get() + "<!-- written by another program -->\n";
        writtenElsewhere(script, theirs);
        answers.add(1); // Cancel
        assertFalse(ide.files.save());
        assertEquals(theirs, Files.readString(script), "Cancel keeps the other program's text");
        assertTrue(asked.get(0).startsWith("File changed on disk"), asked.toString());
        answers.add(0); // Replace
        assertTrue(ide.files.save());
        assertEquals(ide.editor.document().get(), Files.readString(script));
        assertEquals(2, asked.size());
        assertTrue(ide.files.save(), "a file saved since is not asked about");
        assertEquals(2, asked.size());
    }

    @Test
    void theHardwareDialogNeverWritesItsProfileOverTheOpenScript() throws Exception {
        Path script = openScript();
        String text = Files.readString(script);
        Path link = Files.createSymbolicLink(dir.resolve("link.xml"), script);
        HardwareDialog d = HardwareDialog.open(ide.hardware);
        try {
            for (Path over : List.of(script, link)) {
                d.saveProfile(over);
                Gui.settle();
                assertTrue(d.widgets().message().getText().contains("it is the script open in the editor"), d.widgets().message().getText());
            }
        } finally {
            d.shell().dispose();
        }
        assertEquals(text, Files.readString(script));
    }
}
