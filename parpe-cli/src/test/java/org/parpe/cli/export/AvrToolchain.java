package org.parpe.cli.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;

/**
 * The real Arduino AVR toolchain of Debian 12 ({@code arduino-core-avr}, {@code gcc-avr},
 * {@code avr-libc}, {@code binutils-avr}) and {@code simavr} ({@code libsimavr-dev}) for the tests
 * that build exported sketches as the Arduino IDE does and run them on a simulated Uno.
 * The compiler flags are those of the core's {@code platform.txt} for {@code arduino:avr:uno}, plus
 * {@code -DDECIMAL_DIG=__DECIMAL_DIG__}, which Debian 12's core needs to compile {@code WString.cpp}.
 *
 * <p>When the tools are missing the tests are skipped with a message on a developer's machine, so
 * that a clone builds and passes; under CI ({@code CI=true}, set by {@code ./test-all}) they fail.
 */
final class AvrToolchain {
    static final Path CORE = Path.of("/usr/share/arduino/hardware/arduino/avr");
    static final Path PROBE_SOURCE = Path.of("src/test/resources/export/simavr/uno_probe.c").toAbsolutePath();
    /** Debian packages that hold the tools (./test-all installs them). */
    static final String PACKAGES = "arduino-core-avr gcc-avr avr-libc binutils-avr simavr libsimavr-dev gcc";

    private static final List<String> FLAGS = List.of("-Os", "-w", "-ffunction-sections", "-fdata-sections", "-flto",
            "-fno-fat-lto-objects", "-mmcu=atmega328p", "-DF_CPU=16000000L", "-DARDUINO=10807", "-DARDUINO_AVR_UNO",
            "-DARDUINO_ARCH_AVR", "-DDECIMAL_DIG=__DECIMAL_DIG__", "-I" + CORE.resolve("cores/arduino"),
            "-I" + CORE.resolve("variants/standard"), "-I" + CORE.resolve("libraries/SoftwareSerial/src"));
    private static final List<String> CPP = List.of("-std=gnu++11", "-fpermissive", "-fno-exceptions",
            "-fno-threadsafe-statics");

    private final Path dir;
    private final Path core;
    private final Path probe;

    private AvrToolchain(Path dir, Path core, Path probe) {
        this.dir = dir;
        this.core = core;
        this.probe = probe;
    }

    /** The tools, with the Arduino core and the probe built in {@code dir}; skips or fails (CI) when they are missing. */
    static AvrToolchain require(Path dir) throws IOException, InterruptedException {
        List<String> missing = new ArrayList<>();
        for (String tool : List.of("avr-gcc", "avr-g++", "avr-gcc-ar", "avr-size", "avr-nm", "gcc")) {
            if (!HostCompiler.installed(tool)) {
                missing.add(tool);
            }
        }
        for (Path p : List.of(CORE.resolve("cores/arduino/Arduino.h"), Path.of("/usr/include/simavr/sim_avr.h"))) {
            if (!Files.exists(p)) {
                missing.add(p.toString());
            }
        }
        if (!missing.isEmpty()) {
            String msg = "the Arduino AVR toolchain or simavr is missing (" + String.join(", ", missing)
                    + "): install it with 'sudo apt-get install " + PACKAGES + "' (./test-all installs it)";
            if ("true".equals(System.getenv("CI"))) {
                fail(msg);
            }
            Assumptions.abort(msg);
        }
        Path core = dir.resolve("core");
        Files.createDirectories(core);
        List<String> objects = new ArrayList<>();
        try (Stream<Path> s = Files.list(CORE.resolve("cores/arduino"))) {
            for (Path src : s.sorted().toList()) {
                String n = src.getFileName().toString();
                List<String> cmd = compiler(n);
                if (cmd != null) {
                    cmd.addAll(List.of(src.toString(), "-o", n + ".o"));
                    check(core, cmd);
                    objects.add(n + ".o");
                }
            }
        }
        List<String> ar = new ArrayList<>(List.of("avr-gcc-ar", "rcs", "core.a"));
        ar.addAll(objects);
        check(core, ar);
        check(dir, List.of("gcc", "-std=c99", "-Wall", "-Werror", "-O2", "-o", "uno_probe", PROBE_SOURCE.toString(),
                "-lsimavr"));
        return new AvrToolchain(dir, core.resolve("core.a"), dir.resolve("uno_probe"));
    }

