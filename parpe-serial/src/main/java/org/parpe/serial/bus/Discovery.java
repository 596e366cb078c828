package org.parpe.serial.bus;

import java.util.List;

/** How discovery's messages list module IDs ({@code modules 0..7, 9 do not answer}). */
public final class Discovery {
    private Discovery() {
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
