#!/usr/bin/env bash
# Measures the GUI on the diaphragm at the paper's resolution under Xvfb (docs/gui.md, "Real time at
# the paper's resolution"): `./tensim gui --run-for S`, paced (as a user sees it) and unpaced (the
# headroom), between two headless runs of the same integrator and step as a reference of the
# machine's speed at that moment (the machine is shared: compare ratios, not raw figures).
# Usage: bench/gui-realtime.sh [SECONDS]   (default 60; takes about 2 x SECONDS + 2 minutes)
# GUI_ARGS and HEADLESS_ARGS choose the configuration; the defaults are the GUI's (bdf2 at 25 ms, as --realtime).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
S=${1:-60}
GUI_ARGS=${GUI_ARGS:-"--scene diaphragm"}
HEADLESS_ARGS=${HEADLESS_ARGS:-"--realtime"}
OUT=out/perf/gui-realtime
mkdir -p "$OUT"
CFG=$(mktemp -d)
trap 'rm -rf "$CFG"' EXIT
log() { echo "$*" | tee -a "$OUT/log.txt"; }
headless() { # label
  log "== $1 $(date -u +%H:%M:%S) $(uptime | sed 's/.*load/load/')"
  # shellcheck disable=SC2086
  ./tensim diaphragm $HEADLESS_ARGS --seconds 1.5 --vtk-per-cycle 0 --out "$OUT/headless" | tail -1 | tee -a "$OUT/log.txt"
}
gui() { # label, extra args
  local label=$1; shift
  log "== $label $(date -u +%H:%M:%S) $(uptime | sed 's/.*load/load/')"
  # shellcheck disable=SC2086
  ./tensim gui $GUI_ARGS --fresh --config-dir "$CFG" --run-for "$S" "$@" 2>/dev/null | tail -1 | tee -a "$OUT/log.txt"
}
log "# bench/gui-realtime.sh $S  GUI_ARGS='$GUI_ARGS' HEADLESS_ARGS='$HEADLESS_ARGS'  $(date -u)"
headless "headless reference (before)"
gui "gui paced" 
gui "gui unpaced" --unpaced
headless "headless reference (after)"
