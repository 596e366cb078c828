package org.parpe.serial.bus;

import java.util.List;

/**
 * Which of the wanted modules answered a ping.
 *
 * @param found         module IDs that answered
 * @param missing       addressable IDs that did not answer
 * @param unaddressable IDs above {@link org.parpe.serial.protocol.Protocol#MAX_MODULE_ID}
 */
public record Discovery(List<Integer> found, List<Integer> missing, List<Integer> unaddressable) {

    public Discovery {
        found = List.copyOf(found);
        missing = List.copyOf(missing);
        unaddressable = List.copyOf(unaddressable);
    }

    /** Whether every wanted module answered. */
    public boolean complete() {
        return missing.isEmpty() && unaddressable.isEmpty();
    }

    /** A compact text of IDs, sorted, with runs as ranges: {@code 0..7, 9}. */
    public static String format(int[] ids) {
        StringBuilder b = new StringBuilder();
        int[] s = ids.clone();
        java.util.Arrays.sort(s);
        for (int i = 0; i < s.length; ) {
            int j = i;
            while (j + 1 < s.length && s[j + 1] == s[j] + 1) {
                j++;
            }
            b.append(b.length() == 0 ? "" : ", ").append(s[i]);
            if (j > i) {
                b.append(j > i + 1 ? ".." : ", ").append(s[j]);
            }
            i = j + 1;
        }
        return b.toString();
    }

    /** {@link #format(int[])} of a list. */
    public static String format(List<Integer> ids) {
        return format(ids.stream().mapToInt(Integer::intValue).toArray());
    }
}
