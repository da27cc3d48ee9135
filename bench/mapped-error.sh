#!/usr/bin/env bash
# The mapped diaphragm's error against the converged 43-ring run over one inspiration (docs/gui.md, "Mechanics
# coarser than the drawn mesh"): RK2 on the 43-ring mesh (the reference), `diaphragm --realtime` (bdf2 at 25 ms, the
# mechanics at the pick's rings carrying the 43-ring mesh) and `diaphragm --realtime --rings 43` (bdf2 at 25 ms,
# unmapped), their displacements on the 43-ring nodes every 50 ms. Prints the relative RMS error at end-inspiration
# and at the worst moment (the largest RMS difference over the samples over the reference's largest RMS
# displacement, as `diaphragm realtime-study` measures it): mapped against RK2 (the coarse model and the large step
# together), unmapped bdf2 against RK2 (the large step) and mapped against unmapped bdf2 (the coarse model).
# Usage: bench/mapped-error.sh   (RK2 at 43 rings takes 10-30 minutes on a shared 2-core machine)
# Another scene: SCENE_ARGS (options of every run), REF_ARGS (the reference's solver; default RK2), MAPPED_ARGS
# (default --realtime), FULL_ARGS (default --realtime --rings 43) and OUT. The thorax (docs/thorax.md, "Mapped
# mechanics"): SCENE_ARGS="--mesh ../shared/meshes/bodyparts3d/diaphragm-FJ3131-dec28k-mm.obj --units mm --thorax
# ../shared/meshes/thorax" REF_ARGS="--integrator bdf2-contact --dt 0.005" MAPPED_ARGS="--realtime --coarse-edge 8"
# FULL_ARGS=--realtime OUT=out/perf/thorax-mapped-error bench/mapped-error.sh
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
OUT=${OUT:-out/perf/mapped-error}
read -r -a SCENE <<< "${SCENE_ARGS:-}"
read -r -a REF <<< "${REF_ARGS:-}"
read -r -a MAPPED <<< "${MAPPED_ARGS:---realtime}"
read -r -a FULL <<< "${FULL_ARGS:---realtime --rings 43}"
mkdir -p "$OUT"
TI=1.3333333333
TIMES=$(python3 -c "print(','.join([f'{0.05*k:.2f}' for k in range(1, 27)] + ['$TI']))")
run() { # label, args
  local label=$1; shift
  echo "== $label $(date -u +%H:%M:%S) $(uptime | sed 's/.*load/load/')" | tee -a "$OUT/log.txt"
  ./tensim diaphragm "${SCENE[@]}" "$@" --seconds "$TI" --vtk-per-cycle 0 --csv-times "$TIMES" --overwrite --out "$OUT/$label" \
    | tail -1 | python3 -c "import json,sys; s=json.loads(sys.stdin.read()); print(json.dumps({k: s.get(k) for k in
      ['diaphragm_nodes', 'drawn_nodes', 'mechanical_nodes', 'integrator', 'dt_s', 'realtime_factor', 'load_average',
       'right_dome_descent_mm', 'left_dome_descent_mm', 'max_penetration_past_rest_mm', 'resolution_pick']}))" | tee -a "$OUT/log.txt"
}
[ "${SKIP_REFERENCE:-0}" = 1 ] || run rk2 "${REF[@]}"
run mapped "${MAPPED[@]}"
run full-bdf2 "${FULL[@]}"
python3 - "$OUT" <<'PY' | tee -a "$OUT/log.txt"
import csv, math, sys
out = sys.argv[1]
def fields(label):
    by = {}
    with open(f"{out}/{label}/displacements.csv") as f:
        for r in csv.DictReader(f):
            by.setdefault(float(r["t_s"]), []).append((float(r["ux_m"]), float(r["uy_m"]), float(r["uz_m"]),
                                                       float(r["x_m"]) - float(r["ux_m"])))
    return [by[t] for t in sorted(by)], sorted(by)
ref, times = fields("rk2")
def errors(a, b):
    amp = max(math.sqrt(sum(u[0]**2 + u[1]**2 + u[2]**2 for u in s)) for s in b)
    worst, at = 0, 0
    for k, (sa, sb) in enumerate(zip(a, b)):
        assert len(sa) == len(sb), (len(sa), len(sb))
        e = math.sqrt(sum(sum((x[i] - y[i])**2 for i in range(3)) for x, y in zip(sa, sb))) / amp
        if e > worst:
            worst, at = e, times[k]
    end = math.sqrt(sum(sum((x[i] - y[i])**2 for i in range(3)) for x, y in zip(a[-1], b[-1]))) / math.sqrt(
        sum(u[0]**2 + u[1]**2 + u[2]**2 for u in b[-1]))
    return end, worst, at
mapped, _ = fields("mapped")
full, _ = fields("full-bdf2")
for name, a, b in [("mapped vs the reference (total)", mapped, ref),
                   ("unmapped vs the reference (large step)", full, ref),
                   ("mapped vs unmapped (coarse model)", mapped, full)]:
    e, w, t = errors(a, b)
    print(f"{name}: end-inspiration {100*e:.2f} %, worst {100*w:.2f} % at {t:.2f} s")
PY
