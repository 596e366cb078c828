package org.parpe.core.expr;

import java.util.Collection;
import org.parpe.core.text.Message;
import org.parpe.core.text.Msg;

/** "Did you mean" suggestions by edit distance. */
public final class Names {
    private Names() {
    }

    /** {@code " (did you mean 'x'?)"} for the closest candidate, or no text ({@link Message#EMPTY}). */
    public static Message suggest(String name, Collection<String> candidates) {
        return suggest(name, candidates, "");
    }

    /** As {@link #suggest(String, Collection)}, writing the suggestion with {@code prefix}. */
    public static Message suggest(String name, Collection<String> candidates, String prefix) {
        String best = closest(name, candidates);
        return best == null ? Message.EMPTY : Message.of(Msg.DID_YOU_MEAN, prefix + best);
    }

    /** The candidate closest to {@code name} if it is close enough, else {@code null}. */
    public static String closest(String name, Collection<String> candidates) {
        String best = null;
        int bestD = Integer.MAX_VALUE;
        int limit = Math.max(1, Math.min(3, name.length() / 3 + 1));
        for (String c : candidates) {
            if (c.equals(name)) {
                continue;
            }
            int d = distance(name.toLowerCase(java.util.Locale.ROOT), c.toLowerCase(java.util.Locale.ROOT));
            if (d < bestD && d <= limit) {
                best = c;
                bestD = d;
            }
        }
        return best;
    }

    private static int distance(String a, String b) {
        int[] prev = new int[b.length() + 1];
        int[] cur = new int[b.length() + 1];
        for (int j = 0; j <= b.length(); j++) {
            prev[j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            cur[0] = i;
            for (int j = 1; j <= b.length(); j++) {
                int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
                cur[j] = Math.min(Math.min(cur[j - 1] + 1, prev[j] + 1), prev[j - 1] + cost);
            }
            int[] t = prev;
            prev = cur;
            cur = t;
        }
        return prev[b.length()];
    }
}
