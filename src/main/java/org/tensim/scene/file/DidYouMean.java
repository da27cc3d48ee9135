package org.tensim.scene.file;

import java.util.Collection;
import java.util.Locale;

/** The "did you mean" of a refused word: the nearest accepted word by edit distance (Levenshtein). */
public final class DidYouMean {
    private DidYouMean() {
    }

    /**
     * {@code "; did you mean 'x'?"} for the accepted word nearest to {@code word}, or "" when none is within
     * a third of the word's length (plus one) edits.
     */
    public static String suggest(String word, Collection<String> accepted) {
        String best = null;
        int bestD = Integer.MAX_VALUE;
        for (String a : accepted) {
            int d = distance(word.toLowerCase(Locale.ROOT), a.toLowerCase(Locale.ROOT));
            if (d < bestD) {
                bestD = d;
                best = a;
            }
        }
        return best != null && bestD <= word.length() / 3 + 1 ? "; did you mean '" + best + "'?" : "";
    }

    /** The Levenshtein distance: insertions, deletions and substitutions, each 1. */
    public static int distance(String a, String b) {
        int[] prev = new int[b.length() + 1];
        int[] cur = new int[b.length() + 1];
        for (int j = 0; j <= b.length(); j++) {
            prev[j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            cur[0] = i;
            for (int j = 1; j <= b.length(); j++) {
                int sub = prev[j - 1] + (a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1);
                cur[j] = Math.min(sub, Math.min(prev[j] + 1, cur[j - 1] + 1));
            }
            int[] t = prev;
            prev = cur;
            cur = t;
        }
        return prev[b.length()];
    }
}
