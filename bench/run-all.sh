#!/usr/bin/env bash
# Runs every measurement quoted in docs/performance.md, one command each, and keeps
# their outputs under out/perf/ (JSON lines, the scaling chart, JMH and C output).
# Takes about 10 minutes on the 2-core machine. Usage: bench/run-all.sh
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
OUT=out/perf
mkdir -p "$OUT"
run() { # name, command...
  local name=$1; shift
  echo "== $name: $*" | tee -a "$OUT/commands.txt"
  "$@" | tee "$OUT/$name.jsonl"
}
uptime | tee "$OUT/load.txt"
run main        ./tensim bench --n 11,21,31 --threads 1,2 --repeats 7
run builtin     ./tensim bench --n 11,21,31 --solver builtin --repeats 7
run symplectic  ./tensim bench --n 31 --threads 1,2 --integrator symplectic-euler --repeats 7
run symplectic-builtin ./tensim bench --n 31 --solver builtin --integrator symplectic-euler --repeats 7
run links       ./tensim bench --n 21,31 --threads 1,2 --links --repeats 5
run diaphragm   ./tensim bench --scene diaphragm --threads 1,2 --repeats 5
run links-builtin ./tensim bench --n 21,31 --solver builtin --links --repeats 5
run shuffled    ./tensim bench --n 31,49 --threads 1 --shuffle --order auto --repeats 5
run shuffled-authored ./tensim bench --n 31,49 --threads 1 --shuffle --order authored --repeats 5
run shuffled-builtin ./tensim bench --n 31,49 --shuffle --solver builtin --repeats 5
run lattice-rcm ./tensim bench --n 31,49 --threads 1 --order rcm --repeats 5
run scaling     ./tensim bench --n 6,8,11,16,21,26,31,41,49 --threads 1,2 --repeats 5 --out "$OUT/scaling"
run c           timeout 600 bench/c/run.sh 11,21,31 1,2 7
echo "== jmh" | tee -a "$OUT/commands.txt"
gradle -q jmh -PjmhArgs='-f 1 -wi 3 -w 1s -i 5 -r 1s -p n=31' 2>&1 | grep -v -E '^(openjdk|OpenJDK)' \
  | tee "$OUT/jmh.txt"
uptime | tee -a "$OUT/load.txt"
