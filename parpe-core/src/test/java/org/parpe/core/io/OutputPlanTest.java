package org.parpe.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The output policy: what {@link OutputPlan} refuses and how {@link AtomicFiles} puts a file in place. */
class OutputPlanTest {
    @TempDir
    Path dir;

    private List<Path> listing() throws IOException {
        try (var s = Files.list(dir)) {
            return s.sorted().toList();
        }
    }

    @Test
    void anOutputNamingAnInputOrAnotherOutputIsRefusedAlsoThroughALinkOrAnotherSpelling() throws Exception {
        Path in = Files.writeString(dir.resolve("in.xml"), "input");
        Path link = Files.createSymbolicLink(dir.resolve("link.xml"), in);
        Path hard = Files.createLink(dir.resolve("hard.xml"), in);
        for (Path p : List.of(in, link, hard, dir.resolve(".").resolve("in.xml"))) {
            OutputException e = assertThrows(OutputException.class, () -> new OutputPlan().input(in).output("--trace", p.toString()));
            assertTrue(e.getMessage().contains("it is the input file"), e.getMessage());
        }
        OutputPlan plan = new OutputPlan().input(in);
        plan.output("--out", dir.resolve("r.csv").toString());
        OutputException twice = assertThrows(OutputException.class,
                () -> plan.output("--plot", dir.resolve("sub/../r.csv").toString()));
        assertEquals("cannot write --plot file '" + dir.resolve("sub/../r.csv") + "': it is also the --out file;"
                + " give the outputs different names", twice.getMessage());
    }

    @Test
    void devicesFifosDanglingLinksAndDirectoriesAreNeverReplacedAndKeepNeedsAChoice() throws Exception {
        Path fifo = dir.resolve("fifo");
        new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor();
        Path dangling = Files.createSymbolicLink(dir.resolve("dangling"), dir.resolve("nowhere"));
        for (String p : List.of("/dev/null", fifo.toString(), dangling.toString(), dir.toString())) {
            assertThrows(OutputException.class, () -> new OutputPlan().output("--out", p));
            assertThrows(OutputException.class, () -> new OutputPlan().output("--out", p, OutputPlan.Existing.REPLACE, null));
        }
        assertThrows(IOException.class, () -> AtomicFiles.write(fifo, "x"));
        assertTrue(Files.isSymbolicLink(dangling));
        Path kept = Files.writeString(dir.resolve("kept.xml"), "mine");
        OutputException e = assertThrows(OutputException.class,
                () -> new OutputPlan().output("--out", kept.toString(), OutputPlan.Existing.KEEP, "add --force"));
        assertTrue(e.getMessage().endsWith("it exists; add --force"), e.getMessage());
        assertEquals("mine", Files.readString(kept));
    }

    @Test
    void aWriteThroughALinkReplacesItsTargetKeepsTheLinkAndThePermissions() throws Exception {
        Path real = Files.writeString(dir.resolve("real.xml"), "old");
        Files.setPosixFilePermissions(real, PosixFilePermissions.fromString("rwxr-x---"));
        Path link = Files.createSymbolicLink(dir.resolve("link.xml"), real);
        AtomicFiles.write(link, "new");
        assertTrue(Files.isSymbolicLink(link));
        assertEquals("new", Files.readString(real));
        assertEquals("rwxr-x---", PosixFilePermissions.toString(Files.getPosixFilePermissions(real)));
        assertEquals(List.of(link, real), listing());
    }

    @Test
    void aPlantedLinkAtATemporaryNameIsNeverFollowedAndAFailureLeavesNothing() throws Exception {
        Path victim = Files.writeString(dir.resolve("victim"), "precious");
        Path target = Files.writeString(dir.resolve("t.csv"), "old");
        // The old export wrote NAME.tmp: a link planted there redirected the write.
        Files.createSymbolicLink(dir.resolve("t.csv.tmp"), victim);
        AtomicFiles.write(target, "new");
        assertEquals("precious", Files.readString(victim));
        assertEquals("new", Files.readString(target));
        IOException full = assertThrows(IOException.class, () -> AtomicFiles.write(target, out -> {
            out.write("half".getBytes());
            throw new IOException("No space left on device");
        }));
        assertEquals("No space left on device", full.getMessage());
        assertEquals("new", Files.readString(target));
        assertEquals(List.of(target, dir.resolve("t.csv.tmp"), victim), listing());
    }

