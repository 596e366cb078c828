package org.parpe.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.ShrinkingMode;
import net.jqwik.api.statistics.Statistics;

/**
 * The output policy as a property (issue 18): every command that writes files is run with its
 * output paths drawn at random from its own inputs (as given, spelled with {@code ./}, or
 * through a symbolic link), from the other outputs' names and from new names. Whatever is drawn,
 * no input changes; a command that names one file twice or an input as an output is refused
 * (exit 2) before it writes anything; a command that succeeds leaves every output it was given,
 * whole, each in its own file; and no temporary file is left.
 */
class OutputCollisionProperties {
    private static final String WAVE = """
            <program>
              <robot><structure><body elements="0..1"/></structure></robot>
              <parameters><bend value="10" min="0" max="60"/></parameters>
              <main><go/></main>
              <behaviors><go><wave group="body" period="2"/></go></behaviors>
              <automata><wave states="up, down"/></automata>
              <states><up angles="bend"/><down angles="-bend"/></states>
            </program>
            """;
    private static final String SHARD_HEADER = "run,runs,combination,repeat,seed,bend,duration_s,distance_m,forward_m,"
            + "forward_speed_mps,speed_mps,max_tilt_deg,joint_travel_deg,fell,error\n";

    /** A command: its arguments with {@code {0}}, {@code {1}}, ... for the outputs, and the inputs it reads. */
    private record Command(String name, List<String> args, int outputs, List<String> inputs) {
    }

    private static final List<Command> COMMANDS = List.of(
            new Command("run", List.of("run", "main.xml", "--duration", "0.2", "--stimulus", "s.txt", "--trace", "{0}",
                    "--sim", "--metrics", "{1}", "--plot", "{2}"), 3, List.of("main.xml", "inc.xml", "s.txt")),
            new Command("merge", List.of("merge", "a.csv", "b.csv", "--out", "{0}"), 1, List.of("a.csv", "b.csv")),
            new Command("sweep", List.of("sweep", "wave.xml", "--sim", "snake:n=2", "--duration", "0.1", "--vary",
                    "bend=20..40:2", "--out", "{0}", "--plot", "{1}"), 2, List.of("wave.xml")),
            new Command("export", List.of("export", "wave.xml", "--out", "{0}"), 1, List.of("wave.xml")));

    @Provide
    Arbitrary<Integer> command() {
        return Arbitraries.integers().between(0, COMMANDS.size() - 1);
    }

    @Provide
    Arbitrary<List<Integer>> choices() {
        return Arbitraries.integers().between(0, 99).list().ofSize(3);
    }

    @Property(tries = 80, shrinking = ShrinkingMode.OFF)
    void noInputChangesAndNoOutputIsLost(@ForAll("command") int which, @ForAll("choices") List<Integer> picks)
            throws Exception {
        Command c = COMMANDS.get(which);
        Path dir = Files.createTempDirectory("parpe-collide");
        try {
            Map<Path, byte[]> inputs = writeInputs(dir);
            // the names an output may get: each input three ways, and three new names
            List<String> names = new ArrayList<>();
            for (String in : c.inputs()) {
                names.add(dir.resolve(in).toString());
                names.add(dir.resolve(".").resolve(in).toString());
                Path link = dir.resolve("link-" + in);
                if (!Files.exists(link)) {
                    Files.createSymbolicLink(link, dir.resolve(in));
                }
                names.add(link.toString());
            }
            for (int i = 0; i < 3; i++) {
                names.add(dir.resolve("out" + i + (c.name().equals("export") ? "" : ".dat")).toString());
            }
            List<String> outs = new ArrayList<>();
            for (int i = 0; i < c.outputs(); i++) {
                int pick = picks.get(i);
                // half of the draws a name of this output's own, so that whole runs that succeed are drawn too
                outs.add(pick < 50 ? names.get(names.size() - 3 + i) : names.get(pick % names.size()));
            }
            List<String> args = new ArrayList<>();
            for (String a : c.args()) {
                String v = a;
                for (int i = 0; i < outs.size(); i++) {
                    v = v.replace("{" + i + "}", outs.get(i));
                }
                args.add(a.endsWith(".xml") || a.endsWith(".csv") || a.endsWith(".txt") ? dir.resolve(a).toString() : v);
            }
            Cli r = Cli.run(args);
            for (Map.Entry<Path, byte[]> in : inputs.entrySet()) {
                assertArrayEquals(in.getValue(), Files.readAllBytes(in.getKey()), in.getKey() + " changed: " + args + "\n" + r);
            }
            boolean collide = collide(dir, outs, c.inputs());
            Statistics.label("outcome").collect(collide ? "refused" : "written");
            Statistics.label("outcome").coverage(k -> {
                k.check("refused").count(n -> n >= 5);
                k.check("written").count(n -> n >= 5);
            });
            if (collide) {
                assertEquals(2, r.code, "a collision must be refused: " + args + "\n" + r);
            } else {
                assertEquals(0, r.code, args + "\n" + r);
                for (String o : outs) {
                    Path p = Path.of(o);
                    assertTrue(Files.isDirectory(p) ? notEmpty(p) : Files.size(p) > 0, o + " is lost: " + args);
                }
            }
            try (Stream<Path> all = Files.walk(dir)) {
                List<Path> tmp = all.filter(p -> p.getFileName().toString().endsWith(".tmp")).toList();
                assertEquals(List.of(), tmp, "temporary files left: " + args);
            }
        } finally {
            try (Stream<Path> all = Files.walk(dir)) {
                for (Path p : all.sorted(Comparator.reverseOrder()).toList()) {
                    Files.deleteIfExists(p);
                }
            }
        }
    }

    /** Whether two outputs name one file, or an output names an input (following links and ./). */
    private static boolean collide(Path dir, List<String> outs, List<String> inputs) throws IOException {
        Set<Path> seen = new HashSet<>();
        Set<Path> in = new HashSet<>();
        for (String i : inputs) {
            in.add(dir.resolve(i).toRealPath());
        }
        for (String o : outs) {
            Path p = Path.of(o).toAbsolutePath().normalize();
            Path real = Files.exists(p) ? p.toRealPath() : p;
            if (in.contains(real) || !seen.add(real)) {
                return true;
            }
        }
        return false;
    }

    private static boolean notEmpty(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.findAny().isPresent();
        }
    }

    private static Map<Path, byte[]> writeInputs(Path dir) throws IOException {
        Map<String, String> files = new LinkedHashMap<>();
        files.put("main.xml", CliContractTest.GOOD.replace("</program>", "<include file=\"inc.xml\"/></program>"));
        files.put("inc.xml", "<lib/>\n");
        files.put("s.txt", "0.1 $dir=down\n");
        files.put("wave.xml", WAVE);
        files.put("a.csv", SHARD_HEADER + "0,2,0,0,1,20,0.1,0,0,0,0,0,0,0,\n");
        files.put("b.csv", SHARD_HEADER + "1,2,1,0,1,40,0.1,0,0,0,0,0,0,0,\n");
        Map<Path, byte[]> written = new LinkedHashMap<>();
        for (Map.Entry<String, String> f : files.entrySet()) {
            Path p = Files.writeString(dir.resolve(f.getKey()), f.getValue());
            written.put(p, Files.readAllBytes(p));
        }
        return written;
    }
}
