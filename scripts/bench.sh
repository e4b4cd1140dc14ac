#!/usr/bin/env bash
# Runs vroc-bench (the coherent pair query: native V-Clip walk vs Bullet GJK vs libccd) and
# writes docs/benchmarks/coherent_query_<machine>.csv. Usage: scripts/bench.sh [build-dir]
# (`make bench` passes its BUILD_DIR). The machine name is the CPU model from lscpu.
set -euo pipefail
build_dir="${1:-build}"
cd "$(dirname "$0")/.."
cmake --build "$build_dir" --target vroc-bench >/dev/null
machine="$(lscpu | sed -n 's/^Model name:[[:space:]]*//p' | head -1 | tr '[:upper:]' '[:lower:]' | tr -cs 'a-z0-9' '-' | sed 's/-$//')"
machine="${machine:-unknown}-$(nproc)core"
out="docs/benchmarks/coherent_query_${machine}.csv"
mkdir -p docs/benchmarks
"$build_dir/bin/vroc-bench" --benchmark_min_time=0.05 --benchmark_format=csv > "$out.tmp"
mv "$out.tmp" "$out"
echo "vroc: wrote $out"
