#!/usr/bin/env bash
# Runs the scene loaders' libFuzzer targets (tests/fuzz), built by `make fuzz-build` in
# $FUZZ_BUILD (default build-fuzz).
#
#   scripts/fuzz.sh smoke [SECONDS]        each target for SECONDS (default 25), one process:
#                                          `make fuzz-smoke`, run by `make test` (CI)
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

status=0
for t in "${targets[@]}"; do
  bin=$build/tests/fuzz/$t
  [ -x "$bin" ] || { echo "fuzz: $bin is missing (make fuzz-build)" >&2; exit 1; }
  corpus=$build/corpus/$t
  mkdir -p "$build/artifacts"
  args=("${common[@]}" -dict=tests/fuzz/$t.dict -artifact_prefix="$build/artifacts/$t-")
  case $mode in
    smoke)
      rm -rf "$corpus" && mkdir -p "$corpus"
      args+=(-max_total_time="${2:-25}")
      ;;
    long)
      mkdir -p "$corpus"
      # -fork would otherwise count timeouts and OOMs and go on.
      args+=(-runs="${2:-10000000}" -fork="${3:-2}" -ignore_timeouts=0 -ignore_ooms=0)
      ;;
    *) echo "usage: $0 smoke [SECONDS] | long [RUNS] [WORKERS]" >&2; exit 2 ;;
  esac
  echo "fuzz: $t ($mode)"
  # libFuzzer prints a line per new input; keep the log and show its ending.
  log=$build/$t-$mode.log
  start=$SECONDS
  if "$bin" "${args[@]}" "$corpus" "tests/fuzz/corpus/$t" >"$log" 2>&1; then
    grep -E '^(#[0-9]+\s+DONE|#[0-9]+: cov|stat::|INFO: fuzzed for|INFO: exiting|Done )' "$log" | tail -n 8
    echo "fuzz: $t passed in $((SECONDS - start)) s"
  else
    tail -n 60 "$log"
    echo "fuzz: $t FOUND A PROBLEM (log: $log; reproducer in $build/artifacts/)" >&2
    status=1
  fi
done
exit $status
