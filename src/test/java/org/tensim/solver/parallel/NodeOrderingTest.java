package org.tensim.solver.parallel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.tensim.scene.LatticeScene;
import org.tensim.scene.ShuffledScene;
import org.tensim.solver.SystemState;

class NodeOrderingTest {
    @Test
    void reverseCuthillMcKeeIsAPermutationAndShortensAShuffledMesh() {
        SystemState s = SystemState.compile(ShuffledScene.shuffle(LatticeScene.build(10, 0.1, 1, 1, 0, false), 9));
        int[] order = NodeOrdering.reverseCuthillMcKee(s.nodeCount, s.springA, s.springB);
        int[] sorted = order.clone();
        Arrays.sort(sorted);
        for (int i = 0; i < sorted.length; i++) {
            assertEquals(i, sorted[i]);
        }
        double before = NodeOrdering.meanSpan(s.springA, s.springB, null);
        double after = NodeOrdering.meanSpan(s.springA, s.springB, NodeOrdering.invert(order));
        SystemState lattice = SystemState.compile(LatticeScene.build(10, 0.1, 1, 1, 0, false));
        double grid = NodeOrdering.meanSpan(lattice.springA, lattice.springB, null);
        // As local as the grid's own i-j-k numbering, give or take (and 4x shorter than shuffled).
        assertTrue(after < 1.5 * grid && after < before / 4, before + " -> " + after + " (grid " + grid + ")");
    }

    @Test
    void disconnectedNodesAndComponentsAreAllNumbered() {
        int[] a = {0, 2, 5};
        int[] b = {1, 3, 6};
        int[] order = NodeOrdering.reverseCuthillMcKee(8, a, b);
        int[] sorted = order.clone();
        Arrays.sort(sorted);
        assertArrayEquals(new int[] {0, 1, 2, 3, 4, 5, 6, 7}, sorted);
    }

    @Test
    void edgesByLowerEndIsStable() {
        int[] a = {3, 1, 1, 0, 2};
        int[] b = {2, 2, 0, 2, 1};
        // lower ends 2, 1, 0, 0, 1
        assertArrayEquals(new int[] {2, 3, 1, 4, 0}, NodeOrdering.edgesByLowerEnd(4, a, b, null));
    }
}
