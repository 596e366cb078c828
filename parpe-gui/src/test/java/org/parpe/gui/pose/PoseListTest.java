package org.parpe.gui.pose;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.parpe.serial.record.PoseRecording;

class PoseListTest {
    private static PoseList three() {
        PoseList l = new PoseList("leg", new int[] {4, 5});
        l.add(new double[] {10, 20}, 1);
        l.add(new double[] {30, 40}, 0.5);
        l.add(new double[] {-50, 60}, 2);
        return l;
    }

    @Test
    void reorderDuplicateDeleteAndRetimeKeepTheOtherPoses() {
        PoseList l = three();
        assertEquals(0, l.move(1, -1));
        assertArrayEquals(new double[] {30, 40}, l.get(0).angles());
        assertArrayEquals(new double[] {10, 20}, l.get(1).angles());
        assertEquals(0, l.move(0, -1), "the first pose cannot move up");
        assertEquals(3, l.duplicate(2));
        assertEquals(4, l.size());
        assertArrayEquals(l.get(2).angles(), l.get(3).angles());
        assertEquals(2.0, l.get(3).interval());
        l.remove(0);
        assertArrayEquals(new double[] {10, 20}, l.get(0).angles());
        l.retime(1, 0.25);
        assertEquals(0.25, l.get(1).interval());
        assertEquals(0.25 + 2, l.duration(), 1e-12);
    }

    @Test
    void mirrorSwapsPartnersOrNegatesAGroupWithoutThem() {
        PoseList pair = new PoseList("front", new int[] {0, 1, 14, 15});
        pair.add(new double[] {-25, 20, 5, -60}, 1);
        pair.mirror(0, new int[] {2, 3, 0, 1}, false);
        assertArrayEquals(new double[] {5, -60, -25, 20}, pair.get(0).angles());
        PoseList leg = three();
        leg.mirror(2, new int[] {0, 1}, true);
        assertArrayEquals(new double[] {50, -60}, leg.get(2).angles());
    }

    @Test
    void badAnglesAndTimesAreRefusedWithTheValue() {
        PoseList l = three();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> l.add(new double[] {91, 0}, 1));
        assertTrue(e.getMessage().contains("91"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> l.retime(0, 0));
        assertTrue(e.getMessage().contains("got 0"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> l.add(new double[] {1}, 1));
        assertEquals(3, l.size(), "refused edits change nothing");
        assertEquals(0.5, PoseList.parseInterval(" 0.5 s"));
        assertNull(PoseList.parseInterval("abc"));
        assertNull(PoseList.parseInterval("0"));
    }

    @Test
    void theRecordingHasThePosesInOrder() {
        PoseRecording r = three().toRecording();
        assertEquals("leg", r.group());
        assertArrayEquals(new int[] {4, 5}, r.modules());
        assertEquals(3, r.size());
        assertArrayEquals(new double[] {-50, 60}, r.pose(2));
        assertEquals(0.5, r.interval(1));
    }
}
