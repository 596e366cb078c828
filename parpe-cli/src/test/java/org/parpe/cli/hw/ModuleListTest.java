package org.parpe.cli.hw;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.parpe.cli.options.UsageException;

class ModuleListTest {

    @Test
    void rangesListsAndDescendingRanges() throws Exception {
        assertArrayEquals(new int[] {0, 1, 2, 3}, ModuleList.parse("0..3", "--modules"));
        assertArrayEquals(new int[] {4, 2, 3}, ModuleList.parse(" 4, 2 ,3", "--modules"));
        assertArrayEquals(new int[] {3, 2, 1, 8, 9}, ModuleList.parse("3..1, 8..9", "--modules"));
    }

    @Test
    void badListsNameTheOptionAndTheValue() {
        UsageException e = assertThrows(UsageException.class, () -> ModuleList.parse("0..", "--modules"));
        assertTrue(e.getMessage().contains("--modules expects module IDs or ranges like 0..7, got '0..'"), e.getMessage());
        e = assertThrows(UsageException.class, () -> ModuleList.parse("1,1", "--modules"));
        assertTrue(e.getMessage().contains("module 1 is listed twice"), e.getMessage());
        e = assertThrows(UsageException.class, () -> ModuleList.parse("255", "--modules"));
        assertTrue(e.getMessage().contains("module ID must be in 0..254"), e.getMessage());
        assertThrows(UsageException.class, () -> ModuleList.parse("", "--modules"));
        assertThrows(UsageException.class, () -> ModuleList.parse("-1", "--modules"));
    }

    @Test
    void formatIsCompact() {
        assertEquals("0..3, 7, 9, 10", ModuleList.format(new int[] {3, 2, 1, 0, 9, 7, 10}));
        assertEquals("5", ModuleList.format(new int[] {5}));
    }
}
