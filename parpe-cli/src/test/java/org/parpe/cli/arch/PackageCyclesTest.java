package org.parpe.cli.arch;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;

/**
 * Issue 32, item 4: no package cycle anywhere, root packages and the IDE included, over the
 * dependencies the package picture draws ({@link PackageMapTest#dependencies}): the classes as
 * ArchUnit reads them and the types every module's sources name. The sources see what the
 * bytecode hides from the ArchUnit rules ({@code ModuleLayersTest}, {@code GuiPackagesTest}):
 * a constant inlined from another package ({@code Main.INTERNAL_ERROR} in {@code cli.bench}) and
 * picocli's subcommand annotations, which made {@code cli ↔ cli.bench} a cycle they passed.
 */
class PackageCyclesTest {
    @Test
    void noPackageUsesAPackageThatUsesIt() throws IOException {
        List<Set<String>> cycles = cycles(PackageMapTest.dependencies());
        assertEquals(List.of(), cycles, "packages in a cycle (each set uses itself through the others)");
    }

    /** The strongly connected components of more than one package (Tarjan), each sorted. */
    static List<Set<String>> cycles(Map<String, Set<String>> deps) {
        Map<String, Integer> index = new HashMap<>();
        Map<String, Integer> low = new HashMap<>();
        Deque<String> stack = new ArrayDeque<>();
        List<Set<String>> out = new ArrayList<>();
        for (String p : new TreeSet<>(deps.keySet())) {
            if (!index.containsKey(p)) {
                visit(p, deps, index, low, stack, out);
            }
        }
        return out;
    }

    private static void visit(String p, Map<String, Set<String>> deps, Map<String, Integer> index,
                              Map<String, Integer> low, Deque<String> stack, List<Set<String>> out) {
        index.put(p, index.size());
        low.put(p, index.get(p));
        stack.push(p);
        for (String q : new TreeSet<>(deps.getOrDefault(p, Set.of()))) {
            if (!deps.containsKey(q)) {
                continue;
            }
            if (!index.containsKey(q)) {
                visit(q, deps, index, low, stack, out);
                low.put(p, Math.min(low.get(p), low.get(q)));
            } else if (stack.contains(q)) {
                low.put(p, Math.min(low.get(p), index.get(q)));
            }
        }
        if (low.get(p).equals(index.get(p))) {
            Set<String> component = new TreeSet<>();
            String q;
            do {
                q = stack.pop();
                component.add(q);
            } while (!q.equals(p));
            if (component.size() > 1) {
                out.add(component);
            }
        }
    }
}
