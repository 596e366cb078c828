package org.parpe.cli.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.parpe.cli.Cli;

/**
 * The proof of equality of issue 13: for every conformance case (the shared suite and PARPE's
 * own), every example and tutorial script, and scripts that fail at run time, the interpreter
 * runs in-process, the script is exported with {@code --target c}, compiled with gcc
 * ({@code -std=c99 -Wall -Werror -O2}), and run; its trace must equal the interpreter's byte for
 * byte but for the stated maths bound ({@link #assertTracesMatch}), with the same exit code (3 at the same
 * tick for a run-time error, with the same diagnostic) and
 * the same warnings of overlapping instances. Cases whose expected result is a load error: export
 * refuses with the diagnostics of {@code check}. (About a second per case, mostly gcc's.)
 */
class ExportEqualityTest {
    static final Path ROOT = Path.of("..").toAbsolutePath().normalize();

    @TempDir
    Path tmp;

    /**
     * One script to compare.
     *
     * @param name     for the report
     * @param script   the script
     * @param runArgs  the arguments of {@code run} after the script (without {@code --trace})
     * @param check    whether the expected result is a load error
     */
    record Case(String name, Path script, List<String> runArgs, boolean check) {
        @Override
        public String toString() {
            return name;
        }
    }

    @BeforeAll
    static void compilerInstalled() {
        HostCompiler.require("gcc");
    }

    static List<Case> cases() throws IOException {
        List<Case> out = new ArrayList<>();
        for (String suite : List.of("spec/conformance/cases", "spec/conformance-parpe/cases")) {
            try (Stream<Path> s = Files.list(ROOT.resolve(suite))) {
                for (Path dir : s.sorted().toList()) {
                    List<String> args = Arrays.asList(Files.readString(dir.resolve("cmd")).trim().split("\\s+"));
                    boolean check = args.get(0).equals("check");
                    if (!check && docks(dir.resolve(args.get(0)))) {
                        continue; // plate actions are refused by the export (aDockingExampleIsRefusedAtItsStates)
                    }
                    List<String> rest = new ArrayList<>();
                    for (int i = 1; i < args.size(); i++) {
                        String a = args.get(i);
                        rest.add(a);
                        if (a.equals("--stimulus")) {
                            rest.add(dir.resolve(args.get(++i)).toString());
                        }
                    }
                    out.add(new Case(dir.getFileName().toString(), dir.resolve("program.xml"), rest, check));
                }
            }
        }
        for (String folder : List.of("examples", "examples/tutorial")) {
            try (Stream<Path> s = Files.list(ROOT.resolve(folder))) {
                for (Path f : s.filter(p -> p.toString().endsWith(".xml") && !docks(p)).sorted().toList()) {
                    List<String> args = new ArrayList<>(List.of("--duration", "10"));
                    Path stim = f.resolveSibling(f.getFileName().toString().replace(".xml", ".stim"));
                    if (Files.exists(stim)) {
                        args.addAll(List.of("--stimulus", stim.toString()));
                    }
                    out.add(new Case(folder + "/" + f.getFileName(), f, args, false));
                }
            }
        }
        for (String n : List.of("functions", "divide-by-zero", "negative-duration", "period-zero", "huge-angles", "total-zero",
                "pow-huge", "exp-huge", "transitions", "kept-values", "kept-divide-by-zero", "fast-functions", "fast-hidden")) {
            out.add(new Case(n, Path.of("src/test/resources/export/" + n + ".xml").toAbsolutePath(),
                    List.of("--duration", "3", "--seed", "7"), false));
        }
        return out;
    }

    /**
     * Whether an example arms or releases connection plates (PARSL 1.1 §14): the export refuses
     * those ({@link #aDockingExampleIsRefusedAtItsStates}), so they have no C trace to compare.
     */
    static boolean docks(Path script) {
        org.parpe.core.load.LoadResult r = org.parpe.core.load.ScriptLoader.load(script, java.util.Map.of());
        return r.program() != null && r.program().automata().stream()
                .anyMatch(a -> a.states().stream().anyMatch(org.parpe.core.model.StateDef::hasPlateActions));
    }

