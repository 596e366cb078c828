package org.parpe.cli.arch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.tngtech.archunit.core.domain.Dependency;
import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * {@code docs/architecture-packages.svg}, the picture of docs/architecture.md: every module's
 * packages and the dependencies between them ({@link #dependencies}). The test fails when the
 * picture is out of date (a rerun too, so a changed package graph cannot pass as a flake).
 */
class PackageMapTest {
    /** Modules in drawing rows: the applications, the two drivers, the core. */
    private static final List<List<String>> ROWS = List.of(List.of("gui", "cli"), List.of("sim", "serial"),
            List.of("core"));
    private static final Path ROOT = Path.of("..");
    private static final Path PICTURE = ROOT.resolve("docs/architecture-packages.svg");
    /** A reference to a class of PARPE: its package, then the class name's capital. */
    private static final Pattern REFERENCE = Pattern.compile("\\borg\\.parpe\\.((?:[a-z][a-z0-9]*\\.)*)[A-Z]");
    /** Comments and string literals: a class named in a string (the IDE launched by name) is no compile dependency. */
    private static final Pattern COMMENT = Pattern.compile("/\\*.*?\\*/|//[^\\n]*|\"(?:\\\\.|[^\"\\\\\\n])*\"",
            Pattern.DOTALL);

    /** Package → the packages its classes use (other than itself), over every module's main sources. */
    static Map<String, Set<String>> sourceDependencies() throws IOException {
        Map<String, Set<String>> deps = new TreeMap<>();
        for (List<String> row : ROWS) {
            for (String module : row) {
                Path src = ROOT.resolve("parpe-" + module + "/src/main/java");
                List<Path> files;
                try (Stream<Path> s = Files.walk(src)) {
                    files = s.filter(f -> f.toString().endsWith(".java")).sorted().toList();
                }
                for (Path f : files) {
                    String pkg = src.relativize(f.getParent()).toString().replace(f.getFileSystem().getSeparator(), ".");
                    Set<String> used = deps.computeIfAbsent(pkg, k -> new TreeSet<>());
                    String code = COMMENT.matcher(Files.readString(f, StandardCharsets.UTF_8)).replaceAll("");
                    Matcher m = REFERENCE.matcher(code);
                    while (m.find()) {
                        String target = "org.parpe." + m.group(1).replaceAll("\\.$", "");
                        if (!target.equals(pkg)) {
                            used.add(target);
                        }
                    }
                }
            }
        }
        return deps;
    }

    /**
     * Package → the packages its classes use: the compiled classes of the four modules on this
     * module's class path (as ArchUnit reads them, so a call on a value whose type the source
     * never names counts too), and the types every module's sources name (the IDE's only so).
     */
    static Map<String, Set<String>> dependencies() throws IOException {
        Map<String, Set<String>> deps = sourceDependencies();
        for (JavaClass c : new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .importPackages("org.parpe")) {
            for (Dependency d : c.getDirectDependenciesFromSelf()) {
                String from = d.getOriginClass().getPackageName();
                String to = d.getTargetClass().getPackageName();
                if (to.startsWith("org.parpe") && !to.equals(from) && deps.containsKey(from)) {
                    deps.get(from).add(to);
                }
            }
        }
        return deps;
    }

    @Test
    void thePictureTakesEveryModuleAndDependenciesTheSourcesDoNotName() throws IOException {
        Map<String, Set<String>> deps = dependencies();
        assertTrue(deps.containsKey("org.parpe.gui.app"), "the IDE's sources were read");
        // OptimizeCommand calls Parameter.name() on a value whose type it never names
        assertTrue(deps.get("org.parpe.cli.sweep").contains("org.parpe.core.model"), deps.toString());
        assertTrue(deps.get("org.parpe.core.load").contains("org.parpe.core.model"), deps.toString());
    }

    @Test
    void theDocsPictureShowsTheCurrentPackages() throws IOException {
        String svg = svg(dependencies());
        String old = Files.exists(PICTURE) ? Files.readString(PICTURE, StandardCharsets.UTF_8) : "";
        if (!svg.equals(old)) {
            Path target = Boolean.getBoolean("parpe.updateDocs") ? PICTURE : Path.of("target/architecture-packages.svg");
            Files.writeString(target, svg, StandardCharsets.UTF_8);
        }
        assertEquals(old, svg, PICTURE + " is out of date: the new picture is in target/ (or run this test with"
                + " -Dparpe.updateDocs=true to rewrite it) and belongs in the commit that changed the packages");
    }

    private static String module(String pkg) {
        String rest = pkg.substring("org.parpe.".length());
        int dot = rest.indexOf('.');
        return dot < 0 ? rest : rest.substring(0, dot);
    }

    private static String label(String pkg) {
        String m = module(pkg);
        String rest = pkg.substring(("org.parpe." + m).length());
        return rest.isEmpty() ? "(" + m + ")" : rest.substring(1);
    }

    private record Box(int x, int y, int w) {
    }

    private static final int BOX_H = 22;
    private static final int ROW_GAP = 40;
    private static final int PAD = 14;
    private static final int TITLE = 26;
    private static final int CHAR_W = 7;

    /** The picture: a box per module, its packages in rows (a package above those it uses), arrows between. */
    static String svg(Map<String, Set<String>> deps) {
        Map<String, List<List<String>>> layers = new HashMap<>();
        Map<String, int[]> size = new HashMap<>();
        for (List<String> row : ROWS) {
            for (String m : row) {
                List<String> pkgs = deps.keySet().stream().filter(p -> module(p).equals(m)).toList();
                Map<String, Integer> rank = new HashMap<>();
                pkgs.forEach(p -> rank(p, m, deps, rank, new TreeSet<>()));
                int top = rank.values().stream().mapToInt(Integer::intValue).max().orElse(0);
                List<List<String>> ls = new ArrayList<>();
                for (int r = top; r >= 0; r--) {
                    int rr = r;
                    ls.add(pkgs.stream().filter(p -> rank.get(p) == rr).toList());
                }
                layers.put(m, ls);
                int w = 0;
                for (List<String> l : ls) {
                    w = Math.max(w, l.stream().mapToInt(p -> boxWidth(p) + PAD).sum() + PAD);
                }
                size.put(m, new int[] {Math.max(w, 120), TITLE + ls.size() * (BOX_H + ROW_GAP) - ROW_GAP + 2 * PAD});
            }
        }
        int width = 0;
        for (List<String> row : ROWS) {
            width = Math.max(width, row.stream().mapToInt(m -> size.get(m)[0]).sum() + 60 * (row.size() + 1));
        }
        Map<String, Box> boxes = new HashMap<>();
        Map<String, int[]> moduleAt = new HashMap<>();
        StringBuilder body = new StringBuilder();
        int y = 20;
        for (List<String> row : ROWS) {
            int rowW = row.stream().mapToInt(m -> size.get(m)[0]).sum() + 60 * (row.size() - 1);
            int x = (width - rowW) / 2;
            int rowH = 0;
            for (String m : row) {
                int[] s = size.get(m);
                moduleAt.put(m, new int[] {x, y, s[0], s[1]});
                body.append(String.format("  <rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" rx=\"8\" class=\"module\"/>\n",
                        x, y, s[0], s[1]));
                body.append(String.format("  <text x=\"%d\" y=\"%d\" class=\"title\">parpe-%s</text>\n", x + 10, y + 18, m));
                int py = y + TITLE + PAD;
                for (List<String> layer : layers.get(m)) {
                    int lw = layer.stream().mapToInt(p -> boxWidth(p) + PAD).sum() - PAD;
                    int px = x + (s[0] - lw) / 2;
                    for (String p : layer) {
                        boxes.put(p, new Box(px, py, boxWidth(p)));
                        px += boxWidth(p) + PAD;
                    }
                    py += BOX_H + ROW_GAP;
                }
                x += s[0] + 60;
                rowH = Math.max(rowH, s[1]);
            }
            y += rowH + 70;
        }
        int height = y - 70 + 20;
        StringBuilder arrows = new StringBuilder();
        Map<String, Integer> across = new TreeMap<>();
        deps.forEach((from, tos) -> {
            for (String to : tos) {
                if (!boxes.containsKey(to)) {
                    continue;
                }
                if (module(from).equals(module(to))) {
                    Box a = boxes.get(from);
                    Box b = boxes.get(to);
                    boolean down = b.y() > a.y();
                    arrows.append(String.format("  <line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" class=\"%s\"/>\n",
                            a.x() + a.w() / 2, down ? a.y() + BOX_H : a.y(), b.x() + b.w() / 2,
                            down ? b.y() : b.y() + BOX_H, down ? "dep" : "dep up"));
                } else {
                    across.merge(module(from) + " " + module(to), 1, Integer::sum);
                }
            }
        });
        across.forEach((pair, n) -> {
            int[] a = moduleAt.get(pair.split(" ")[0]);
            int[] b = moduleAt.get(pair.split(" ")[1]);
            boolean sameRow = a[1] == b[1];
            int x1 = a[0] + a[2] / 2 + (b[0] > a[0] ? 30 : b[0] < a[0] ? -30 : 0);
            int x2 = b[0] + b[2] / 2 + (a[0] > b[0] ? 30 : a[0] < b[0] ? -30 : 0);
            int y1 = sameRow ? a[1] + a[3] / 2 : a[1] + a[3];
            int y2 = sameRow ? b[1] + b[3] / 2 : b[1];
            if (sameRow) {
                x1 = b[0] > a[0] ? a[0] + a[2] : a[0];
                x2 = b[0] > a[0] ? b[0] : b[0] + b[2];
            }
            arrows.append(String.format("  <line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" class=\"use\"/>\n", x1, y1, x2, y2));
            arrows.append(String.format("  <text x=\"%d\" y=\"%d\" class=\"count\">%d</text>\n", (x1 + x2) / 2 + 4,
                    (y1 + y2) / 2 - 3, n));
        });
        StringBuilder svg = new StringBuilder();
        svg.append(String.format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
                + "viewBox=\"0 0 %d %d\" font-family=\"sans-serif\" font-size=\"12\">\n", width, height, width, height));
        svg.append("""
                  <!-- Generated by parpe-cli's PackageMapTest from the sources; do not edit. -->
                  <defs>
                    <marker id="head" viewBox="0 0 10 10" refX="10" refY="5" markerWidth="7" markerHeight="7" orient="auto">
                      <path d="M0,0 L10,5 L0,10 z" fill="#4a6f94"/>
                    </marker>
                    <marker id="bighead" viewBox="0 0 10 10" refX="10" refY="5" markerWidth="9" markerHeight="9" orient="auto">
                      <path d="M0,0 L10,5 L0,10 z" fill="#555"/>
                    </marker>
                    <style>
                      .module { fill: #f4f6f9; stroke: #8a96a6; stroke-width: 1.2; }
                      .title { font-weight: bold; font-size: 14px; fill: #223; }
                      .pkg { fill: #ffffff; stroke: #4a6f94; stroke-width: 1; }
                      .name { fill: #123; text-anchor: middle; }
                      .dep { stroke: #4a6f94; stroke-width: 1; fill: none; marker-end: url(#head); opacity: 0.7; }
                      .up { stroke: #c0392b; }
                      .use { stroke: #555; stroke-width: 2.5; marker-end: url(#bighead); }
                      .count { fill: #555; font-size: 11px; }
                    </style>
                  </defs>
                  <rect width="100%" height="100%" fill="white"/>
                """);
        svg.append(body);
        boxes.entrySet().stream().sorted(Map.Entry.comparingByKey()).forEach(e -> {
            Box b = e.getValue();
            svg.append(String.format("  <rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" rx=\"3\" class=\"pkg\"/>\n",
                    b.x(), b.y(), b.w(), BOX_H));
            svg.append(String.format("  <text x=\"%d\" y=\"%d\" class=\"name\">%s</text>\n", b.x() + b.w() / 2,
                    b.y() + 15, label(e.getKey())));
        });
        svg.append(arrows);
        svg.append("</svg>\n");
        return svg.toString();
    }

    private static int boxWidth(String pkg) {
        return label(pkg).length() * CHAR_W + 16;
    }

    /** 0 for a package that uses no other of its module; else one more than the highest it uses. */
    private static int rank(String p, String module, Map<String, Set<String>> deps, Map<String, Integer> rank,
                            Set<String> visiting) {
        Integer known = rank.get(p);
        if (known != null) {
            return known;
        }
        if (!visiting.add(p)) {
            return 0;
        }
        int r = 0;
        for (String q : deps.getOrDefault(p, Set.of())) {
            if (module(q).equals(module) && deps.containsKey(q)) {
                r = Math.max(r, rank(q, module, deps, rank, visiting) + 1);
            }
        }
        visiting.remove(p);
        rank.put(p, r);
        return r;
    }
}