    /** A built sketch: its ELF, the end of its static data in RAM, and what avr-size measures. */
    record Elf(Path file, int bssEnd, long flash, long staticRam) {
    }

    /**
     * Builds the sketch folder {@code sketch} (NAME.ino and the runtime) for an Uno, as arduino-builder
     * does. No library is linked: an Uno sketch includes none (its bus console is its own, not
     * SoftwareSerial, whose pin-change interrupts it would clash with).
     */
    Elf build(Path sketch) throws IOException, InterruptedException {
        Path obj = Files.createTempDirectory(dir, "obj");
        List<String> objects = new ArrayList<>();
        try (Stream<Path> s = Files.list(sketch)) {
            for (Path src : s.sorted().toList()) {
                String n = src.getFileName().toString();
                List<String> cmd = compiler(n);
                if (cmd != null) {
                    cmd.addAll(List.of("-I" + sketch, src.toString(), "-o", n + ".o"));
                    check(obj, cmd);
                    objects.add(n + ".o");
                }
            }
        }
        List<String> link = new ArrayList<>(List.of("avr-gcc", "-w", "-Os", "-flto", "-fuse-linker-plugin",
                "-Wl,--gc-sections", "-mmcu=atmega328p", "-o", "sketch.elf"));
        link.addAll(objects);
        link.addAll(List.of(core.toString(), "-lm"));
        check(obj, link);
        HostCompiler.Result size = check(obj, List.of("avr-size", "-A", "sketch.elf"));
        long text = section(size.out(), ".text");
        long data = section(size.out(), ".data");
        long bss = section(size.out(), ".bss");
        HostCompiler.Result nm = check(obj, List.of("avr-nm", "sketch.elf"));
        int end = nm.out().lines().filter(l -> l.endsWith(" _end")).mapToInt(l -> Integer.parseInt(l.substring(0, 8), 16) & 0xFFFF)
                .findFirst().orElseThrow();
        return new Elf(obj.resolve("sketch.elf"), end, text + data, data + bss);
    }

    /** Runs {@code elf} for {@code seconds} on the probe; see uno_probe.c for its arguments and lines. */
    List<String> simulate(Elf elf, double seconds, double from, List<String> pins) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of(probe.toString(), elf.file().toString(), String.valueOf(seconds),
                String.valueOf(from), Integer.toHexString(elf.bssEnd())));
        cmd.addAll(pins);
        return check(elf.file().getParent(), cmd).out().lines().toList();
    }

    /** The compiler command for a source of the core or the sketch (by its extension), or {@code null} for another file. */
    private static List<String> compiler(String name) {
        List<String> cmd;
        if (name.endsWith(".c")) {
            cmd = new ArrayList<>(List.of("avr-gcc", "-c", "-std=gnu11"));
        } else if (name.endsWith(".cpp") || name.endsWith(".ino")) {
            cmd = new ArrayList<>(List.of("avr-g++", "-c"));
            cmd.addAll(CPP);
            cmd.addAll(name.endsWith(".ino") ? List.of("-x", "c++") : List.of());
        } else if (name.endsWith(".S")) {
            cmd = new ArrayList<>(List.of("avr-gcc", "-c", "-x", "assembler-with-cpp"));
        } else {
            return null;
        }
        cmd.addAll(FLAGS);
        return cmd;
    }

    private static long section(String sizeA, String name) {
        return sizeA.lines().filter(l -> l.startsWith(name + " ")).mapToLong(l -> Long.parseLong(l.trim().split("\\s+")[1]))
                .findFirst().orElse(0);
    }

    private static HostCompiler.Result check(Path in, List<String> cmd) throws IOException, InterruptedException {
        HostCompiler.Result r = HostCompiler.run(in, cmd, 600);
        assertEquals(0, r.code(), () -> String.join(" ", cmd) + ":\n" + r.err());
        return r;
    }
}
