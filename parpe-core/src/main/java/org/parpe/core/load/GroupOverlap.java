package org.parpe.core.load;

import java.util.BitSet;
import java.util.HashMap;
import java.util.Map;
import org.parpe.core.model.Group;

/**
 * The static overlap test of PARSL.md §7: whether two groups share a module. The loader's
 * instance checks report unconditional overlaps with it; the diagrams mark the instances under
 * {@code <if>} that it finds, which may drive one module twice at run time. Group members are
 * kept as bit sets, one per group name, so that many instances compare quickly.
 */
public final class GroupOverlap {
    private final Map<String, BitSet> members = new HashMap<>();

    /** The smallest module ID that both groups hold, or {@code null} when they share none. */
    public Integer shared(Group a, Group b) {
        BitSet x = (BitSet) bits(a).clone();
        x.and(bits(b));
        return x.isEmpty() ? null : x.nextSetBit(0);
    }

    private BitSet bits(Group g) {
        return members.computeIfAbsent(g.name(), k -> {
            BitSet b = new BitSet();
            g.modules().forEach(b::set);
            return b;
        });
    }
}
