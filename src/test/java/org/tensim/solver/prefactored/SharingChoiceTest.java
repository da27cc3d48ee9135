package org.tensim.solver.prefactored;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * {@link SharingChoice}: the fixed policies, and the measured one measuring each form first, then using the
 * faster and trying the other once every {@link SharingChoice#PROBE_PERIOD} calls, following a change.
 */
class SharingChoiceTest {
    @Test
    void fixedPoliciesDoNotMeasure() {
        SharingChoice never = new SharingChoice(KernelSharing.NEVER);
        SharingChoice always = new SharingChoice(KernelSharing.ALWAYS);
        for (int i = 0; i < 100; i++) {
            assertFalse(never.share());
            assertTrue(always.share());
            always.record(true, 1_000_000); // slow: still shared
        }
    }

    /** Calls that share among {@code calls}, each timed as {@code sharedNs} or {@code serialNs}. */
    private static int shared(SharingChoice c, int calls, long sharedNs, long serialNs) {
        int n = 0;
        for (int i = 0; i < calls; i++) {
            boolean s = c.share();
            c.record(s, s ? sharedNs : serialNs);
            n += s ? 1 : 0;
        }
        return n;
    }

    @Test
    void measuredPolicyUsesTheFasterFormAndFollowsAChange() {
        SharingChoice c = new SharingChoice(KernelSharing.MEASURED);
        assertTrue(c.share(), "shared first");
        c.record(true, 100);
        assertFalse(c.share(), "then the calling thread alone");
        c.record(false, 200);
        int calls = 20 * SharingChoice.PROBE_PERIOD;
        assertEquals(calls - 20, shared(c, calls, 100, 200), "shared but for one probe in each period");
        // The other core becomes busy: sharing now costs more; the probes of the calling thread see it.
        int now = shared(c, calls, 400, 200);
        assertTrue(now < 2 * 20 + 10, "mostly on the calling thread once measured slower: " + now + " of " + calls);
        assertEquals(200, c.averageNanos(false), 1e-9);
    }
}
