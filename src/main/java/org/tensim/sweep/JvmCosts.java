package org.tensim.sweep;

import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.util.Map;

/**
 * What the JVM spent besides the points' own threads while a sweep ran, for sweep.json: the
 * process's CPU time, the JIT compilers' time and the garbage collectors' time. On few cores the
 * compilers compete with the workers: with one worker they use an otherwise idle core, with a
 * worker per core they take from the points (docs/scaling.md, "Local throughput").
 *
 * @param processCpuNs CPU time of the whole process so far, ns (-1 when the JVM does not tell)
 * @param compileMs    total time of the JIT compiler threads so far, ms (their elapsed time, summed over
 *                     compilations; -1 when not monitored)
 * @param gcMs         total collection time of all garbage collectors so far, ms
 */
record JvmCosts(long processCpuNs, long compileMs, long gcMs) {
    /** The costs so far. */
    static JvmCosts now() {
        java.lang.management.OperatingSystemMXBean os = ManagementFactory.getOperatingSystemMXBean();
        long cpu = os instanceof com.sun.management.OperatingSystemMXBean s ? s.getProcessCpuTime() : -1;
        java.lang.management.CompilationMXBean jit = ManagementFactory.getCompilationMXBean();
        long compile = jit != null && jit.isCompilationTimeMonitoringSupported() ? jit.getTotalCompilationTime() : -1;
        long gc = 0;
        for (GarbageCollectorMXBean b : ManagementFactory.getGarbageCollectorMXBeans()) {
            gc += Math.max(0, b.getCollectionTime());
        }
        return new JvmCosts(cpu, compile, gc);
    }

    /**
     * Adds, since {@code before}: {@code process_cpu_s} (every thread of the JVM), {@code jit_compile_s}
     * and {@code gc_s}, in seconds (NaN where the JVM does not tell).
     */
    void putSince(JvmCosts before, Map<String, Object> out) {
        out.put("process_cpu_s", processCpuNs < 0 || before.processCpuNs < 0 ? Double.NaN
                : round((processCpuNs - before.processCpuNs) / 1e9));
        out.put("jit_compile_s", compileMs < 0 || before.compileMs < 0 ? Double.NaN
                : round((compileMs - before.compileMs) / 1e3));
        out.put("gc_s", round((gcMs - before.gcMs) / 1e3));
    }

    private static double round(double v) {
        return Math.round(v * 1e4) / 1e4;
    }
}
