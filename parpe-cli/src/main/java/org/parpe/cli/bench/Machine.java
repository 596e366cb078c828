package org.parpe.cli.bench;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The machine a run of {@code parpe bench} measured, as {@code machine.*} lines at the head of
 * its figures: the same build runs at less than half the speed on another kind of processor, so
 * a saved run says where its times come from and {@code --compare} can say when two runs'
 * times do not compare.
 */
final class Machine {
    /** The prefix of the machine's lines; {@link BenchResults#compare} reads them back. */
    static final String PREFIX = "machine.";
    static final String CPU = PREFIX + "cpu";
    static final String CORES = PREFIX + "cores";

    private Machine() {
    }

    /** This machine's lines, read now (the load average is the one at the start of the run). */
    static List<String> lines() {
        return lines(cpuInfo(), Runtime.getRuntime().availableProcessors(), System.getProperty("java.vm.name", "?") + " "
                + System.getProperty("java.runtime.version", System.getProperty("java.version", "?")),
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
    }

    /**
     * The lines for a machine whose {@code /proc/cpuinfo} says {@code cpuInfo} (empty where there
     * is none), with {@code cores} processors for this JVM, the Java runtime {@code java} and the
     * one-minute load average {@code load} (negative where the system has none).
     */
    static List<String> lines(String cpuInfo, int cores, String java, double load) {
        List<String> out = new ArrayList<>();
        String model = field(cpuInfo, "model name");
        out.add(CPU + "=" + (model == null ? System.getProperty("os.arch", "?") : model));
        out.add(CORES + "=" + cores);
        String mhz = field(cpuInfo, "cpu MHz");
        if (mhz != null) {
            try {
                out.add(PREFIX + "cpu_mhz=" + Math.round(Double.parseDouble(mhz)));
            } catch (NumberFormatException e) {
                // a field we cannot read is left out rather than guessed
            }
        }
        out.add(PREFIX + "java=" + java);
        if (load >= 0) {
            out.add(String.format(Locale.ROOT, PREFIX + "load_average=%.2f", load));
        }
        return out;
    }

    /** The value of the first {@code name : value} line of {@code cpuInfo}, or null. */
    private static String field(String cpuInfo, String name) {
        for (String line : cpuInfo.split("\n")) {
            int colon = line.indexOf(':');
            if (colon > 0 && line.substring(0, colon).trim().equals(name)) {
                String v = line.substring(colon + 1).trim().replaceAll("\\s+", " ");
                return v.isEmpty() ? null : v;
            }
        }
        return null;
    }

    private static String cpuInfo() {
        try {
            return Files.readString(Path.of("/proc/cpuinfo"), StandardCharsets.UTF_8);
        } catch (IOException | RuntimeException e) {
            return "";
        }
    }
}
