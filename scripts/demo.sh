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
"$vroc" run "$root/scenes/staircase.json" --backend "$backend" --duration 5 --out "$out" --sound "$out/impacts.wav"
echo
echo "Output (absolute path): $out"
echo "  trajectory.csv  every virtual body's pose and velocity per frame"
echo "  events.csv      every collision: time, bodies, contact point, normal, impulse"
echo "  impacts.wav     the collisions as sound (modal synthesis per material; impacts_events.csv beside it)"
echo "  run.json        settings, timings (per-step p50/p90/p99), state_hash, build facts"
echo "  view.html       the run's 3D replay for a browser (docs/viewer.md)"

# The see-through display loop (tools/play, docs/hmd.md): a tracked real notepad, driven by a
# device plugin, bats a row of balls; frames rendered offscreen, impacts as sound.
play_out="$root/runs/tracked-notepad-play-demo"
echo
echo "vroc demo: vroc play, a tracked notepad (scenes/tracked_notepad.json) on '$backend'"
"$vroc" play "$root/scenes/tracked_notepad.json" --backend "$backend" --frames 90 --width 320 --height 240 \
  --out "$play_out" --sound "$play_out/impacts.wav"
echo "Frames, play.json and impacts.wav: $play_out"

# The comparison (tools/harness, docs/harness.md): the same scene on every backend of this build.
backends=$("$vroc" backends --names | paste -sd, -)
compare_out="$root/runs/staircase-compare-demo"
echo
echo "vroc demo: comparing the staircase scene on: $backends"
"$vroc" compare "$root/scenes/staircase.json" --backends "$backends" --duration 5 --out "$compare_out"
echo "Comparison report: $compare_out/report.html"
