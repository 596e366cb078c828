package org.parpe.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The source checkout's {@code parpe} launcher inside Slurm jobs (issue 26, items 4 and 5), run
 * with bash in a copy of a checkout whose {@code java} and {@code mvn} are stand-ins on the PATH
 * that record how they were called.
 */
class LauncherTest {
    private static final Path LAUNCHER = Path.of("../parpe");

    @TempDir
    Path dir;
    Path checkout;
    Path jar;

    @BeforeEach
    void copyCheckout() throws Exception {
        checkout = dir.resolve("checkout");
        Files.createDirectories(checkout.resolve("parpe-cli/target"));
        Files.createDirectories(checkout.resolve("parpe-core/src/main/java"));
        Files.copy(LAUNCHER, checkout.resolve("parpe"));
        Files.writeString(checkout.resolve("pom.xml"), "<project/>\n");
        Files.writeString(checkout.resolve("parpe-core/src/main/java/A.java"), "class A {}\n");
        jar = checkout.resolve("parpe-cli/target/parpe.jar");
        Files.writeString(jar, "jar");
        Path bin = Files.createDirectories(dir.resolve("bin"));
        for (String tool : List.of("java", "mvn")) {
            Path f = bin.resolve(tool);
            Files.writeString(f, "#!/bin/sh\necho \"" + tool + " $*\" >>" + dir.resolve("calls") + "\n");
            Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("rwxr-xr-x"));
        }
    }

    private void sourcesNewerThanJar(boolean newer) throws Exception {
        FileTime old = FileTime.fromMillis(System.currentTimeMillis() - 3_600_000);
        FileTime now = FileTime.fromMillis(System.currentTimeMillis());
        Files.setLastModifiedTime(checkout.resolve("pom.xml"), old);
        Files.setLastModifiedTime(checkout.resolve("parpe-core/src/main/java/A.java"), newer ? now : old);
        Files.setLastModifiedTime(jar, newer ? old : now);
    }

    /** Runs {@code parpe sweep} with {@code env} added; returns exit code and standard error. */
    private String[] launch(Map<String, String> env) throws Exception {
        ProcessBuilder pb = new ProcessBuilder("bash", checkout.resolve("parpe").toString(), "sweep", "x.xml")
                .redirectErrorStream(true);
        pb.environment().keySet().removeIf(k -> k.startsWith("SLURM_") || k.startsWith("PARPE"));
        pb.environment().put("PATH", dir.resolve("bin") + ":/usr/bin:/bin");
        pb.environment().putAll(env);
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes());
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        return new String[] {Integer.toString(p.exitValue()), out};
    }

    private String calls() throws Exception {
        Path c = dir.resolve("calls");
        return Files.exists(c) ? Files.readString(c) : "";
    }

    @Test
    void aSlurmJobNeverBuildsAndSaysWhatToDo() throws Exception {
        sourcesNewerThanJar(true);
        String[] r = launch(Map.of("SLURM_JOB_ID", "77", "SLURM_ARRAY_TASK_ID", "3"));
        assertEquals("2", r[0], r[1]);
        assertTrue(r[1].contains("parpe: parpe-cli is not built or older than its sources, and Slurm job 77 does not"
                + " build"), r[1]);
        assertTrue(r[1].contains("./parpe help"), r[1]);
        assertEquals("", calls(), "the launcher ran Maven or Java inside a Slurm job");
        assertEquals("jar", Files.readString(jar));
        // the jar missing altogether: the same refusal
        Files.delete(jar);
        assertEquals("2", launch(Map.of("SLURM_JOB_ID", "77"))[0]);
        assertEquals("", calls());
    }

    @Test
    void outsideSlurmStaleSourcesAreBuilt() throws Exception {
        sourcesNewerThanJar(true);
        launch(Map.of());
        assertTrue(calls().startsWith("mvn "), calls());
    }

    @Test
    void theHeapIsSizedFromTheJobsMemory() throws Exception {
        sourcesNewerThanJar(false);
        launch(Map.of("SLURM_JOB_ID", "5", "SLURM_MEM_PER_NODE", "1000"));
        assertTrue(calls().contains(" -Xmx600m "), calls());
        Files.delete(dir.resolve("calls"));
        launch(Map.of("SLURM_JOB_ID", "5", "SLURM_MEM_PER_CPU", "500", "SLURM_CPUS_ON_NODE", "4"));
        assertTrue(calls().contains(" -Xmx1200m "), calls());
        Files.delete(dir.resolve("calls"));
        launch(Map.of());
        assertTrue(calls().startsWith("java ") && calls().contains(" -jar "), calls());
        assertFalse(calls().contains("-Xmx"), calls());
    }
}
