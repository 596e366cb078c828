package org.parpe.cli.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.parpe.cli.options.UsageException;

/**
 * How an export's folder is written (issue 21, items 13 and 14): a link planted at the name the
 * old code used for its temporary file ({@code NAME.tmp}) redirected the write; a failure while
 * writing the third file left a new header beside old tables. Both failed before.
 */
class ExportFilesTest {
    @TempDir
    Path dir;

    @Test
    void aLinkPlantedAtTheOldTemporaryNameRedirectsNothing() throws Exception {
        Path victim = Files.writeString(dir.resolve("victim.txt"), "precious");
        Path out = Files.createDirectory(dir.resolve("out"));
        Files.createSymbolicLink(out.resolve("program.h.tmp"), victim);
        ExportFiles.write(out, Map.of("program.h", "new header"));
        assertEquals("precious", Files.readString(victim));
        assertEquals("new header", Files.readString(out.resolve("program.h")));
    }

    @Test
    void aFailureWhileWritingLeavesTheWholeOldExport() throws Exception {
        Path out = Files.createDirectory(dir.resolve("out"));
        Files.writeString(out.resolve("program.h"), "old header");
        Files.writeString(out.resolve("program.c"), "old tables");
        Map<String, String> files = new LinkedHashMap<>();
        files.put("program.h", "new header");
        files.put("program.c", "new tables");
        // a name longer than a file system takes (255 bytes at most), refused while the files are written
        files.put("x".repeat(254) + ".c", "more");
        IOException e = assertThrows(IOException.class, () -> ExportFiles.write(out, files));
        assertEquals("its name is 256 bytes long, more than the 255 a file system takes", e.getMessage());
        assertEquals("old header", Files.readString(out.resolve("program.h")));
        assertEquals("old tables", Files.readString(out.resolve("program.c")));
        try (var s = Files.list(out)) {
            assertEquals(List.of("program.c", "program.h"), s.map(p -> p.getFileName().toString()).sorted().toList(),
                    "no temporary file is left");
        }
    }

    @Test
    void aLinkOrFifoAtAnExportedNameIsRefused() throws Exception {
        Path victim = Files.writeString(dir.resolve("victim.txt"), "precious");
        Path out = Files.createDirectory(dir.resolve("out"));
        Files.createSymbolicLink(out.resolve("program.h"), victim);
        UsageException e = assertThrows(UsageException.class, () -> ExportFiles.write(out, Map.of("program.h", "x")));
        assertTrue(e.getMessage().contains("is not a regular file"), e.getMessage());
        assertEquals("precious", Files.readString(victim));
    }
}
