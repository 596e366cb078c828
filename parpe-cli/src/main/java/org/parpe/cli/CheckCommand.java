package org.parpe.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.stream.Stream;
import org.parpe.cli.text.CliMsg;
import org.parpe.cli.options.Inputs;
import org.parpe.cli.options.UsageException;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.diag.DiagnosticList;
import org.parpe.core.xml.InputFiles;
import org.parpe.core.xml.XmlReader;
import org.parpe.sim.world.Challenge;
import org.parpe.sim.world.ChallengeReader;
import org.parpe.sim.world.WorldReader;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code parpe check FILE|DIR...}: loads and validates scripts, reporting every problem. A folder
 * stands for the {@code .xml} and {@code .parsl} files directly in it (not in its subfolders,
 * where robot configurations usually live), in name order: a teacher checks a class's folder.
 */
@Command(name = "check", mixinStandardHelpOptions = true, description = "Check PARSL scripts; errors are printed as FILE:LINE:COL."
        + " A folder checks the .xml and .parsl files directly in it.")
final class CheckCommand implements Callable<Integer> {
    @Parameters(arity = "1..*", paramLabel = "FILE|DIR", descriptionKey = "files",
            description = "PARSL scripts, or folders of them, to check.")
    List<Path> files;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        int code = 0;
        List<Path> scripts = new ArrayList<>();
        for (Path f : files) {
            if (!Files.isDirectory(f)) {
                scripts.add(f);
                continue;
            }
            List<Path> inside = scriptsIn(f);
            if (inside.isEmpty()) {
                spec.commandLine().getErr().println("parpe: " + CliMsg.EMPTY_FOLDER.text(f));
                code = 2;
            }
            scripts.addAll(inside);
        }
        for (Path f : scripts) {
            try {
                Inputs.check(f);
            } catch (UsageException e) {
                spec.commandLine().getErr().println("parpe: " + e.getMessage());
                code = Math.max(code, 2);
                continue;
            }
            if (isChallenge(f)) {
                code = Math.max(code, checkChallenge(f));
                continue;
            }
            LoadResult r = ScriptLoader.load(f, Map.of());
            for (Diagnostic d : r.diagnostics()) {
                spec.commandLine().getErr().println(d.format());
            }
            if (r.program() == null) {
                code = Math.max(code, 1);
                spec.commandLine().getErr().println(f + ": " + errors(r.errors().size()));
            } else {
                spec.commandLine().getOut().println(f + ": " + CliMsg.OK.text());
            }
        }
        return code;
    }

    private static boolean isChallenge(Path f) {
        try {
            return XmlReader.rootName(InputFiles.readText(f)).equals("challenge");
        } catch (IOException e) {
            return false; // the loader reports it
        }
    }

    /** Checks a challenge file and the world it names, as {@code parpe grade} reads them. */
    private int checkChallenge(Path f) {
        DiagnosticList found = new DiagnosticList();
        Challenge c = ChallengeReader.read(f, found);
        if (c != null) {
            WorldReader.read(c.world(), found);
        }
        found.all().forEach(d -> spec.commandLine().getErr().println(d.format()));
        if (found.hasErrors()) {
            spec.commandLine().getErr().println(f + ": " + errors(found.errorCount()));
            return 1;
        }
        spec.commandLine().getOut().println(f + ": " + CliMsg.OK_CHALLENGE.text());
        return 0;
    }

    /** {@code 1 error}, {@code 3 errors}: the summary of a file that does not load. */
    private static String errors(long n) {
        return (n == 1 ? CliMsg.ONE_ERROR : CliMsg.N_ERRORS).text(n);
    }

    private List<Path> scriptsIn(Path dir) {
        try (Stream<Path> s = Files.list(dir)) {
            return s.filter(p -> InputFiles.isScript(p) && Files.isRegularFile(p)).sorted().toList();
        } catch (IOException | RuntimeException e) {
            return List.of();
        }
    }
}
