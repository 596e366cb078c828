package org.parpe.gui.diagram;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.eclipse.jface.text.ITextOperationTarget;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Point;
import org.junit.jupiter.api.Test;
import org.parpe.gui.app.IdeAccess;
import org.parpe.gui.app.IdeWindow;
import org.parpe.gui.diagram.Projection.View;

/**
 * The workbench of free nodes with real widgets (issue 24, item 1: node positions live beside
 * the script, not inside it): a behavior {@code <main>} does not run is dragged on the program
 * view's workbench; the place is in {@code SCRIPT.layout} beside the script, whose bytes never
 * change; after Save, closing the IDE and opening the script in a new one the node is where it
 * was put. A foreign file of the layout's name is never written over; an untitled document
 * keeps its places in memory and writes them beside the file Save As chooses; dropping a free
 * node on the lane (or an automaton on a bar) is an edit of the text that one Undo takes back.
 */
class DiagramWorkbenchGuiTest {
    /** One behavior run by {@code <main>}, one (idle) not run, and an automaton (spare) no behavior plays. */
    static final String SCRIPT = """
            <program>
              <robot><structure><legs elements="0..3"/><front elements="0, 1"/><back elements="2, 3"/></structure></robot>
              <main>
                <walk/>
              </main>
              <behaviors>
                <walk>
                  <wave group="legs"/>
                </walk>
                <idle><rest group="front"/><rest group="back"/></idle>
              </behaviors>
              <automata>
                <wave states="up, down"/>
                <rest states="down"/>
                <spare states="up, down" times="2, 2"/>
              </automata>
              <states><up angles="30"/><down angles="-30"/></states>
            </program>
            """;

    private static IdeWindow open(Path home, Path script) {
        IdeWindow ide = IdeAccess.openIde(home);
        IdeAccess.shell(ide).setSize(1366, 768);
        IdeAccess.open(ide, script);
        DiagramDriver d = new DiagramDriver(ide);
        d.front();
        d.show(View.PROGRAM, null);
        return ide;
    }

    /** Drags free node {@code name} by {@code dx, dy} canvas pixels with the left button. */
    private static void dragFree(DiagramDriver d, String name, int dx, int dy) {
        Point a = d.pane().workbench().where(name);
        assertNotNull(a, name + " is no free node of the " + d.pane().shown().view() + " view");
        dragTo(d, a, new Point(a.x + dx, a.y + dy));
    }

    private static void dragTo(DiagramDriver d, Point a, Point b) {
        d.mouse(SWT.MouseDown, a);
        d.mouse(SWT.MouseMove, new Point((a.x + b.x) / 2, (a.y + b.y) / 2));
        d.mouse(SWT.MouseMove, b);
        d.mouse(SWT.MouseUp, b);
    }

    /** Waits until free node {@code name} is drawn away from {@code before}, and returns where. */
    private static double[] movedFrom(DiagramDriver d, String name, double[] before) {
        IdeAccess.pump(() -> {
            double[] now = d.pane().workbench().at(name);
            return now != null && (now[0] != before[0] || now[1] != before[1]);
        }, name + " drawn where it was put");
        return d.pane().workbench().at(name);
    }

    @Test
    void aFreeNodeStaysWhereItWasPutAfterSaveCloseAndReopenAndTheScriptsBytesDoNotChange() throws Exception {
        Path home = Files.createTempDirectory("parpe-workbench-test");
        Path script = Files.createDirectories(home.resolve("scripts")).resolve("bench.xml");
        Files.writeString(script, SCRIPT);
        byte[] bytes = Files.readAllBytes(script);
        Path layout = script.resolveSibling("bench.xml.layout");
        IdeWindow ide = open(home, script);
        double[] put;
        try {
            DiagramDriver d = new DiagramDriver(ide);
            double[] before = d.pane().workbench().at("idle");
            assertNotNull(before, "idle, which <main> does not run, is a free node of the program view");
            assertNull(d.pane().workbench().at("walk"), "walk is on the lane, not on the workbench");
            assertFalse(Files.exists(layout), "nothing is written before a node is moved");
            dragFree(d, "idle", 300, 40);
            put = movedFrom(d, "idle", before);
            assertTrue(Files.isRegularFile(layout), "the place is written beside the script at once");
            String kept = Files.readString(layout);
            assertTrue(kept.startsWith("parpe-layout 1\n") && kept.contains("program idle "), kept);
            assertEquals(SCRIPT, d.text(), "moving a free node changes no text (there is nothing to undo)");
            assertFalse(IdeAccess.files(ide).dirty());
            assertTrue(IdeAccess.files(ide).save());
            DiagramWindow.picture(ide, "diagram-workbench.png");
        } finally {
            IdeAccess.closeIde(ide);
        }
        assertArrayEquals(bytes, Files.readAllBytes(script), "the script's bytes are unchanged");
        IdeWindow again = open(home, script);
        try {
            DiagramDriver d = new DiagramDriver(again);
            assertArrayEquals(put, d.pane().workbench().at("idle"), "reopened, idle is where it was put");
        } finally {
            IdeAccess.closeIde(again);
        }
        assertArrayEquals(bytes, Files.readAllBytes(script));
    }

