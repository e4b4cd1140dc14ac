#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The installed package, used the way someone outside VROC uses it (issue 13; CTest label
# `install`, tests/install/CMakeLists.txt):
#   1. `cmake --install` the build into a temporary prefix, then move the tree (the package must
#      not depend on where it was installed) and check the layout, that native's internals and the
#      test fixtures stayed out, and that no installed file names the build or source tree;
#   2. the installed `vroc` finds its built-in plugins next to itself and runs a shipped scene
#      (first bounce of ball_drop at the closed-form time sqrt(2 h / g));
#   3. a device plugin in C, compiled with `cc $(pkg-config --cflags vroc-plugin) -shared`, is loaded
#      by the installed `vroc` and drives a tracked body: trajectory.csv shows the plugin's pose;
#   4. two C++-only downstream CMake projects: downstream/ (find_package(vroc), vroc::core alone, no
#      MPI looked for) builds, its program passes its own checks (downstream/main.cpp) and its C++
#      SDK plugin loads in the installed `vroc`; downstream_harness/ (COMPONENTS harness
#      backend_native) compares its own backend with native through the harness and compiles every
#      installed header.
# Usage: install_test.sh BUILD_DIR SOURCE_DIR
#   (JOBS=n for the downstream build, default 2; CMAKE=path of cmake, default the one on PATH)
set -euo pipefail

build=$(realpath "$1")
source=$(realpath "$2")
jobs=${JOBS:-2}
cmake=${CMAKE:-cmake}
# Outside the build tree on purpose: a program inside it may also search the build's plugins.
work=$(mktemp -d "${TMPDIR:-/tmp}/vroc-install-test.XXXXXX")
# Kept when the test fails, for the files its messages name.
trap 'status=$?; if [ $status -eq 0 ]; then rm -rf "$work"; else echo "install test: files kept in $work" >&2; fi' EXIT
unset VROC_PLUGIN_PATH

fail() { echo "install test: FAIL: $*" >&2; exit 1; }
ok() { echo "ok    $*"; }
# Runs a command, keeping its output in $work/out; fails with the output if it exits non-zero.
run() {
  local rc=0
  "$@" > "$work/out" 2>&1 || rc=$?
  if [ "$rc" -ne 0 ]; then
    cat "$work/out" >&2
    fail "exit $rc: $*"
  fi
}
expect_in_output() {   # expect_in_output TEXT WHAT
  grep -qF -- "$1" "$work/out" || { cat "$work/out" >&2; fail "$2: no '$1' in the output"; }
}

