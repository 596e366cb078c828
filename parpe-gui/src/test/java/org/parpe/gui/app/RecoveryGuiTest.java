package org.parpe.gui.app;

import org.parpe.gui.prefs.Prefs;

import org.parpe.gui.files.Autosave;
import org.parpe.gui.files.FileActions;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Recovery in the real window: a copy left by an IDE that is gone is offered, recovered as
 * unsaved text, survives "Don't Save" on closing, and is deleted once the text is saved.
 */
class RecoveryGuiTest {
    @TempDir
    Path dir;
    private IdeWindow ide;
    private final List<String> asked = new ArrayList<>();
    private final List<String> messages = new ArrayList<>();

    @AfterEach
    void closeWindow() {
        if (ide != null && !ide.shell.isDisposed()) {
            ide.shell.dispose();
        }
    }

    /** Opens an IDE on {@code home} whose questions are answered in turn by {@code answers}. */
    private IdeWindow open(Path home, int... answers) {
        IdeWindow w = new IdeWindow(Gui.display(), new Prefs(home));
        int[] next = {0};
        w.files.answerWith((title, message, buttons) -> {
            asked.add(title);
            messages.add(message);
            return next[0] < answers.length ? answers[next[0]++] : 2;
        });
        w.open(null, false);
        return w;
    }

    private static List<String> orphanTexts(Path home) {
        try (Autosave probe = new Autosave(home)) {
            return probe.orphans().stream().map(Autosave.Copy::text).toList();
        }
    }

    @Test
    void recoveredTextSurvivesDontSaveAndGoesOnlyWhenSaved() throws Exception {
        Path home = dir.resolve("home");
        Path script = dir.resolve("walk.xml");
        String original = Files.readString(Gui.example("hello-snake.xml"));
        Files.writeString(script, original);
        String unsaved = original.replace("period=\"1\"", "period=\"2\"");
        Autosave crashed = new Autosave(home);
        crashed.write(Autosave.slotFor(script), script, unsaved);
        crashed.close();

        ide = open(home, 0, 1); // Recover; then "Don't Save" when closing
        assertEquals("Recover unsaved work", asked.get(0));
        assertEquals(unsaved, ide.editor.document().get());
        assertEquals(script.toAbsolutePath().normalize(), ide.files.file());
        assertTrue(ide.files.dirty(), "recovered text must be unsaved");
        assertTrue(ide.shell.getText().startsWith("*"), "title should mark unsaved text: " + ide.shell.getText());
        assertTrue(ide.closeRequested(), "Don't Save should let the window close");
        ide.shell.dispose();
        assertEquals(List.of(unsaved), orphanTexts(home), "Don't Save after recovering deleted the recovered copy");
        assertEquals(original, Files.readString(script));

        asked.clear();
        ide = open(home, 0); // Recover again, then save
        assertEquals(unsaved, ide.editor.document().get());
        assertTrue(ide.files.save());
        assertEquals(unsaved, Files.readString(script));
        assertFalse(ide.files.dirty());
        assertEquals(List.of(), ide.files.autosave().own(), "the saved text's copy is still there");
        ide.shell.dispose();
        assertEquals(List.of(), orphanTexts(home));
    }

    @Test
    void discardDeletesTheCopyAndNotNowKeepsIt() throws Exception {
        Path home = dir.resolve("home2");
        Autosave crashed = new Autosave(home);
        crashed.write(crashed.untitledSlot(), null, "<program/>");
        crashed.close();

        ide = open(home, 2); // Not Now
        assertEquals(FileActions.template(), ide.editor.document().get());
        ide.shell.dispose();
        assertEquals(List.of("<program/>"), orphanTexts(home));

        ide = open(home, 1); // Discard
        ide.shell.dispose();
        assertEquals(List.of(), orphanTexts(home));
    }

    // Issue 23, item 8.

    @Test
    void aLessonCopyIsOfferedAndRecoveredByItsName() throws Exception {
        Path home = dir.resolve("home3");
        Path lesson = Gui.example("tutorial/02-gait-table-snake.xml");
        Autosave crashed = new Autosave(home);
        crashed.write(crashed.untitledSlot(), null, lesson, "<program/>");
        crashed.close();
        ide = open(home, 0); // Recover
        assertTrue(messages.get(0).contains("your copy of the example 02-gait-table-snake.xml"), messages.get(0));
        assertEquals("02-gait-table-snake.xml (example copy)", ide.files.name(), "not *untitled.xml");
        assertTrue(ide.shell.getText().startsWith("*02-gait-table-snake.xml"), ide.shell.getText());
    }

    @Test
    void textDiscardedWithDontSaveIsNotCopiedAgainWhileAnotherQuestionIsOpen() throws Exception {
        Path home = dir.resolve("home4");
        Path script = dir.resolve("mine.xml");
        Files.writeString(script, Files.readString(Gui.example("hello-snake.xml")));
        ide = open(home, 1); // "Don't Save"
        Gui.open(ide, script);
        ide.editor.document().set(ide.editor.document().get() + "\n<!-- edited -->\n");
        ide.files.autosaveNow();
        assertEquals(1, ide.files.autosave().own().size());
        assertTrue(ide.files.confirmDiscard());
        // The autosave timer fires while, say, the Pose panel asks about its poses before quitting.
        ide.files.autosaveNow();
        assertEquals(List.of(), ide.files.autosave().own(), "the discarded text was copied again");
        ide.shell.dispose();
        assertEquals(List.of(), orphanTexts(home), "the discarded text is offered at the next start");
    }

    @Test
    void aDocumentUndoneBackToItsSavedTextLeavesNoCopy() throws Exception {
        Path home = dir.resolve("home5");
        Path script = dir.resolve("undo.xml");
        String original = Files.readString(Gui.example("hello-snake.xml"));
        Files.writeString(script, original);
        ide = open(home);
        Gui.open(ide, script);
        ide.editor.document().set(original + "\n<!-- edited -->\n");
        ide.files.autosaveNow();
        assertEquals(1, ide.files.autosave().own().size());
        ide.editor.document().set(original);
        ide.files.autosaveNow();
        assertEquals(List.of(), ide.files.autosave().own(), "a clean document's copy would be offered after a crash");
    }
}
