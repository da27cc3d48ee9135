# Sourced by bench/sweep-scaling.sh and bench/sweep-spark-overhead.sh: the project folder, the spec
# and rounds (the caller's arguments or its defaults), the output folder, and the load average.
# Usage: bench_setup DEFAULT-SPEC DEFAULT-ROUNDS OUT-NAME "$@"
bench_setup() {
  ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  SPEC=$(realpath "${4:-$ROOT/$1}")
  ROUNDS=${5:-$2}
  OUT="$ROOT/out/perf/$3"
  mkdir -p "$OUT"
}
load() { cut -d' ' -f1-3 /proc/loadavg; }
