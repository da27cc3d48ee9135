#!/usr/bin/env bash
# Sweep throughput of the local engine with 2 workers against 1 (docs/scaling.md, "Local throughput"),
# each from the sweep's own timing (sweep.json: points_per_s, which leaves out the JVM's start-up),
# beside the machine's own ceiling for the same work measured in the same round: two separate JVMs,
# each running the whole spec with 1 worker at the same time. Two JVMs share nothing but the machine
# (cores, caches, memory bandwidth), each paying its own JIT warm-up: 2 workers in one JVM falling
# short of them would be the engine's, matching them the machine's (and the JIT's, which the sweep.json
# figures printed here separate: CPU per point, and the JVM's CPU besides the points).
# "One core" is measured twice: the whole JVM pinned to one core (`taskset -c 0`, so its JIT compilers and
# GC share that core with the worker: the machine cut to one core), and 1 worker with both cores visible
# (the compilers then run free on the idle second core, a baseline that favours one worker).
# Usage: bench/sweep-scaling.sh [SPEC] [ROUNDS]   (default docs/examples/sweep-diaphragm-bench.json, 3)
# Each round runs the spec five times (1 core, 1 worker, 2 workers, 2 JVMs at once): about 4 x 16 x 2.5 s
# of CPU; odd rounds run them in that order, even rounds in the reverse one, so that a drift of the host's
# speed during a round does not favour one side.
set -euo pipefail
# shellcheck source=bench/sweep-lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/sweep-lib.sh"
bench_setup docs/examples/sweep-diaphragm-bench.json 3 sweep-scaling "$@"
"$ROOT/tensim" --help >/dev/null # builds once, outside the timed runs
log() { echo "$*" | tee -a "$OUT/log.txt"; }
sweep() { # out-dir, workers [command prefix]
  rm -rf "$1"
  ${3:-} "$ROOT/tensim" sweep --spec "$SPEC" --workers "$2" --out "$1" >/dev/null 2>&1 \
    || { echo "sweep into $1 failed; rerun: ${3:-} $ROOT/tensim sweep --spec $SPEC --workers $2 --out $1" >&2; exit 1; }
}
jvms() { sweep "$OUT/jvm-a" 1 & a=$!; sweep "$OUT/jvm-b" 1 & b=$!; wait $a; wait $b; }
log "# bench/sweep-scaling.sh $SPEC $ROUNDS  $(date -u)  $(nproc) cores"
log "# per round: points/s on 1 core (taskset), with 1 worker, 2 workers, 2 JVMs x 1 worker (summed); the"
log "# ratios of 2 workers to 1 core and to 1 worker, and of 2 JVMs to 1 worker;"
log "# CPU s per point (1 core / 1w / 2w / 2 JVMs: a growth with two at once is contention for the shared core"
log "# resources); CPU s of the JVM besides the points (JIT compilers, GC, I/O) and the JIT's own time, 1w / 2w"
for r in $(seq 1 "$ROUNDS"); do
  t=$(date -u +%H:%M:%S); l=$(load)
  if ((r % 2)); then
    sweep "$OUT/c1" 1 "taskset -c 0"; sweep "$OUT/w1" 1; sweep "$OUT/w2" 2; jvms
  else
    jvms; sweep "$OUT/w2" 2; sweep "$OUT/w1" 1; sweep "$OUT/c1" 1 "taskset -c 0"
  fi
  python3 - "$OUT" "$r" "$t" "$l" "$(load)" <<'PY' | tee -a "$OUT/log.txt"
import json, sys
out, r, t, l0, l1 = sys.argv[1:]
d = {k: json.load(open(f"{out}/{k}/sweep.json")) for k in ("c1", "w1", "w2", "jvm-a", "jvm-b")}
pc, p1, p2 = d["c1"]["points_per_s"], d["w1"]["points_per_s"], d["w2"]["points_per_s"]
pj = d["jvm-a"]["points_per_s"] + d["jvm-b"]["points_per_s"]
cpu = lambda k: d[k]["sum_point_cpu_s"] / d[k]["ran"]
other = lambda k: d[k]["process_cpu_s"] - d[k]["sum_point_cpu_s"]
print(f"round {r} {t} load {l0} -> {l1}: points/s 1core {pc:.3f} 1w {p1:.3f} 2w {p2:.3f} 2jvm {pj:.3f}; "
      f"ratio 2w/1core {p2 / pc:.2f} 2w/1w {p2 / p1:.2f} 2jvm/1w {pj / p1:.2f}; cpu/point 1core "
      f"{cpu('c1'):.3f} / {cpu('w1'):.3f} / {cpu('w2'):.3f} / "
      f"{(cpu('jvm-a') + cpu('jvm-b')) / 2:.3f} s; other cpu {other('w1'):.2f} / {other('w2'):.2f} s, "
      f"jit {d['w1']['jit_compile_s']:.2f} / {d['w2']['jit_compile_s']:.2f} s; cores obtained 2w "
      f"{d['w2']['cores_obtained']:.2f}")
PY
done
log "# done $(date -u +%H:%M:%S), load $(load)"
