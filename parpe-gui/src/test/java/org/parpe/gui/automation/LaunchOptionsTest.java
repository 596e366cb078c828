package org.parpe.gui.automation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Issue 19, item 10: {@code parpe gui}'s options are parsed by picocli, like the command line's:
 * every option of docs/cli.md ("gui") and docs/ide.md, both spellings of a value, and a bad
 * option is one line and exit code 2 without a stack trace.
 */
class LaunchOptionsTest {
    private static String error(String... args) {
        return assertThrows(IllegalArgumentException.class, () -> LaunchOptions.parse(List.of(args))).getMessage();
    }

    @Test
    void everyDocumentedOptionIsRead() {
        LaunchOptions o = LaunchOptions.parse(List.of("lesson.xml", "--run-for", "2.5", "--screenshot", "w.png",
                "--exit", "--pose-panel", "--grid", "travel"));
        assertEquals(Path.of("lesson.xml"), o.file());
        assertEquals(2.5, o.runFor());
        assertEquals(Path.of("w.png"), o.screenshot());
        assertTrue(o.exit() && o.posePanel() && o.automated() && !o.bench() && !o.help());
        assertEquals("travel", o.grid());
        LaunchOptions none = LaunchOptions.parse(List.of());
        assertNull(none.file());
        assertFalse(none.automated());
        assertTrue(LaunchOptions.parse(List.of("--bench")).bench());
        assertTrue(LaunchOptions.parse(List.of("-h")).help());
        for (String option : List.of("FILE", "--run-for", "--screenshot", "--exit", "--pose-panel", "--grid", "--bench",
                "--help")) {
            assertTrue(LaunchOptions.usage().contains(option), option + " in\n" + LaunchOptions.usage());
        }
    }

    /** Fails on the hand-written parser: it knew neither {@code --option=value} nor an option where a value belongs. */
    @Test
    void valuesMayFollowAnEqualsSignAndAnOptionIsNoValue() {
        LaunchOptions o = LaunchOptions.parse(List.of("--run-for=3", "--grid=t", "a.xml"));
        assertEquals(3.0, o.runFor());
        assertEquals("t", o.grid());
        assertEquals("Expected parameter for option '--screenshot' but found '--exit'",
                error("a.xml", "--screenshot", "--exit"));
    }

    @Test
    void badArgumentsAreOneClearLine() {
        assertEquals("Unknown option: '--frobnicate'", error("--frobnicate"));
        assertEquals("--run-for must be a number of seconds >= 0, got 'soon'", error("--run-for", "soon"));
        assertEquals("--run-for must be a number of seconds >= 0, got '-1'", error("--run-for=-1"));
        assertEquals("only one FILE may be given, got 'a.xml' and 'b.xml'", error("a.xml", "b.xml"));
    }

    @Test
    void aBadOptionExitsWithTwoAndNoStackTrace() {
        PrintStream saved = System.err;
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code;
        try {
            System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
            code = org.parpe.gui.Main.run(new String[] {"gui", "--run-for"});
        } finally {
            System.setErr(saved);
        }
        String text = err.toString(StandardCharsets.UTF_8);
        assertEquals(2, code);
        assertTrue(text.startsWith("parpe gui: error: Missing required parameter for option '--run-for' (S)\n"), text);
        assertTrue(text.contains("Usage: parpe gui"), text);
        assertFalse(text.contains("Exception") || text.contains("\tat "), text);
    }

    /** Issue 31 item 5: {@code parpe gui DIR} said "no such file" for a folder that exists. */
    @Test
    void aFolderIsCalledAFolder(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir) {
        PrintStream saved = System.err;
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code;
        try {
            System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
            code = org.parpe.gui.Main.run(new String[] {"gui", dir.toString()});
        } finally {
            System.setErr(saved);
        }
        assertEquals(2, code);
        assertEquals("parpe gui: error: cannot read " + dir + ": it is a directory\n", err.toString(StandardCharsets.UTF_8));
    }
}
