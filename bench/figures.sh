#!/usr/bin/env bash
# Regenerates the figures README.md and docs/ quote, one command each, into out/figures/NAME/.
# Every command writes a summary.json (or JSON lines) with the date, the commit, the core count and the
# load (io.Provenance); this script adds each command line to out/figures/commands.txt and prints, at the
# end, one line per run with those fields. The shared data (../shared/meshes) is used where it is present.
# Takes several hours on a two-core machine (the real-time study and the thorax's are the longest).
# Usage: bench/figures.sh [NAME...]   (no NAME: all of them; e.g. bench/figures.sh cube accuracy)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
OUT=out/figures
SHARED="${TENSIM_SHARED:-$ROOT/../shared}"
BP="$SHARED/meshes/bodyparts3d"
THORAX="$SHARED/meshes/thorax"
mkdir -p "$OUT"
wanted=("$@")
want() { [ ${#wanted[@]} -eq 0 ] || printf '%s\n' "${wanted[@]}" | grep -qx "$1"; }
run() { # name, command... (--out is added)
  local name=$1; shift
  want "$name" || return 0
  echo "== $name: $* --out $OUT/$name ($(date -u +%FT%TZ), load $(cut -d' ' -f1-3 /proc/loadavg))" \
    | tee -a "$OUT/commands.txt"
  "$@" --out "$OUT/$name" > "$OUT/$name.log" 2>&1 || echo "   $name failed: see $OUT/$name.log"
}
run cube ./tensim cube
run accuracy ./tensim accuracy
run accuracy-diaphragm ./tensim accuracy --scene diaphragm
run stability ./tensim stability
run volume-study ./tensim volume-study --cantilever-cells 2,4,8,16 --block-cells 2.5,4.5,8.5,16.5
run volume-study-sliding ./tensim volume-study --sliding-root
run diaphragm ./tensim diaphragm
run diaphragm-paper ./tensim diaphragm --model paper
run resolution ./tensim diaphragm resolution-study --study-rings 14,20,28,43 --no-pick
run realtime ./tensim diaphragm realtime-study
run realtime-setting ./tensim diaphragm --realtime --seconds 8
if [ -f "$BP/diaphragm-FJ3131-dec28k-mm.obj" ]; then
  run bodyparts3d ./tensim diaphragm --mesh "$BP/diaphragm-FJ3131-dec28k-mm.obj" --units mm \
    --boxes "$BP/rib-sternum-bounds-mm.json" --integrator bdf2 --dt 0.005
  if [ -f "$THORAX/parts.json" ]; then
    run thorax ./tensim diaphragm --mesh "$BP/diaphragm-FJ3131-dec28k-mm.obj" --units mm --thorax "$THORAX" \
      --integrator bdf2 --dt 0.005 --seconds 4
    run thorax-resolution ./tensim diaphragm resolution-study --mesh "$BP/diaphragm-FJ3131-dec28k-mm.obj" \
      --units mm --thorax "$THORAX" --integrator bdf2 --dt 0.005 --cells 6,4.5
  fi
else
  echo "== $BP not found: the BodyParts3D and thorax figures are left out" | tee -a "$OUT/commands.txt"
fi
if want perf; then
  echo "== perf: bench/run-all.sh (out/perf)" | tee -a "$OUT/commands.txt"
  bench/run-all.sh > "$OUT/perf.log" 2>&1 || echo "   perf failed: see $OUT/perf.log"
fi
if want gui; then
  echo "== gui: ./tensim gui --fresh --run-for 60" | tee -a "$OUT/commands.txt"
  ./tensim gui --fresh --run-for 60 > "$OUT/gui.log" 2>&1 || echo "   gui failed: see $OUT/gui.log"
fi
# One line per run: when, which commit, how many cores, the load.
for s in "$OUT"/*/summary.json; do
  [ -f "$s" ] || continue
  python3 - "$s" <<'PY' 2>/dev/null || echo "$s"
import json, sys
d = json.load(open(sys.argv[1]))
print(sys.argv[1], d.get("status"), d.get("finished_utc"), d.get("commit"), "cores", d.get("cores"),
      "load", d.get("load_average_1min"))
PY
done
