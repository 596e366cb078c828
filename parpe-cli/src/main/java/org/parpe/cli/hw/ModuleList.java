package org.parpe.cli.hw;

import org.parpe.cli.text.CliMsg;
import java.util.Arrays;
import java.util.LinkedHashSet;
import java.util.Set;
import org.parpe.cli.options.UsageException;
import org.parpe.serial.bus.Discovery;
import org.parpe.serial.g1.Protocol;

/** Parses module lists of the command line: {@code 0..7}, {@code 0,2,5}, {@code 0..3,8..9}. */
final class ModuleList {

    private ModuleList() {
    }

    /** The IDs in the order written; {@code option} names the option in messages. */
    static int[] parse(String text, String option) throws UsageException {
        if (text == null || text.isBlank()) {
            throw new UsageException(CliMsg.NEEDS_MODULE_LIST.text(option));
        }
        Set<Integer> ids = new LinkedHashSet<>();
        for (String item : text.split(",", -1)) {
            String s = item.trim();
            int dots = s.indexOf("..");
            int a = id(dots < 0 ? s : s.substring(0, dots), text, option);
            int b = dots < 0 ? a : id(s.substring(dots + 2), text, option);
            for (int i = a; a <= b ? i <= b : i >= b; i += a <= b ? 1 : -1) {
                if (!ids.add(i)) {
                    throw new UsageException(CliMsg.MODULE_TWICE.text(option, i, text));
                }
            }
        }
        return ids.stream().mapToInt(Integer::intValue).toArray();
    }

    /** The same IDs, ascending. */
    static int[] sorted(int[] ids) {
        int[] s = ids.clone();
        Arrays.sort(s);
        return s;
    }

    private static int id(String s, String text, String option) throws UsageException {
        String t = s.trim();
        if (!t.matches("\\d{1,6}")) {
            throw new UsageException(CliMsg.MODULE_LIST_SYNTAX.text(option, text));
        }
        int v = Integer.parseInt(t);
        if (v > Protocol.MAX_MODULE_ID) {
            throw new UsageException(CliMsg.MODULE_ID_RANGE.text(option, Protocol.MAX_MODULE_ID, v));
        }
        return v;
    }

    /** A compact text of IDs: {@code 0..7, 9}. */
    static String format(int[] ids) {
        return Discovery.format(ids);
    }
}
