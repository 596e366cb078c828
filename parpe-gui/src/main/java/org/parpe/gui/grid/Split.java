package org.parpe.gui.grid;

import java.util.ArrayList;
import java.util.List;
import org.parpe.core.load.ListItem;

/** The trimmed items of a PARSL list, split as the loader splits them ({@link ListItem#ranges}). */
final class Split {
    private Split() {
    }

    /** The trimmed texts of the parts of {@code s}. */
    static List<String> texts(String s, char separator) {
        List<String> out = new ArrayList<>();
        for (int[] p : ListItem.ranges(s, 0, s.length(), separator)) {
            out.add(s.substring(p[0], p[1]).trim());
        }
        return out;
    }
}
