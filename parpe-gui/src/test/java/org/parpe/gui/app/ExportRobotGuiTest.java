package org.parpe.gui.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.parpe.gui.files.ExportRobotDialog;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * Issue 34, item 1: File → Export in the IDE. The open hello-snake lesson's robot (the 3D view's
 * "auto" choice) exported as MJCF is a file in the chosen folder that parses as XML with a joint
 * per module named m0, m1, …; a folder that is a file is refused with a clear message and nothing
 * is written. Real widgets under Xvfb.
 */
class ExportRobotGuiTest {
    private IdeWindow ide;

    @AfterEach
    void close() {
        Gui.closeIde(ide);
    }

    @Test
    void theOpenLessonsRobotIsExportedAsMjcf() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-export-home"));
        Gui.open(ide, Gui.example("tutorial/03-hello-snake.xml"));
        Gui.pump(() -> ide.program() != null, "the lesson to load");
        Path out = Files.createTempDirectory("parpe-export").resolve("mjcf");
        ExportRobotDialog d = ide.menus.openExportRobot();
        assertEquals("auto", d.robot().robot(), "the dialog starts on the script's robot choice");
        d.setTarget("mjcf");
        d.setFolder(out);
        d.export();
        Gui.pump(() -> !d.busy(), "the export");
        Path mjcf = out.resolve("snake.xml");
        assertTrue(Files.isRegularFile(mjcf), d.message());
        assertTrue(d.message().startsWith("Wrote snake.xml to " + out + " (snake: 14 links, 7 servo joints, 0 loops)"), d.message());
        Document doc = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(mjcf.toFile());
        assertEquals("mujoco", doc.getDocumentElement().getTagName());
        NodeList joints = doc.getElementsByTagName("joint");
        List<String> names = new ArrayList<>();
        for (int i = 0; i < joints.getLength(); i++) {
            names.add(((Element) joints.item(i)).getAttribute("name"));
        }
        // The lesson drives modules 0, 2, 4 and 6 of the simulator's 7-module snake (its comment).
        for (int id = 0; id <= 6; id++) {
            assertTrue(names.contains("m" + id), "joint m" + id + " in " + names);
        }
    }

    /**
     * A file of the export's name in the folder is the user's (an earlier export, perhaps edited
     * since): the IDE asks before it replaces it, keeps it on Cancel and replaces it, whole, on Replace.
     */
    @Test
    void aFileOfTheSameNameIsReplacedOnlyAfterAsking() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-export-home"));
        Gui.open(ide, Gui.example("tutorial/03-hello-snake.xml"));
        Gui.pump(() -> ide.program() != null, "the lesson to load");
        Path out = Files.createTempDirectory("parpe-export");
        Path mine = Files.writeString(out.resolve("snake.xml"), "<mujoco model=\"edited by hand\"/>");
        ExportRobotDialog d = ide.menus.openExportRobot();
        d.setTarget("mjcf");
        d.setFolder(out);
        List<String> asked = new ArrayList<>();
        d.answerWith((title, message, buttons) -> {
            asked.add(message + " " + String.join("/", buttons));
            return 1;
        });
        d.export();
        Gui.pump(() -> !d.busy(), "the export");
        assertEquals(1, asked.size(), "asked once before replacing: " + asked);
        assertTrue(asked.get(0).startsWith("The folder " + out + " already has snake.xml.") && asked.get(0).endsWith("Replace/Cancel"),
                asked.get(0));
        assertEquals("<mujoco model=\"edited by hand\"/>", Files.readString(mine), "Cancel keeps the user's file");
        assertEquals("Nothing written: " + mine + " is kept", d.message());
        try (var list = Files.list(out)) {
            assertEquals(List.of(mine), list.toList(), "nothing else written beside it");
        }
        d.answerWith((title, message, buttons) -> 0);
        d.export();
        Gui.pump(() -> !d.busy(), "the export");
        assertTrue(d.message().startsWith("Wrote snake.xml to " + out), d.message());
        assertTrue(Files.readString(mine).contains("<joint name=\"m6\""), "Replace writes the export in its place");
    }

    @Test
    void aFolderThatIsAFileIsRefusedAndNothingIsWritten() throws Exception {
        ide = Gui.openIde(Files.createTempDirectory("parpe-export-home"));
        Gui.open(ide, Gui.example("tutorial/03-hello-snake.xml"));
        Gui.pump(() -> ide.program() != null, "the lesson to load");
        Path parent = Files.createTempDirectory("parpe-export");
        Path file = Files.writeString(parent.resolve("notes.txt"), "mine");
        ExportRobotDialog d = ide.menus.openExportRobot();
        d.setFolder(file);
        d.export();
        Gui.pump(() -> !d.busy(), "the export");
        assertEquals("Nothing written: '" + file + "' is a file, not a folder", d.message());
        assertEquals("mine", Files.readString(file), "the file in the folder's place is untouched");
        try (var list = Files.list(parent)) {
            assertEquals(List.of(file), list.toList(), "nothing else written beside it");
        }
    }
}
