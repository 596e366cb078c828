package org.parpe.gui.pose;

import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import org.parpe.core.model.Group;
import org.parpe.core.model.Program;

/**
 * Left/right partners for mirroring a pose: groups named {@code left…} and {@code right…} with the
 * same rest of the name and the same size pair their modules position by position
 * ({@code leftSwing[k]} with {@code rightSwing[k]}; {@code left} with {@code right}).
 */
final class MirrorMap {
    private MirrorMap() {
    }

    /**
     * For each position {@code k} of {@code modules}, the position of its partner in the same
     * list, or {@code k} when its partner is not in the list or it has none.
     */
    static int[] swap(Program program, int[] modules) {
        Map<Integer, Integer> partner = new HashMap<>();
        if (program != null) {
            for (Group l : program.robot().groups()) {
                String ln = l.name().toLowerCase(Locale.ROOT);
                if (!ln.startsWith("left")) {
                    continue;
                }
                for (Group r : program.robot().groups()) {
                    String rn = r.name().toLowerCase(Locale.ROOT);
                    if (rn.startsWith("right") && rn.substring(5).equals(ln.substring(4)) && r.size() == l.size()) {
                        for (int k = 0; k < l.size(); k++) {
                            partner.put(l.modules().get(k), r.modules().get(k));
                            partner.put(r.modules().get(k), l.modules().get(k));
                        }
                    }
                }
            }
        }
        int[] swap = new int[modules.length];
        for (int k = 0; k < modules.length; k++) {
            swap[k] = k;
            Integer p = partner.get(modules[k]);
            for (int j = 0; p != null && j < modules.length; j++) {
                if (modules[j] == p) {
                    swap[k] = j;
                }
            }
        }
        return swap;
    }

    /** Whether no position has a partner (then mirroring negates, as {@code !} does). */
    static boolean unpaired(int[] swap) {
        for (int k = 0; k < swap.length; k++) {
            if (swap[k] != k) {
                return false;
            }
        }
        return true;
    }
}
