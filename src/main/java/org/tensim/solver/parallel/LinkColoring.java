package org.tensim.solver.parallel;

/**
 * A colouring of the rigid links such that no two links of one colour share a node
 * (a proper edge colouring of the link graph). Links of one colour are independent:
 * their Gauss-Seidel corrections touch disjoint nodes, so they can be applied in any
 * order, or in parallel, with identical results.
 *
 * <p>Greedy in authored order: each link takes the smallest colour not yet used at
 * either of its ends, so at most 2d - 1 colours for a largest node degree d (chains
 * and the tensegrity cube's links need 2 or 3).
 */
public final class LinkColoring {
    private final int[] colour;
    private final int colours;

    private LinkColoring(int[] colour, int colours) {
        this.colour = colour;
        this.colours = colours;
    }

    /** Colours the links (la[i], lb[i]) of a graph with {@code n} nodes. */
    public static LinkColoring greedy(int n, int[] la, int[] lb) {
        final int m = la.length;
        // Links incident to each node (CSR), filled as links get coloured.
        int[] start = new int[n + 1];
        for (int i = 0; i < m; i++) {
            start[la[i] + 1]++;
            start[lb[i] + 1]++;
        }
        for (int i = 0; i < n; i++) {
            start[i + 1] += start[i];
        }
        int[] fill = java.util.Arrays.copyOf(start, n);
        int[] incident = new int[start[n]];
        int[] colour = new int[m];
        boolean[] used = new boolean[2 * m + 2];
        int colours = 0;
        for (int i = 0; i < m; i++) {
            int a = la[i];
            int b = lb[i];
            for (int p = start[a]; p < fill[a]; p++) {
                used[colour[incident[p]]] = true;
            }
            for (int p = start[b]; p < fill[b]; p++) {
                used[colour[incident[p]]] = true;
            }
            int c = 0;
            while (used[c]) {
                c++;
            }
            colour[i] = c;
            colours = Math.max(colours, c + 1);
            for (int p = start[a]; p < fill[a]; p++) {
                used[colour[incident[p]]] = false;
            }
            for (int p = start[b]; p < fill[b]; p++) {
                used[colour[incident[p]]] = false;
            }
            incident[fill[a]++] = i;
            incident[fill[b]++] = i;
        }
        return new LinkColoring(colour, colours);
    }

    /** Number of colours. */
    public int colours() {
        return colours;
    }

    /** Colour of link i, in [0, colours()). */
    public int colour(int link) {
        return colour[link];
    }

    /** Number of links coloured. */
    public int links() {
        return colour.length;
    }
}
