#!/usr/bin/env bash
# Per-step wall time of the native backend against Bullet on every scene in scenes/ (issue 4,
# "Speed targets": native <= 0.5 x Bullet). Runs `vroc run` on each scene with each backend,
# reads step_wall_time_us.p50 from run.json, prints a table and writes
# docs/benchmarks/scene_ratios_<machine>.csv (scene,native_p50_us,bullet_p50_us,ratio,native_steps,bullet_steps,
# load_1min: the 1-minute load average after the scene's two runs, since wall times depend on it).
#
# Usage: scripts/measure_scene_ratios.sh [BUILD_DIR] [DURATION_S]
#   BUILD_DIR   default build-perf (the vroc binary is BUILD_DIR/bin/vroc)
#   DURATION_S  simulated seconds per run, default 5 (icollide.json: 2, it is the heavy one)
# Environment: MACHINE names the CSV (default: hostname); SCENES overrides the scene list.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build-perf}
duration=${2:-5}
vroc="$build_dir/bin/vroc"
[[ -x "$vroc" ]] || { echo "measure_scene_ratios: $vroc not found (build the vroc target first)" >&2; exit 2; }
machine=${MACHINE:-$(hostname -s)}
out_csv="docs/benchmarks/scene_ratios_${machine}.csv"
runs=$(mktemp -d /tmp/vroc-scene-ratios.XXXXXX)
trap 'rm -rf "$runs"' EXIT
scenes=${SCENES:-$(ls scenes/*.json)}
# No view.html per run (its cost is not the engine's), when this build writes one.
no_view=()
run_help=$("$vroc" run --help 2>&1 || true)
[[ $run_help == *--no-view* ]] && no_view=(--no-view)

p50_and_steps() {   # run.json -> "p50 steps"
    python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); print("%.3f" % r["step_wall_time_us"]["p50"], r["steps"])' "$1"
}

echo "scene,native_p50_us,bullet_p50_us,ratio,native_steps,bullet_steps,load_1min" > "$out_csv.tmp"
printf '%-14s %14s %14s %8s %7s %7s  %s\n' scene native_p50_us bullet_p50_us ratio n_steps b_steps load
for scene in $scenes; do
    name=$(basename "$scene" .json)
    d=$duration
    [[ "$name" == icollide ]] && d=${ICOLLIDE_DURATION:-2}
    declare -A p50=() steps=()
    for backend in native bullet; do
        extra=()   # both on one core: Bullet is single-threaded, native is told so
        [[ $backend == native ]] && extra=(--set native.threads=1)
        if "$vroc" run "$scene" --backend "$backend" --duration "$d" "${extra[@]}" "${no_view[@]}" \
               --out "$runs/$name-$backend" -q 2>"$runs/$name-$backend.err"; then
            read -r p50[$backend] steps[$backend] < <(p50_and_steps "$runs/$name-$backend/run.json")
        else
            echo "measure_scene_ratios: $name on $backend failed: $(head -c 300 "$runs/$name-$backend.err")" >&2
            p50[$backend]=nan; steps[$backend]=0
        fi
    done
    ratio=$(python3 -c 'import sys; n,b=sys.argv[1:]; print("nan" if "nan" in (n,b) or float(b)==0 else "%.3f"%(float(n)/float(b)))' "${p50[native]}" "${p50[bullet]}")
    load=$(cut -d' ' -f1 /proc/loadavg)
    printf '%-14s %14s %14s %8s %7s %7s  %s\n' "$name" "${p50[native]}" "${p50[bullet]}" "$ratio" "${steps[native]}" "${steps[bullet]}" "$load"
    echo "$name,${p50[native]},${p50[bullet]},$ratio,${steps[native]},${steps[bullet]},$load" >> "$out_csv.tmp"
    unset p50 steps
done
mv "$out_csv.tmp" "$out_csv"
echo "wrote $out_csv (load average at the end: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'))"