    @Test
    void aForeignFileOfTheLayoutsNameIsLeftAsItIsAndSaidOnce() throws Exception {
        Path home = Files.createTempDirectory("parpe-workbench-test");
        Path script = Files.createDirectories(home.resolve("scripts")).resolve("bench.xml");
        Files.writeString(script, SCRIPT);
        Path foreign = script.resolveSibling("bench.xml.layout");
        String theirs = "<layout engine=\"another tool\"><pane x=\"3\"/></layout>\n";
        Files.writeString(foreign, theirs);
        IdeWindow ide = open(home, script);
        try {
            DiagramDriver d = new DiagramDriver(ide);
            // the script's validation says "No problems" when it ends: after that, the status bar is the pane's
            IdeAccess.pump(() -> IdeAccess.status(ide).equals("No problems"), "the script validated");
            double[] before = d.pane().workbench().at("idle");
            dragFree(d, "idle", 200, 30);
            double[] put = movedFrom(d, "idle", before);
            String said = IdeAccess.status(ide);
            assertTrue(said.contains("bench.xml.layout is not a PARPE layout file"), said);
            IdeAccess.statusBar(ide).setMessage("");
            dragFree(d, "idle", -100, 20);
            movedFrom(d, "idle", put);
            assertFalse(IdeAccess.status(ide).contains("not a PARPE layout file"), "said once: " + IdeAccess.status(ide));
            put = d.pane().workbench().at("idle");
            assertArrayEquals(put, new double[] {d.pane().places().at(FreeNodes.PROGRAM, "idle")[0],
                    d.pane().places().at(FreeNodes.PROGRAM, "idle")[1]}, "the place is kept in memory");
            assertEquals(theirs, Files.readString(foreign), "the foreign file is not written over");
        } finally {
            IdeAccess.closeIde(ide);
        }
    }

    @Test
    void anUntitledDocumentKeepsPlacesInMemoryAndSaveAsWritesThemBesideTheNewFile() throws Exception {
        Path home = Files.createTempDirectory("parpe-workbench-test");
        Path folder = Files.createDirectories(home.resolve("scripts"));
        IdeWindow ide = IdeAccess.openIde(home);
        IdeAccess.shell(ide).setSize(1366, 768);
        try {
            IdeAccess.dontSave(ide);
            IdeAccess.files(ide).newFile();
            IdeAccess.editor(ide).document().set(SCRIPT);
            DiagramDriver d = new DiagramDriver(ide);
            d.front();
            d.show(View.PROGRAM, null);
            IdeAccess.pump(() -> d.pane().workbench().at("idle") != null, "the workbench of the untitled script");
            double[] before = d.pane().workbench().at("idle");
            dragFree(d, "idle", 250, 50);
            double[] put = movedFrom(d, "idle", before);
            try (var files = Files.list(folder)) {
                assertEquals(0, files.count(), "an untitled document writes nothing");
            }
            Path target = folder.resolve("new.xml");
            IdeAccess.files(ide).chooseSaveTargetWith((dir, name) -> target);
            assertTrue(IdeAccess.files(ide).saveAs());
            assertEquals(SCRIPT, Files.readString(target));
            String kept = Files.readString(folder.resolve("new.xml.layout"));
            assertTrue(kept.contains("program idle "), kept);
            assertArrayEquals(put, new double[] {Double.parseDouble(kept.split("\n")[1].split(" ")[2]),
                    Double.parseDouble(kept.split("\n")[1].split(" ")[3])}, 0.051, kept);
        } finally {
            IdeAccess.closeIde(ide);
        }
    }

    @Test
    void droppedOnTheLaneAFreeBehaviorIsRunFromMainAndDroppedOnABarAFreeAutomatonIsPlayed() throws Exception {
        Path home = Files.createTempDirectory("parpe-workbench-test");
        Path script = Files.createDirectories(home.resolve("scripts")).resolve("bench.xml");
        Files.writeString(script, SCRIPT);
        IdeWindow ide = open(home, script);
        try {
            DiagramDriver d = new DiagramDriver(ide);
            dragTo(d, d.pane().workbench().where("idle"), d.pane().where(d.node("<walk/>")));
            d.caughtUp();
            assertEquals(SCRIPT.replace("    <walk/>\n", "    <walk/>\n    <idle/>\n"), d.text());
            assertNull(d.pane().workbench().at("idle"), "idle now runs from <main>: it is on the lane");
            IdeAccess.editor(ide).run(ITextOperationTarget.UNDO);
            assertEquals(SCRIPT, d.text(), "one Undo takes the drop back");
            d.caughtUp();

            d.show(View.LANES, "walk");
            assertNotNull(d.pane().workbench().where("spare"), "spare, which no behavior plays, is a free node of the lanes");
            dragTo(d, d.pane().workbench().where("spare"), d.pane().where(d.node("<wave group")));
            d.caughtUp();
            assertEquals(SCRIPT.replace("      <wave group=\"legs\"/>\n",
                    "      <wave group=\"legs\"/>\n      <spare group=\"legs\"/>\n"), d.text());
            IdeAccess.editor(ide).run(ITextOperationTarget.UNDO);
            assertEquals(SCRIPT, d.text());
        } finally {
            IdeAccess.closeIde(ide);
        }
    }
}
