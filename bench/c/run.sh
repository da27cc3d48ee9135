#!/usr/bin/env bash
# Builds and runs the plain C reference of the lattice force pass and steps.
# Usage: bench/c/run.sh [N[,N...]] [T[,T...]] [repeats]    (defaults: 31 1,2 5)
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
OUT="$HERE/../../build/bench-c"
mkdir -p "$OUT"
gcc -O3 -march=native -fopenmp -std=c11 -D_POSIX_C_SOURCE=200809L -o "$OUT/lattice" "$HERE/lattice.c" -lm
exec "$OUT/lattice" "${1:-31}" "${2:-1,2}" "${3:-5}"
