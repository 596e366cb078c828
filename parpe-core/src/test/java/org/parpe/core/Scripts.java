package org.parpe.core;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/** Every PARSL file of the repository: the examples, the tutorial's and the conformance programs. */
final class Scripts {
    private Scripts() {
    }

    /** Every script file, sorted within each folder. */
    static List<Path> all() throws IOException {
        List<Path> all = new ArrayList<>(Examples.all());
        try (var s = Files.list(Examples.dir().resolve("tutorial"))) {
            all.addAll(s.filter(p -> p.toString().endsWith(".xml")).sorted().toList());
        }
        for (Path c : Conformance.cases()) {
            all.add(c.resolve("program.xml"));
        }
        return all;
    }

    /** The scripts that load without errors. */
    static List<Path> loading() throws IOException {
        List<Path> out = new ArrayList<>();
        for (Path p : all()) {
            if (org.parpe.core.load.ScriptLoader.load(p, java.util.Map.of()).ok()) {
                out.add(p);
            }
        }
        return out;
    }
}
