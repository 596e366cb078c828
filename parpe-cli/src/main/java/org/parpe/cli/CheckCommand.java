package org.parpe.cli;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.parpe.core.diag.Diagnostic;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code parpe check FILE...}: loads and validates scripts, reporting every problem. */
@Command(name = "check", mixinStandardHelpOptions = true, description = "Check PARSL scripts; errors are printed as FILE:LINE:COL.")
final class CheckCommand implements Callable<Integer> {
    @Parameters(arity = "1..*", paramLabel = "FILE", description = "PARSL scripts to check.")
    List<Path> files;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        int code = 0;
        for (Path f : files) {
            try {
                Inputs.check(f);
            } catch (UsageException e) {
                spec.commandLine().getErr().println("parpe: " + e.getMessage());
                code = Math.max(code, 2);
                continue;
            }
            LoadResult r = ScriptLoader.load(f, Map.of());
            for (Diagnostic d : r.diagnostics()) {
                spec.commandLine().getErr().println(d.format());
            }
            if (r.program() == null) {
                code = Math.max(code, 1);
                spec.commandLine().getErr().println(f + ": " + r.errors().size()
                        + (r.errors().size() == 1 ? " error" : " errors"));
            } else {
                spec.commandLine().getOut().println(f + ": ok");
            }
        }
        return code;
    }
}
