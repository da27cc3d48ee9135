#!/usr/bin/env bash
# Overhead per point of the Spark engine (embedded, local[2]) against the local engine with 2
# workers on the same spec (docs/scaling.md, "Spark overhead per point"), from each sweep's own
# timing (sweep.json's wall_s: Spark's start-up before the first point is left out, the first
# jobs' class loading is in), alternated, with a check that both wrote the same values.
# Usage: bench/sweep-spark-overhead.sh [SPEC] [ROUNDS]   (default docs/examples/sweep-cube-16.json, 2)
set -euo pipefail
# shellcheck source=bench/sweep-lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/sweep-lib.sh"
bench_setup docs/examples/sweep-cube-16.json 2 sweep-spark "$@"
run() { # out-dir, engine args...
  local d=$1; shift
  rm -rf "$d"
  "$ROOT/tensim" sweep --spec "$SPEC" --out "$d" "$@" >/dev/null 2>"$d.err" \
    || { echo "sweep into $d failed (see $d.err)" >&2; exit 1; }
}
"$ROOT/tensim" sweep --help >/dev/null; "$ROOT/tensim" sweep --engine spark --help >/dev/null # builds both
echo "# bench/sweep-spark-overhead.sh $SPEC $ROUNDS  $(date -u)  $(nproc) cores" | tee -a "$OUT/log.txt"
for r in $(seq 1 "$ROUNDS"); do
  t=$(date -u +%H:%M:%S); l=$(load)
  run "$OUT/local" --engine local --workers 2
  run "$OUT/spark" --engine spark --master 'local[2]'
  python3 - "$OUT" "$r" "$t" "$l" "$(load)" <<'PY' | tee -a "$OUT/log.txt"
import csv, json, sys
out, r, t, l0, l1 = sys.argv[1:]
d = {k: json.load(open(f"{out}/{k}/sweep.json")) for k in ("local", "spark")}
rows = {k: {row["point"]: row for row in csv.DictReader(open(f"{out}/{k}/results.csv"))} for k in d}
skip = {"wall_s", "cpu_s"}
same = rows["local"].keys() == rows["spark"].keys() and all(
    {c: v for c, v in rows["local"][p].items() if c not in skip} == {c: v for c, v in rows["spark"][p].items() if c not in skip}
    for p in rows["local"])
n = d["local"]["ran"]
print(f"round {r} {t} load {l0} -> {l1}: {n} points, wall local {d['local']['wall_s']:.2f} s, "
      f"spark {d['spark']['wall_s']:.2f} s: {(d['spark']['wall_s'] - d['local']['wall_s']) / n:+.3f} s per point; "
      f"process cpu {d['local']['process_cpu_s']:.1f} / {d['spark']['process_cpu_s']:.1f} s; "
      f"results identical: {'yes' if same else 'NO'}")
PY
done