    @Test
    void severalFilesAreReplacedAllOrNone() throws Exception {
        Path h = Files.writeString(dir.resolve("program.h"), "old header");
        Path c = Files.writeString(dir.resolve("program.c"), "old tables");
        Map<Path, Content> files = new LinkedHashMap<>();
        files.put(h, Content.text("new header"));
        files.put(c, out -> {
            throw new IOException("No space left on device");
        });
        assertThrows(IOException.class, () -> AtomicFiles.writeAll(files));
        assertEquals("old header", Files.readString(h));
        assertEquals("old tables", Files.readString(c));
        assertEquals(List.of(c, h), listing());
        files.put(c, Content.text("new tables"));
        AtomicFiles.writeAll(files);
        assertEquals("new header", Files.readString(h));
        assertEquals("new tables", Files.readString(c));
    }

    @Test
    void anOutputStreamThatIsAbortedLeavesTheTargetAndNoTemporaryFile() throws Exception {
        Path t = Files.writeString(dir.resolve("trace.csv"), "old");
        Output o = new OutputPlan().output("--trace", t.toString());
        Output.Stream s = o.open();
        s.write("half");
        s.abort();
        assertEquals("old", Files.readString(t));
        assertEquals(List.of(t), listing());
        Output.Stream again = o.open();
        again.write("new");
        again.close();
        again.abort();
        assertEquals("new", Files.readString(t));
    }

    /** Issue 31 item 5: a 0444 file was silently replaced (by root as by its owner: a rename needs no write permission on the file). */
    @Test
    void aWriteProtectedFileIsRefusedAlsoForRootAndAlsoThroughALink() throws Exception {
        Path t = Files.writeString(dir.resolve("t.csv"), "mine");
        Files.setPosixFilePermissions(t, PosixFilePermissions.fromString("r--r--r--"));
        Path link = Files.createSymbolicLink(dir.resolve("link.csv"), t);
        for (Path p : List.of(t, link)) {
            OutputException e = assertThrows(OutputException.class, () -> new OutputPlan().output("--trace", p.toString()));
            assertEquals("cannot write --trace file '" + p + "': it is write-protected; make it writable (chmod u+w)"
                    + " or choose another name", e.getMessage());
            IOException direct = assertThrows(IOException.class, () -> AtomicFiles.write(p, "new"));
            assertTrue(direct.getMessage().startsWith("it is write-protected"), direct.getMessage());
        }
        assertEquals("mine", Files.readString(t));
        assertEquals(List.of(link, t), listing());
        Files.setPosixFilePermissions(t, PosixFilePermissions.fromString("rw-r--r--"));
        AtomicFiles.write(t, "new");
        assertEquals("new", Files.readString(t));
    }

    /**
     * Issue 31 item 5: another user's file in a writable folder was replaced by one of ours. The
     * writer here is user {@code nobody}, so that the rule is checked whoever runs the test.
     */
    @Test
    void anotherUsersFileIsRefused() throws Exception {
        Path t = Files.writeString(dir.resolve("theirs.csv"), "theirs");
        var nobody = t.getFileSystem().getUserPrincipalLookupService().lookupPrincipalByName("nobody");
        String owner = Files.getOwner(t).getName();
        IOException e = assertThrows(IOException.class, () -> AtomicFiles.checkOwner(t, nobody));
        assertEquals("it belongs to user " + owner + "; replacing it would make it nobody's; choose another name"
                + " or ask " + owner + " to remove it", e.getMessage());
        AtomicFiles.checkOwner(t, Files.getOwner(t));
        AtomicFiles.checkOwner(dir.resolve("new.csv"), nobody);
    }

    /** Issue 31 item 5: names over 233 bytes failed with "File name too long", the temporary name being 22 bytes longer. */
    @Test
    void aNameOfTheLongestLengthIsWrittenItsTemporaryNameShortened() throws Exception {
        for (String name : List.of("a".repeat(251) + ".ino", "\u00e9".repeat(127) + "x")) {
            Path t = dir.resolve(name);
            AtomicFiles.write(t, "sketch");
            assertEquals("sketch", Files.readString(t));
            assertTrue(AtomicFiles.tmpStem(name).getBytes(java.nio.charset.StandardCharsets.UTF_8).length <= 255 - 22);
        }
        assertEquals("short.ino", AtomicFiles.tmpStem("short.ino"));
        assertEquals(2, listing().size());
    }
}
