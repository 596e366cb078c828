package org.parpe.core;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.Engine;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.Stimulus;
import org.parpe.core.run.StimulusParser;
import org.parpe.core.run.TraceWriter;

/**
 * Runs a case of the PARSL conformance suite (spec/conformance) or of PARPE's extra suite
 * (spec/conformance-parpe) through the core API (no CLI), as run.sh would.
 */
public final class Conformance {
    /** The repository's root: the folder holding {@code spec/PARSL.md}. */
    public static final Path ROOT = locate();
    /** The PARSL conformance suite, the repository's copy of the shared one (spec/conformance). */
    public static final Path CASES = ROOT.resolve("spec/conformance/cases");
    /** PARPE's own extra cases, in the same layout (spec/conformance-parpe). */
    public static final Path PARPE_CASES = ROOT.resolve("spec/conformance-parpe/cases");

    private Conformance() {
    }

    private static Path locate() {
        Path here = Path.of("").toAbsolutePath();
        for (Path p = here; p != null; p = p.getParent()) {
            if (Files.isRegularFile(p.resolve("spec/PARSL.md"))) {
                return p;
            }
        }
        throw new IllegalStateException("no spec/PARSL.md in " + here + " or a folder above it");
    }

    /** The case folders of both suites, sorted (the PARSL suite first). */
    public static List<Path> cases() throws IOException {
        List<Path> all = new ArrayList<>(cases(CASES));
        all.addAll(cases(PARPE_CASES));
        return all;
    }

    /** The case folders of one suite, sorted. */
    public static List<Path> cases(Path suite) throws IOException {
        if (!Files.isDirectory(suite)) {
            throw new IllegalStateException("a conformance suite is missing: expected " + suite);
        }
        try (var s = Files.list(suite)) {
            return s.filter(p -> Files.exists(p.resolve("cmd"))).sorted().toList();
        }
    }

    /** The outcome of a run: trace text and diagnostics. */
    public record Outcome(String trace, List<Diagnostic> diagnostics, boolean loaded) {
    }

    /** The arguments of a case's cmd file. */
    public static List<String> args(Path dir) throws IOException {
        return List.of(Files.readString(dir.resolve("cmd")).trim().split("\\s+"));
    }

    /** Runs {@code run ARGS} of a case folder and returns the trace. */
    public static Outcome run(Path dir, List<String> args) throws Exception {
        Path file = null;
        double duration = Double.POSITIVE_INFINITY;
        double tick = 0.01;
        Map<String, Double> params = new LinkedHashMap<>();
        Path stimulus = null;
        for (int i = 0; i < args.size(); i++) {
            String a = args.get(i);
            switch (a) {
                case "--duration": duration = Double.parseDouble(args.get(++i)); break;
                case "--tick": tick = Double.parseDouble(args.get(++i)); break;
                case "--param":
                    String[] kv = args.get(++i).split("=", 2);
                    params.put(kv[0], Double.parseDouble(kv[1]));
                    break;
                case "--stimulus": stimulus = dir.resolve(args.get(++i)); break;
                default: file = dir.resolve(a);
            }
        }
        LoadResult r = ScriptLoader.load(file, params);
        if (!r.ok()) {
            return new Outcome("", r.diagnostics(), false);
        }
        List<Stimulus> stimuli = stimulus == null ? List.of()
                : StimulusParser.parse(stimulus.toString(), Files.readString(stimulus, StandardCharsets.UTF_8), r.program());
        Engine e = new Engine(r.program(), new RunOptions(tick, 0, stimuli));
        StringWriter out = new StringWriter();
        e.addObserver(new TraceWriter(out));
        List<Diagnostic> warnings = new ArrayList<>(r.diagnostics());
        e.setWarningSink(warnings::add);
        e.start();
        for (long k = 0; k * tick <= duration + 1e-9; k++) {
            if (!e.step()) {
                break;
            }
        }
        return new Outcome(out.toString(), warnings, true);
    }

    /** Compares traces as run.sh does; returns null when equal within 1e-6, else where they differ. */
    public static String compare(String expected, String got) {
        String[] exp = expected.strip().split("\r?\n");
        String[] act = got.strip().split("\r?\n");
        if (!exp[0].replace(" ", "").equals(act[0].replace(" ", ""))) {
            return "header: expected " + exp[0] + ", got " + act[0];
        }
        if (exp.length != act.length) {
            return "expected " + (exp.length - 1) + " rows, got " + (act.length - 1) + " (last time got "
                    + act[act.length - 1].split(",")[0] + ")";
        }
        String[] names = exp[0].split(",");
        for (int r = 1; r < exp.length; r++) {
            String[] ev = exp[r].split(",");
            String[] av = act[r].split(",");
            for (int c = 0; c < ev.length; c++) {
                if (c >= av.length || Math.abs(Double.parseDouble(ev[c]) - Double.parseDouble(av[c])) > 1e-6 + 1e-9) {
                    return "row " + r + " (time " + ev[0] + "), column " + names[c] + ": expected " + ev[c] + ", got "
                            + (c < av.length ? av[c] : "nothing");
                }
            }
        }
        return null;
    }
}
