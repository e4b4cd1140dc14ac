#!/usr/bin/env bash
# The main job of `make demo` (called with the build directory as $1): simulate the paper's
# staircase scene (balls thrown down a staircase) on the native backend if this build has it,
# else on the Bullet reference, and say where the output landed.
set -euo pipefail
build=${1:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
vroc="$build/bin/vroc"
[ -x "$vroc" ] || vroc="$root/$build/bin/vroc"
if [ ! -x "$vroc" ]; then
  echo "vroc: error: $build/bin/vroc not found; run 'make build' first" >&2
  exit 2
fi

if "$vroc" backends --names | grep -qx native; then backend=native; else backend=bullet; fi
out="$root/runs/staircase-$backend-demo"

echo "vroc demo: the staircase scene (scenes/staircase.json) on the '$backend' backend"
"$vroc" backends
"$vroc" run "$root/scenes/staircase.json" --backend "$backend" --duration 5 --out "$out"
echo
echo "Output (absolute path): $out"
echo "  trajectory.csv  every virtual body's pose and velocity per frame"
echo "  events.csv      every collision: time, bodies, contact point, normal, impulse"
echo "  run.json        settings, timings (per-step p50/p90/p99), state_hash, build facts"

# The comparison (tools/harness, docs/harness.md): the same scene on every backend of this build.
backends=$("$vroc" backends --names | paste -sd, -)
compare_out="$root/runs/staircase-compare-demo"
echo
echo "vroc demo: comparing the staircase scene on: $backends"
"$vroc" compare "$root/scenes/staircase.json" --backends "$backends" --duration 5 --out "$compare_out"
echo "Comparison report: $compare_out/report.html"
