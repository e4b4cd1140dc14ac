#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs the libFuzzer targets of tests/fuzz/ (`make fuzz`, docs/fuzzing.md), one after the other,
# each for SECONDS, on a working copy of its committed seed corpus inside BUILD_DIR (so the
# committed corpus only changes by hand). Prints and writes BUILD_DIR/fuzz-summary.txt: executions,
# time and executions per second per target. Exits non-zero if any target found a crash, leak or
# timeout; the input is saved in BUILD_DIR/fuzz-artifacts/<target>/.
#   usage: scripts/run_fuzz.sh BUILD_DIR SECONDS [TARGET...]   (default: every target)
set -euo pipefail
build=$(realpath "$1")
seconds=$2
shift 2
source_dir=$(cd "$(dirname "$0")/.." && pwd)
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=(scene_loader_fuzz mesh_import_fuzz pose_csv_fuzz opentrack_datagram_fuzz plugin_validation_fuzz)
fi

summary=$build/fuzz-summary.txt
mkdir -p "$build/fuzz-logs"
printf '%-26s %8s %12s %10s %8s  %s\n' target seconds executions exec/s corpus result > "$summary"
failed=0
for target in "${targets[@]}"; do
  corpus=$build/fuzz-corpus/$target
  artifacts=$build/fuzz-artifacts/$target
  log=$build/fuzz-logs/$target.log
  mkdir -p "$corpus" "$artifacts"
  cp -n "$source_dir/tests/fuzz/corpus/$target/"* "$corpus/"   # seeds; earlier finds are kept
  extra=()
  dict=$source_dir/tests/fuzz/${target%_fuzz}.dict
  [ -f "$dict" ] && extra+=("-dict=$dict")
  echo "vroc: fuzzing $target for ${seconds} s (log: $log)"
  status=0
  touch "$artifacts/.run-start"
  start=$SECONDS
  # A slow input (10 s) counts as a finding: every target handles one input in milliseconds.
  ASAN_SYMBOLIZER_PATH=$(command -v llvm-symbolizer-16 || command -v llvm-symbolizer || true) \
  ASAN_OPTIONS=detect_leaks=1:strict_init_order=1 \
  LSAN_OPTIONS=suppressions=$source_dir/tests/fuzz/lsan.supp:print_suppressions=0 \
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$build/bin/$target" "$corpus" -max_total_time="$seconds" -timeout=10 -print_final_stats=1 \
      -artifact_prefix="$artifacts/" "${extra[@]}" > "$log" 2>&1 || status=$?
  elapsed=$((SECONDS - start))
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  units=$(ls "$corpus" | wc -l)
  result=ok
  found=$(find "$artifacts" -newer "$artifacts/.run-start" -type f -name '*-*' | head -1)
  if [ "$status" -ne 0 ] || [ -n "$found" ]; then
    result="FAILED (exit $status; artifacts in $artifacts)"
    failed=1
    grep -E '^(==[0-9]+==ERROR|SUMMARY|vroc fuzz:|.*runtime error)' "$log" | head -5 || true
  fi
  printf '%-26s %8s %12s %10s %8s  %s\n' "$target" "$elapsed" "${runs:-?}" "${rate:-?}" "$units" "$result" >> "$summary"
done
cat "$summary"
exit $failed
