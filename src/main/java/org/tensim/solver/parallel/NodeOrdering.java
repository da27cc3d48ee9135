package org.tensim.solver.parallel;

import java.util.Arrays;

/**
 * Bandwidth-reducing node orders for the force pass: reverse Cuthill-McKee (RCM)
 * over the spring graph, and the measure used to decide whether it pays.
 *
 * <p>Why: the spring loop reads the positions of both ends of each spring and adds
 * to both ends' forces. When the ends of consecutive springs are close in memory,
 * those accesses hit lines already in L1/L2; a mesh whose node ids were handed out
 * in an arbitrary order (a shuffled import) makes nearly every access a miss. RCM
 * numbers nodes breadth-first from a peripheral node, so that neighbours get
 * nearby numbers ({@link #meanSpan} small).
 *
 * <p>An order is an array {@code order} with {@code order[j]} = the authored node id
 * at internal position j; its inverse {@code rank[id] = j}.
 */
public final class NodeOrdering {
    private NodeOrdering() {
    }

    /**
     * Reverse Cuthill-McKee order of the graph with {@code n} nodes and the edges
     * (ea[i], eb[i]). Components are numbered one after the other; each starts from a
     * pseudo-peripheral node (George-Liu), neighbours are visited by increasing degree.
     * Deterministic. O(n + m log d) time.
     */
    public static int[] reverseCuthillMcKee(int n, int[] ea, int[] eb) {
        int[] start = new int[n + 1];
        for (int i = 0; i < ea.length; i++) {
            start[ea[i] + 1]++;
            start[eb[i] + 1]++;
        }
        for (int i = 0; i < n; i++) {
            start[i + 1] += start[i];
        }
        int[] adj = new int[start[n]];
        int[] fill = Arrays.copyOf(start, n);
        for (int i = 0; i < ea.length; i++) {
            adj[fill[ea[i]]++] = eb[i];
            adj[fill[eb[i]]++] = ea[i];
        }
        final int[] degree = new int[n];
        for (int i = 0; i < n; i++) {
            degree[i] = start[i + 1] - start[i];
        }
        // Neighbour lists sorted by degree (ties by id), once, so the BFS visits them in order.
        for (int i = 0; i < n; i++) {
            sortByDegree(adj, start[i], start[i + 1], degree);
        }

        int[] order = new int[n];
        int[] level = new int[n];
        Arrays.fill(level, -1);
        boolean[] visited = new boolean[n];
        int count = 0;
        int[] byDegree = new int[n];
        for (int i = 0; i < n; i++) {
            byDegree[i] = i;
        }
        sortByDegree(byDegree, 0, n, degree);
        for (int seed : byDegree) {
            if (visited[seed]) {
                continue;
            }
            int root = peripheral(seed, start, adj, degree, level, order, count);
            // Breadth-first numbering from root (order[count..] is the queue).
            int head = count;
            order[count++] = root;
            visited[root] = true;
            while (head < count) {
                int u = order[head++];
                for (int p = start[u]; p < start[u + 1]; p++) {
                    int w = adj[p];
                    if (!visited[w]) {
                        visited[w] = true;
                        order[count++] = w;
                    }
                }
            }
        }
        // Reverse: Cuthill-McKee's order reversed has the same bandwidth and less fill.
        for (int i = 0, j = n - 1; i < j; i++, j--) {
            int tmp = order[i];
            order[i] = order[j];
            order[j] = tmp;
        }
        return order;
    }

    /**
     * George-Liu: repeat a BFS from the lowest-degree node of the deepest level while
     * the depth grows. {@code level} is scratch (-1 = not reached, reset on return);
     * {@code queue[queueFrom..]} is scratch too (the final numbering overwrites it).
     */
    private static int peripheral(int seed, int[] start, int[] adj, int[] degree, int[] level, int[] queue,
            int queueFrom) {
        int root = seed;
        int depth = -1;
        int tail = queueFrom;
        for (int round = 0; round < 8; round++) {
            for (int q = queueFrom; q < tail; q++) {
                level[queue[q]] = -1;
            }
            int head = queueFrom;
            tail = queueFrom;
            queue[tail++] = root;
            level[root] = 0;
            int maxLevel = 0;
            while (head < tail) {
                int u = queue[head++];
                for (int p = start[u]; p < start[u + 1]; p++) {
                    int w = adj[p];
                    if (level[w] < 0) {
                        level[w] = level[u] + 1;
                        maxLevel = Math.max(maxLevel, level[w]);
                        queue[tail++] = w;
                    }
                }
            }
            if (maxLevel <= depth) {
                break;
            }
            depth = maxLevel;
            int best = root;
            for (int q = queueFrom; q < tail; q++) {
                int u = queue[q];
                if (level[u] == maxLevel && (best == root || degree[u] < degree[best])) {
                    best = u;
                }
            }
            if (best == root) {
                break;
            }
            root = best;
        }
        for (int q = queueFrom; q < tail; q++) {
            level[queue[q]] = -1;
        }
        return root;
    }

    private static void sortByDegree(int[] a, int from, int to, int[] degree) {
        // Insertion sort: neighbour lists are short; the full list is sorted once at setup.
        if (to - from > 64) {
            Integer[] boxed = new Integer[to - from];
            for (int i = from; i < to; i++) {
                boxed[i - from] = a[i];
            }
            Arrays.sort(boxed, (p, q) -> degree[p] != degree[q] ? Integer.compare(degree[p], degree[q])
                    : Integer.compare(p, q));
            for (int i = from; i < to; i++) {
                a[i] = boxed[i - from];
            }
            return;
        }
        for (int i = from + 1; i < to; i++) {
            int v = a[i];
            int j = i - 1;
            while (j >= from && (degree[a[j]] > degree[v] || (degree[a[j]] == degree[v] && a[j] > v))) {
                a[j + 1] = a[j];
                j--;
            }
            a[j + 1] = v;
        }
    }

    /** The inverse of a permutation: {@code rank[order[j]] = j}. */
    public static int[] invert(int[] order) {
        int[] rank = new int[order.length];
        for (int j = 0; j < order.length; j++) {
            rank[order[j]] = j;
        }
        return rank;
    }

    /**
     * Mean distance |rank[a] - rank[b]| between the ends of the edges, in nodes: the
     * locality measure of an order ({@code rank == null}: the authored order).
     */
    public static double meanSpan(int[] ea, int[] eb, int[] rank) {
        if (ea.length == 0) {
            return 0;
        }
        double sum = 0;
        for (int i = 0; i < ea.length; i++) {
            int a = rank == null ? ea[i] : rank[ea[i]];
            int b = rank == null ? eb[i] : rank[eb[i]];
            sum += Math.abs(a - b);
        }
        return sum / ea.length;
    }

    /**
     * Edge indices sorted by the internal position of their lower end (stable: edges
     * with the same lower end keep their authored order), so that the loop walks the
     * nodes forwards. Counting sort, O(n + m).
     */
    public static int[] edgesByLowerEnd(int n, int[] ea, int[] eb, int[] rank) {
        int[] count = new int[n + 1];
        for (int i = 0; i < ea.length; i++) {
            count[lower(ea[i], eb[i], rank) + 1]++;
        }
        for (int i = 0; i < n; i++) {
            count[i + 1] += count[i];
        }
        int[] out = new int[ea.length];
        for (int i = 0; i < ea.length; i++) {
            out[count[lower(ea[i], eb[i], rank)]++] = i;
        }
        return out;
    }

    private static int lower(int a, int b, int[] rank) {
        return rank == null ? Math.min(a, b) : Math.min(rank[a], rank[b]);
    }
}