# ---- 1. install, move, layout -------------------------------------------------------------------
run "$cmake" --install "$build" --prefix "$work/stage"
mv "$work/stage" "$work/prefix"
p="$work/prefix"
config=$(find "$p" -path '*/cmake/vroc/vrocConfig.cmake' | head -n 1)
[ -n "$config" ] || fail "no vrocConfig.cmake under the prefix"
libdir=$(dirname "$(dirname "$(dirname "$config")")")
libdir=${libdir#"$p"/}
for f in bin/vroc include/vroc/core/backend.h include/vroc/core/backend_registry.h include/vroc/harness/commands/compare.h \
         include/vroc/plugin/vroc_device_plugin.h include/vroc/plugin_sdk/plugin_sdk.h include/vroc/native/native_backend.h \
         "$libdir/libvroc_core.a" "$libdir/libvroc_harness.a" "$libdir/libvroc_plugin_support.a" \
         "$libdir/cmake/vroc/vrocConfigVersion.cmake" "$libdir/cmake/vroc/vroc-core-targets.cmake" \
         "$libdir/cmake/vroc/vroc-harness-targets.cmake" "$libdir/cmake/vroc/vroc-backend_native-targets.cmake" \
         "$libdir/pkgconfig/vroc-plugin.pc" "$libdir/vroc/plugins/vroc-plugin-analytic.so" \
         share/vroc/scenes/ball_drop.json share/vroc/scenes/tracked_notepad.json share/vroc/plugin-exports.map; do
  [ -e "$p/$f" ] || fail "not installed: $f"
done
[ "$(ls "$p/include")" = vroc ] || fail "include/ holds more than vroc/: $(ls "$p/include" | tr '\n' ' ')"
for internal in geometry narrowphase dynamics scheduling backend; do
  [ ! -e "$p/include/$internal" ] && [ ! -e "$p/include/vroc/$internal" ] || fail "native internals installed: $internal"
done
if ls "$p/$libdir/vroc/plugins" | grep -q fixture; then fail "test fixtures installed as plugins"; fi
if grep -rlF -e "$build" -e "$source" "$p/$libdir/cmake" "$p/$libdir/pkgconfig" "$p/include" > "$work/out"; then
  cat "$work/out" >&2
  fail "installed files name the build or source tree"
fi
ok "cmake --install: layout under $(basename "$p") ($libdir), no internals, no fixtures, relocatable"

# ---- 2. the installed vroc: plugins and a shipped scene -----------------------------------------
vroc="$p/bin/vroc"
run "$vroc" plugins
expect_in_output "$p/$libdir/vroc/plugins/vroc-plugin-analytic.so" "vroc plugins"
if grep -F "file: " "$work/out" | grep -vqF "file: $p/"; then
  cat "$work/out" >&2
  fail "the installed vroc loaded a plugin from outside its prefix"
fi
run "$vroc" plugins --names
for name in analytic force-log predict replay spacemouse-sim spacenav udp; do
  grep -qx "$name" "$work/out" || { cat "$work/out" >&2; fail "vroc plugins --names: no $name"; }
done
ok "installed vroc finds its 7 built-in plugins in $libdir/vroc/plugins"

run "$vroc" run "$p/share/vroc/scenes/ball_drop.json" --backend native --duration 1 --out "$work/ball_drop"
[ -s "$work/ball_drop/run.json" ] || fail "vroc run: no run.json"
# First contact of a ball dropped from rest with its lowest point h = 1 m above the floor: the scene
# file states h and g = 9.81 m/s^2, so t = sqrt(2 h / g) = 0.4515 s. Native reports the exact time
# of contact; touching counts from the scene's collision_distance of 1 mm (up to 2.3e-4 s earlier).
first=$(awk -F, 'NR == 2 { print $1 }' "$work/ball_drop/events.csv")
[ -n "$first" ] || fail "vroc run ball_drop: no collision event"
awk -v t="$first" 'BEGIN { e = t - sqrt(2 * 1.0 / 9.81); exit !(e < 5e-4 && e > -5e-4) }' ||
  fail "vroc run ball_drop: first contact at t = $first s, expected 0.4515 s"
ok "installed vroc runs share/vroc/scenes/ball_drop.json: first contact at t = $first s (closed form 0.4515 s)"

# ---- 3. a plugin in C through pkg-config --------------------------------------------------------
export PKG_CONFIG_PATH="$p/$libdir/pkgconfig"
cflags=$(pkg-config --cflags vroc-plugin)
include_dir=${cflags#-I}
include_dir=${include_dir%% *}
[ "$(realpath "$include_dir")" = "$(realpath "$p/include")" ] ||
  fail "pkg-config --cflags vroc-plugin: '$cflags' is not the installed include directory"
mkdir -p "$work/c-plugins"
run cc $cflags -std=c11 -Wall -Wextra -Werror -fPIC -shared -o "$work/c-plugins/vroc-plugin-hold.so" \
  "$source/tests/install/hold_plugin.c" "-Wl,--version-script=$(pkg-config --variable=exports_map vroc-plugin)"
run "$vroc" plugins --plugin "$work/c-plugins/vroc-plugin-hold.so"
expect_in_output "hold  1.0.0  (ABI 2)" "vroc plugins --plugin vroc-plugin-hold.so"
expect_in_output "device 0: held hand" "vroc plugins --plugin vroc-plugin-hold.so"
# By name through VROC_PLUGIN_PATH, driving the tracked notepad: every recorded notepad pose after
# the first device read is the plugin's (0.25, 1.5, 0.75), 90 degrees about z.
VROC_PLUGIN_PATH="$work/c-plugins" run "$vroc" run "$p/share/vroc/scenes/tracked_notepad.json" --backend native \
  --duration 0.25 --track notepad=hold --out "$work/hold"
awk -F, 'function sq(v) { return v * v }
         NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
         $col["body"] == "notepad" && $col["t"] > 0 {
           n++
           h = 0.70710678118654752
           d = sq($col["x"] - 0.25) + sq($col["y"] - 1.5) + sq($col["z"] - 0.75) + sq($col["qx"]) + sq($col["qy"])
           d += sq($col["qz"] - h) + sq($col["qw"] - h)
           if (d > 1e-18) bad++
         }
         END { exit !(n > 0 && bad == 0) }' "$work/hold/trajectory.csv" ||
  fail "vroc run --track notepad=hold: the notepad's poses are not the plugin's (see $work/hold/trajectory.csv)"
ok "C plugin built with pkg-config vroc-plugin: loaded by the installed vroc, drives the tracked notepad"

# ---- 4. the downstream CMake projects ------------------------------------------------------------
# Both are C++ only (project(... CXX)): the package must not need the C language.
generator=()
command -v ninja > /dev/null && generator=(-G Ninja)
# 4a. find_package(vroc) without components, linking vroc::core alone: no MPI, no reference engines
#     (downstream/CMakeLists.txt fails its configure if any was looked for).
run "$cmake" -S "$source/tests/install/downstream" -B "$work/downstream" "${generator[@]}" \
  -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=$p"
expect_in_output "vroc 0.1.0 from $p/$libdir/cmake/vroc" "downstream configure"
if grep -q "Found MPI" "$work/out"; then cat "$work/out" >&2; fail "downstream configure (vroc::core only) mentions MPI"; fi
run "$cmake" --build "$work/downstream" -j "$jobs"
run "$work/downstream/vroc_downstream"
cat "$work/out"
expect_in_output "downstream (core): all checks passed" "vroc_downstream"
run "$vroc" plugins --plugin "$work/downstream/vroc-plugin-hover.so"
expect_in_output "hover  1.0.0  (ABI 2)" "vroc plugins --plugin vroc-plugin-hover.so"
ok "C++-only downstream project: find_package(vroc) links vroc::core alone (no MPI), C++ SDK plugin loads"

# 4a. The Python package, where `make install` puts it (lib/python3.X/dist-packages), imported from
#     the moved prefix: it steps a scene and finds the prefix's plugins.
python=$(sed -n 's/^VROC_PYTHON_EXECUTABLE:INTERNAL=//p' "$build/CMakeCache.txt")
if [ -n "$python" ]; then
  module=$(find "$p/lib" -path '*/dist-packages/vroc/_vroc*.so' | head -n 1)
  [ -n "$module" ] || fail "the Python module was not installed under $p/lib/python3.X/dist-packages"
  run env PYTHONPATH="$(dirname "$(dirname "$module")")" "$python" -c "
import vroc
assert vroc.__file__.startswith('$p/'), vroc.__file__
sim = vroc.Simulation('$p/share/vroc/scenes/ball_drop.json', 'native')
sim.run(1.0)
names = [x['name'] for x in vroc.plugins() if x.get('rejected') is None]
assert 'analytic' in names, names
print('python ok', sim.state_hash, vroc.plugins()[0]['path'])"
  expect_in_output "python ok" "import vroc from the prefix"
  expect_in_output " $p/" "vroc.plugins() from the prefix"
  ok "Python package: imported from the moved prefix, steps a scene, lists the prefix's plugins"
fi

# 4b. find_package(vroc COMPONENTS harness backend_native): the harness compares the downstream
#     backend with native; MPI is found for C++ only; every installed header compiles.
run "$cmake" -S "$source/tests/install/downstream_harness" -B "$work/downstream_harness" "${generator[@]}" \
  -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=$p"
expect_in_output "vroc 0.1.0 from $p/$libdir/cmake/vroc: harness, backend_native" "downstream_harness configure"
run "$cmake" --build "$work/downstream_harness" -j "$jobs"
run "$work/downstream_harness/vroc_downstream_harness"
cat "$work/out"
expect_in_output "downstream (harness): all checks passed" "vroc_downstream_harness"
ok "C++-only downstream project with COMPONENTS harness: own backend compared with native, all headers compile"
echo "install test: all passed"
