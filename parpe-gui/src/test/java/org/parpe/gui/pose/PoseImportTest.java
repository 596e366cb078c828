package org.parpe.gui.pose;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.parpe.core.model.Program;
import org.parpe.serial.record.RecordingWriter;

/** A saved recording read back gives the poses, and runs through them at the recorded times. */
class PoseImportTest {
    @Test
    void aSavedRecordingReadsBackAndRunsThroughItsPoses() {
        PoseList l = new PoseList("leg", new int[] {7, 3});
        l.add(new double[] {12.5, -40}, 1);
        l.add(new double[] {-33, 0}, 0.75);
        l.add(new double[] {60, 45.25}, 1.5);
        Program p = ScriptInsertTest.load(RecordingWriter.toParsl(l.toRecording(), "test"));
        PoseList back = PoseImport.read(p, "leg").orElseThrow();
        assertEquals(3, back.size());
        double[] t = RecordingWriter.rowTimes(l.toRecording());
        double reached = 0;
        Traces trace = Traces.run(p, 10);
        for (int i = 0; i < 3; i++) {
            assertArrayEquals(l.get(i).angles(), back.get(i).angles(), 1e-9);
            assertEquals(t[i], back.get(i).interval(), 1e-9);
            reached += t[i];
            double when = Math.round(reached * 100) / 100.0;
            assertEquals(l.get(i).angles()[0], trace.at(7, when), 1e-6, "module 7 at pose " + (i + 1));
            assertEquals(l.get(i).angles()[1], trace.at(3, when), 1e-6, "module 3 at pose " + (i + 1));
        }
        assertTrue(PoseImport.read(p, "other").isEmpty());
    }
}
