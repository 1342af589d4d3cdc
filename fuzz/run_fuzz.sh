#!/usr/bin/env bash
# Runs the libFuzzer targets of a CTAB_FUZZ build (docs/fuzzing.md), one after the other, each for SECONDS:
#   fuzz/run_fuzz.sh BUILD_DIR SECONDS TARGET...
# First every saved finding of a target (fuzz/findings/TARGET-*.bin) is run once, as a regression input (a failure
# fails the script, and the target is fuzzed all the same); then the target fuzzes from its working corpus
# BUILD_DIR/fuzz-corpus/TARGET (kept between runs, so `make fuzz` goes on where it stopped) and the seeds of
# fuzz/corpus/TARGET. A crash, a sanitizer report, a leak, an input slower than 20 s or over 2 GB is a failure: the
# input lands in BUILD_DIR/fuzz-findings/, and the script exits 1 once every
# target has run. Prints each target's executions and executions per second.
set -uo pipefail
cd "$(dirname "$0")/.."
build=$1 seconds=$2
shift 2
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# The targets' scratch files (readers that take a path) in a directory of this run, in memory where /dev/shm exists.
base=${TMPDIR:-/tmp}
[ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && base=/dev/shm
TMPDIR=$(mktemp -d "$base/ctab-fuzz.XXXXXX")
export TMPDIR
trap 'rm -rf "$TMPDIR"' EXIT
mkdir -p "$build/fuzz-findings"
failed=()
for target in "$@"; do
  binary=$build/bin/fuzz_$target
  log=$build/fuzz-findings/$target.log
  findings=(fuzz/findings/"$target"-*.bin)
  if [ -e "${findings[0]}" ] && ! "$binary" "${findings[@]}" > "$log.findings" 2>&1; then
    echo "fuzz: $target: a saved finding still fails (fuzz/findings/$target-*.bin); log: $log.findings"
    failed+=("$target")
  fi
  mkdir -p "$build/fuzz-corpus/$target"
  start=$SECONDS
  "$binary" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$build/fuzz-findings/$target-" "$build/fuzz-corpus/$target" "fuzz/corpus/$target" \
    > "$log" 2>&1
  status=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
  echo "fuzz: $target: ${runs:-?} executions in $((SECONDS - start)) s (${rate:-?}/s), exit $status"
  if [ "$status" -ne 0 ]; then
    grep -E "^(==[0-9]+==ERROR|SUMMARY|.*runtime error)" "$log" | head -n 5
    echo "fuzz: $target: FAILED; the input is in $build/fuzz-findings/ (log: $log)"
    [[ " ${failed[*]} " == *" $target "* ]] || failed+=("$target")
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: failed: ${failed[*]}"
  exit 1
fi
