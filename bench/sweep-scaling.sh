#!/usr/bin/env bash
# Sweep throughput of the local engine with 2 workers against 1 (docs/scaling.md, "Local throughput"),
# each from the sweep's own timing (sweep.json: points_per_s, which leaves out the JVM's start-up),
# beside the machine's own ceiling for the same work measured in the same round: two separate JVMs,
# each running the whole spec with 1 worker at the same time. Two JVMs share nothing but the machine
# (cores, caches, memory bandwidth), so their ratio is what any engine could get here; 2 workers
# falling short of it would be the engine's, matching it the machine's.
# Usage: bench/sweep-scaling.sh [SPEC] [ROUNDS]   (default docs/examples/sweep-diaphragm-bench.json, 3)
# Each round runs the spec four times (1 worker, 2 workers, 2 JVMs at once): about 4 x 16 x 0.8 s.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SPEC=$(realpath "${1:-$ROOT/docs/examples/sweep-diaphragm-bench.json}")
ROUNDS=${2:-3}
OUT="$ROOT/out/perf/sweep-scaling"
mkdir -p "$OUT"
"$ROOT/tensim" --help >/dev/null # builds once, outside the timed runs
load() { cut -d' ' -f1-3 /proc/loadavg; }
log() { echo "$*" | tee -a "$OUT/log.txt"; }
sweep() { # out-dir, workers
  rm -rf "$1"
  "$ROOT/tensim" sweep --spec "$SPEC" --workers "$2" --out "$1" >/dev/null 2>&1 \
    || { echo "sweep into $1 failed; rerun: $ROOT/tensim sweep --spec $SPEC --workers $2 --out $1" >&2; exit 1; }
}
field() { # dir, key
  python3 -c "import json,sys; print(json.load(open(sys.argv[1] + '/sweep.json'))[sys.argv[2]])" "$1" "$2"
}
ratio() { python3 -c "import sys; print('%.2f' % (float(sys.argv[1]) / float(sys.argv[2])))" "$1" "$2"; }
log "# bench/sweep-scaling.sh $SPEC $ROUNDS  $(date -u)  $(nproc) cores"
log "# columns: round, UTC, load before, points/s with 1 worker, 2 workers, 2 JVMs x 1 worker (sum),"
log "#          2-worker ratio, 2-JVM ratio, mean point wall s (1 worker / 2 workers), cores obtained by 2 workers"
for r in $(seq 1 "$ROUNDS"); do
  t=$(date -u +%H:%M:%S); l=$(load)
  sweep "$OUT/w1" 1
  sweep "$OUT/w2" 2
  sweep "$OUT/jvm-a" 1 & a=$!
  sweep "$OUT/jvm-b" 1 & b=$!
  wait $a; wait $b
  p1=$(field "$OUT/w1" points_per_s); p2=$(field "$OUT/w2" points_per_s)
  pj=$(python3 -c "import sys; print(round(float(sys.argv[1]) + float(sys.argv[2]), 4))" \
    "$(field "$OUT/jvm-a" points_per_s)" "$(field "$OUT/jvm-b" points_per_s)")
  log "round $r  $t  load $l  1w $p1  2w $p2  2jvm $pj  ratio-2w $(ratio "$p2" "$p1")  ratio-2jvm $(ratio "$pj" "$p1")" \
    " point-wall $(field "$OUT/w1" mean_point_wall_s)/$(field "$OUT/w2" mean_point_wall_s)" \
    " cores-2w $(field "$OUT/w2" cores_obtained)"
done
log "# done $(date -u +%H:%M:%S), load $(load)"
