package org.parpe.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.TreeSet;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

/**
 * The repository's spec/PARSL.md and spec/conformance are byte-identical copies of the shared
 * PARSL folder when that folder sits beside the repository (../shared/parsl); a clone without
 * it skips this test and still runs the suite from spec/.
 */
class SpecCopyTest {
    private static final Path SHARED = Conformance.ROOT.resolve("../shared/parsl").normalize();

    @Test
    void specCopyIsByteIdenticalToTheSharedFolder() throws IOException {
        Assumptions.assumeTrue(Files.isDirectory(SHARED),
                "no shared PARSL folder at " + SHARED + " beside the repository: nothing to compare spec/ with");
        Path spec = Conformance.ROOT.resolve("spec");
        assertSame(SHARED.resolve("PARSL.md"), spec.resolve("PARSL.md"));
        Path shared = SHARED.resolve("conformance");
        Path copy = spec.resolve("conformance");
        TreeSet<Path> names = new TreeSet<>(files(shared));
        TreeSet<Path> copied = new TreeSet<>(files(copy));
        List<Path> missing = new ArrayList<>(names);
        missing.removeAll(copied);
        List<Path> extra = new ArrayList<>(copied);
        extra.removeAll(names);
        assertTrue(missing.isEmpty(), "spec/conformance lacks " + missing + " of " + shared);
        assertTrue(extra.isEmpty(), "spec/conformance has " + extra + ", which " + shared + " does not");
        for (Path f : names) {
            assertSame(shared.resolve(f), copy.resolve(f));
        }
    }

    private static void assertSame(Path original, Path copy) throws IOException {
        assertTrue(Files.isRegularFile(copy), copy + " is missing (it should copy " + original + ")");
        byte[] a = Files.readAllBytes(original);
        byte[] b = Files.readAllBytes(copy);
        int at = Arrays.mismatch(a, b);
        assertEquals(-1, at, () -> copy + " differs from " + original + " at byte " + at);
    }

    /** Every regular file under {@code dir}, relative to it. */
    private static List<Path> files(Path dir) throws IOException {
        try (Stream<Path> s = Files.walk(dir)) {
            return s.filter(Files::isRegularFile).map(dir::relativize).toList();
        }
    }
}
