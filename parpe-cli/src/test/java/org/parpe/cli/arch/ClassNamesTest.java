package org.parpe.cli.arch;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Issue 32, item 6: a class name says what the class is, once. No two top-level classes of the
 * five modules have the same name, or the same words in another order ({@code DialogHardware}
 * beside {@code HardwareDialog}), but the two entry points {@code Main} of the command line and
 * the IDE.
 */
class ClassNamesTest {
    private static final Path ROOT = Path.of("..");
    private static final List<String> MODULES = List.of("core", "sim", "serial", "cli", "gui");
    private static final Pattern WORD = Pattern.compile("[A-Z][a-z0-9]*|[a-z0-9]+");

    @Test
    void noTwoClassesShareTheirWords() throws IOException {
        Map<String, List<String>> byWords = new TreeMap<>();
        for (String m : MODULES) {
            Path src = ROOT.resolve("parpe-" + m + "/src/main/java");
            try (Stream<Path> s = Files.walk(src)) {
                for (Path f : s.filter(p -> p.toString().endsWith(".java")).sorted().toList()) {
                    String name = f.getFileName().toString().replace(".java", "");
                    if (!name.equals("package-info") && !name.equals("Main")) {
                        byWords.computeIfAbsent(words(name), k -> new ArrayList<>())
                                .add(src.relativize(f).toString().replace(".java", ""));
                    }
                }
            }
        }
        List<List<String>> clashes = byWords.values().stream().filter(l -> l.size() > 1).toList();
        assertEquals(List.of(), clashes, "classes named alike; name one of each after what it is");
    }

    /** The words of a class name, sorted: {@code DialogHardware} and {@code HardwareDialog} alike. */
    static String words(String name) {
        List<String> w = new ArrayList<>();
        Matcher m = WORD.matcher(name);
        while (m.find()) {
            w.add(m.group().toLowerCase(java.util.Locale.ROOT));
        }
        String[] sorted = w.toArray(String[]::new);
        Arrays.sort(sorted);
        return String.join(" ", sorted);
    }
}