    @org.junit.jupiter.api.Test
    void aDockingExampleIsRefusedAtItsStates(@org.junit.jupiter.api.io.TempDir Path out) throws Exception {
        Path script = ROOT.resolve("examples/docking-snake-loop.xml");
        org.junit.jupiter.api.Assertions.assertTrue(docks(script));
        org.parpe.cli.Cli r = org.parpe.cli.Cli.run("export", script.toString(), "--out", out.resolve("c").toString());
        org.junit.jupiter.api.Assertions.assertEquals(1, r.code, r.toString());
        org.junit.jupiter.api.Assertions.assertTrue(r.err.contains(script + ":")
                && r.err.contains("error: state 'grab' arms connection plates"), r.err);
        org.junit.jupiter.api.Assertions.assertFalse(Files.exists(out.resolve("c")), "nothing written");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void generatedCTraceEqualsInterpreterTrace(Case c) throws Exception {
        if (c.check()) {
            refusedLikeCheck(c);
            return;
        }
        Path javaTrace = tmp.resolve("interpreter.csv");
        List<String> run = new ArrayList<>(List.of("run", c.script().toString()));
        run.addAll(c.runArgs());
        run.addAll(List.of("--trace", javaTrace.toString()));
        Cli interpreter = Cli.run(run);
        assertTrue(interpreter.code == 0 || interpreter.code == 3, () -> "interpreter: " + interpreter);

        Path dir = tmp.resolve("c");
        List<String> export = new ArrayList<>(List.of("export", c.script().toString(), "--target", "c", "--out", dir.toString()));
        export.addAll(options(c.runArgs(), "--tick", "--param"));
        Cli exported = Cli.run(export);
        assertEquals(0, exported.code, () -> "export: " + exported);
        HostCompiler.compile(dir);
        List<String> program = new ArrayList<>(List.of(dir.resolve("program").toString()));
        program.addAll(options(c.runArgs(), "--duration", "--stimulus", "--seed"));
        program.addAll(List.of("--trace", tmp.resolve("c.csv").toString()));
        HostCompiler.Result r = HostCompiler.run(dir, program, 60);
        assertEquals(interpreter.code, r.code(), () -> "exit code of the C program; its stderr: " + r.err()
                + "\ninterpreter: " + interpreter);
        assertTracesMatch(Files.readString(javaTrace), Files.readString(tmp.resolve("c.csv")));
        assertEquals(overlapWarnings(interpreter.err), overlapWarnings(r.err()), "warnings of overlapping instances");
        if (interpreter.code == 3) {
            // the whole diagnostic: place, message (numbers written as parpe run writes them) and tick time
            assertEquals(errorLines(interpreter.err), errorLines(r.err()), "the C program's run-time error");
        }
    }

    @Test
    void theTraceComparisonAllowsOneUnitInTheLastDigitAndNothingElse() {
        String java = "time,m0\n0.010000,30.000000\n";
        assertTracesMatch(java, "time,m0\n0.010000,30.000001\n");
        assertTracesMatch(java, "time,m0\n0.010000,29.999999\n");
        for (String c : List.of("time,m0\n0.010000,30.000002\n", "time,m1\n0.010000,30.000000\n",
                "time,m0\n0.010000,30.000000\n0.020000,30.000000\n", "time,m0\n0.010000,30.000000",
                "time,m0\n0.010000,30.0000001\n")) {
            assertThrows(AssertionError.class, () -> assertTracesMatch(java, c), c);
        }
    }

    /** The options {@code names} of {@code args} (pairs of option and value), in order. */
    static List<String> options(List<String> args, String... names) {
        List<String> out = new ArrayList<>();
        for (int i = 0; i + 1 < args.size(); i += 2) {
            if (List.of(names).contains(args.get(i))) {
                out.add(args.get(i));
                out.add(args.get(i + 1));
            }
        }
        return out;
    }

    private void refusedLikeCheck(Case c) {
        Cli check = Cli.run(List.of("check", c.script().toString()));
        Cli export = Cli.run(List.of("export", c.script().toString(), "--out", tmp.resolve("c").toString()));
        assertEquals(1, check.code, () -> "check: " + check);
        assertEquals(1, export.code, () -> "export: " + export);
        assertEquals(diagnostics(check.err), diagnostics(export.err));
        assertTrue(Files.notExists(tmp.resolve("c")), "nothing is written for a script with errors");
    }

    /**
     * The stated equality (docs/embedded.md): the traces are equal byte for byte, except that a number may
     * differ by one unit in its last printed digit (1e-6), where a maths function's last-bit difference
     * ({@link MathsBoundTest}) reaches the sixth decimal. Layout, columns, text and line count are exact.
     */
    static void assertTracesMatch(String java, String c) {
        if (java.equals(c)) {
            return;
        }
        List<String> jl = java.lines().toList();
        List<String> cl = c.lines().toList();
        assertEquals(jl.size(), cl.size(), "lines of the C program's trace");
        for (int i = 0; i < jl.size(); i++) {
            String[] jf = jl.get(i).split(",", -1);
            String[] cf = cl.get(i).split(",", -1);
            int line = i + 1;
            assertEquals(jf.length, cf.length, () -> "fields of trace line " + line + ": " + cl.get(line - 1));
            for (int k = 0; k < jf.length; k++) {
                if (jf[k].equals(cf[k])) {
                    continue;
                }
                String j = jf[k];
                String x = cf[k];
                boolean numbers = j.matches("-?\\d+\\.\\d{6}") && x.matches("-?\\d+\\.\\d{6}");
                assertTrue(numbers && new java.math.BigDecimal(j).subtract(new java.math.BigDecimal(x)).abs()
                        .compareTo(new java.math.BigDecimal("0.000001")) <= 0,
                        () -> "trace line " + line + ": the C program writes " + x + " where parpe run writes " + j);
            }
        }
        assertEquals(java.endsWith("\n"), c.endsWith("\n"), "final newline of the trace");
    }

    private static List<String> errorLines(String err) {
        return err.lines().filter(l -> l.contains(": error: ")).toList();
    }

    private static List<String> overlapWarnings(String err) {
        return err.lines().filter(l -> l.contains(": warning: instances ")).toList();
    }

    private static List<String> diagnostics(String err) {
        return err.lines().filter(l -> l.contains(": error: ") || l.contains(": warning: ")).toList();
    }
}
