package org.parpe.core;

import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.parpe.core.load.LoadResult;
import org.parpe.core.load.ScriptLoader;
import org.parpe.core.run.Engine;
import org.parpe.core.run.RunOptions;
import org.parpe.core.run.ScriptRuntimeError;

/**
 * Mutates the example scripts and the conformance programs thousands of times; every mutant
 * must end in diagnostics or in a run (possibly stopped by a run-time error), never in an
 * uncaught exception. A failing mutant is saved under target/ to reproduce it.
 */
class FuzzTest {
    private static final String[] TOKENS = {"<", ">", "\"", "=", "..", "$", "!", "(", ")", ",", ";", "&amp;", "&lt;",
        "0", "-1", "1e309", "999999999", ".", "[", "]", "</x>", "<x/>", "$_self_angle", "$0_touch_left", "$time",
        "all", "sin(", "sum()", "forever", "\n", " ", "/", "^", "%", "&&", "||", "==", "if(1,2)", "NaN", "\u00e9"};

    @Test
    @org.junit.jupiter.api.Timeout(180)
    void mutantsNeverCrashTheLoaderOrTheScheduler() throws Exception {
        List<String> seeds = new ArrayList<>();
        for (Path p : Examples.all()) {
            seeds.add(Files.readString(p));
        }
        for (Path c : Conformance.cases()) {
            seeds.add(Files.readString(c.resolve("program.xml")));
        }
        Random rnd = new Random(20261121);
        int loaded = 0;
        int iterations = Integer.getInteger("parpe.fuzz.iterations", 4000);
        for (int i = 0; i < iterations; i++) {
            String text = seeds.get(rnd.nextInt(seeds.size()));
            int rounds = 1 + rnd.nextInt(3);
            for (int r = 0; r < rounds; r++) {
                text = mutate(text, rnd);
            }
            try {
                LoadResult result = ScriptLoader.loadText(Path.of("fuzz.xml"), text, Map.of());
                if (result.ok()) {
                    loaded++;
                    run(result);
                }
            } catch (RuntimeException | StackOverflowError e) {
                Path out = Path.of("target", "fuzz-failure-" + i + ".xml");
                Files.createDirectories(out.getParent());
                Files.writeString(out, text);
                fail("mutant " + i + " (saved to " + out + ") threw " + e + "\n" + Arrays.toString(e.getStackTrace()));
            }
        }
        if (loaded < 100) {
            fail("too few mutants loaded (" + loaded + "): the mutations no longer exercise the scheduler");
        }
    }

    private static void run(LoadResult result) {
        Engine e = new Engine(result.program(), RunOptions.defaults());
        e.start();
        try {
            for (int k = 0; k < 300 && e.step(); k++) {
                // run a few seconds of every mutant that loads
            }
        } catch (ScriptRuntimeError expected) {
            // a located run-time error is a correct outcome
        }
    }

    static String mutate(String s, Random rnd) {
        int at = rnd.nextInt(s.length() + 1);
        switch (rnd.nextInt(7)) {
            case 0:
                return s.substring(0, at) + s.substring(Math.min(s.length(), at + 1 + rnd.nextInt(8)));
            case 1:
                return s.substring(0, at) + TOKENS[rnd.nextInt(TOKENS.length)] + s.substring(at);
            case 2: {
                String[] lines = s.split("\n", -1);
                int a = rnd.nextInt(lines.length);
                int b = rnd.nextInt(lines.length);
                String t = lines[a];
                lines[a] = lines[b];
                lines[b] = t;
                return String.join("\n", lines);
            }
            case 3: {
                List<String> lines = new ArrayList<>(List.of(s.split("\n", -1)));
                int a = rnd.nextInt(lines.size());
                if (rnd.nextBoolean()) {
                    lines.add(a, lines.get(a));
                } else {
                    lines.remove(a);
                }
                return String.join("\n", lines);
            }
            case 4:
                return s.replaceFirst("\\d+(\\.\\d+)?", List.of("0", "-3", "0.0001", "1e6", "-0", "7.5").get(rnd.nextInt(6)));
            case 5: {
                String[] names = s.split("[^A-Za-z_]+");
                String a = names[rnd.nextInt(names.length)];
                String b = names[rnd.nextInt(names.length)];
                return a.isEmpty() ? s : s.replaceFirst("\\b" + a + "\\b", b);
            }
            default:
                return s.replace("period=\"", "period=\"" + List.of("-", "0*", "$time*", "1/").get(rnd.nextInt(4)));
        }
    }
}
