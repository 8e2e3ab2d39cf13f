#!/usr/bin/env bash
# Runs the scene loaders' libFuzzer targets (tests/fuzz), built by `make fuzz-build` in
# $FUZZ_BUILD (default build-fuzz).
#
#   scripts/fuzz.sh smoke [SECONDS]        each target for SECONDS (default 25), one process
#                                          each, side by side: `make fuzz-smoke`, run by
#                                          `make test` (CI)
#   scripts/fuzz.sh long [RUNS] [WORKERS]  each target for RUNS executions (default 10 million)
#                                          in WORKERS processes (-fork, default 2): `make fuzz`
#
# tests/fuzz/corpus/<target> is only read: new inputs go to $FUZZ_BUILD/corpus/<target> (emptied
# first by smoke, kept by long so a later run goes on from it). A finding (crash, sanitizer
# report, uncaught exception, timeout, out-of-memory) leaves its reproducer in
# $FUZZ_BUILD/artifacts/ and makes the script fail; replay one with
# `$FUZZ_BUILD/tests/fuzz/<target> <file>`.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-smoke}
build=${FUZZ_BUILD:-build-fuzz}
targets=(fuzz_obj fuzz_scene_json)

# -timeout: the slowest valid input known (JSON primitives up to the 50M-triangle limit) takes
# about 35 s under ASan; -rss_limit_mb: it peaks at about 2.1 GB. Inputs of 8 KiB leave room for
# a scene file, an OBJ and an MTL.
common=(-timeout=60 -rss_limit_mb=4096 -max_len=8192 -print_final_stats=1)

# run TARGET: fuzzes one target into its log; prints the log's ending and returns non-zero on a
# finding.
run() {
  local t=$1 bin=$build/tests/fuzz/$1 corpus=$build/corpus/$1 log=$build/$1-$mode.log
  local args=("${common[@]}" -dict=tests/fuzz/$t.dict -artifact_prefix="$build/artifacts/$t-")
  case $mode in
    smoke)
      rm -rf "$corpus" && mkdir -p "$corpus"
      args+=(-max_total_time="$seconds")
      ;;
    long)
      mkdir -p "$corpus"
      # -fork would otherwise count timeouts and OOMs and go on.
      args+=(-runs="$runs" -fork="$workers" -ignore_timeouts=0 -ignore_ooms=0)
      ;;
  esac
  # libFuzzer prints a line per new input; keep the log and show its ending.
  local start=$SECONDS
  echo "fuzz: $t ($mode)"
  if "$bin" "${args[@]}" "$corpus" "tests/fuzz/corpus/$t" >"$log" 2>&1; then
    grep -E '^(#[0-9]+\s+DONE|#[0-9]+: cov|stat::|INFO: fuzzed for|INFO: exiting|Done )' "$log" | tail -n 8 || true
    echo "fuzz: $t passed in $((SECONDS - start)) s"
  else
    tail -n 60 "$log"
    echo "fuzz: $t FOUND A PROBLEM (log: $log; reproducer in $build/artifacts/)" >&2
    return 1
  fi
}

case $mode in
  smoke) seconds=${2:-25} ;;
  long) runs=${2:-10000000} workers=${3:-2} ;;
  *) echo "usage: $0 smoke [SECONDS] | long [RUNS] [WORKERS]" >&2; exit 2 ;;
esac
for t in "${targets[@]}"; do
  [ -x "$build/tests/fuzz/$t" ] || { echo "fuzz: $build/tests/fuzz/$t is missing (make fuzz-build)" >&2; exit 1; }
done
mkdir -p "$build/artifacts"

status=0
if [ "$mode" = smoke ]; then
  # One process per target, side by side (CI has a core for each): the smoke run takes SECONDS,
  # not SECONDS per target. Their reports are shown one after the other once both are done.
  pids=()
  for t in "${targets[@]}"; do run "$t" > "$build/$t-smoke.report" 2>&1 & pids+=($!); done
  for p in "${pids[@]}"; do wait "$p" || status=1; done
  for t in "${targets[@]}"; do cat "$build/$t-smoke.report"; done
else
  # long: one target at a time, each already in WORKERS processes.
  for t in "${targets[@]}"; do run "$t" || status=1; done
fi
exit $status
