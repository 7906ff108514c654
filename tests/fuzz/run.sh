#!/usr/bin/env bash
# Bounded fuzzing of carom's inputs (tests/fuzz/README.md): each libFuzzer harness for SECONDS,
# under AddressSanitizer and UBSan. Fails on any crash, sanitizer report, hang (one input over
# -timeout), memory blow-up (-rss_limit_mb) or a bad input answered with anything but a
# SceneError; the input that did it is kept in $WORK/artifacts/.
#
#   tests/fuzz/run.sh SECONDS [HARNESS ...]
#   (default: fuzz_scene fuzz_overrides fuzz_initial_file fuzz_resume)
#
# Needs the fuzz build: cmake --preset fuzz && cmake --build --preset fuzz.
# Environment: FUZZ_BUILD (default build/fuzz), WORK (default FUZZ_BUILD/fuzz-work: the corpora
# grow there from run to run), JOBS (parallel fuzzing processes per harness, default 1).
set -uo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
seconds="${1:?usage: run.sh SECONDS [HARNESS ...]}"
shift
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(fuzz_scene fuzz_overrides fuzz_initial_file fuzz_resume)
build="${FUZZ_BUILD:-$root/build/fuzz}"
work="${WORK:-$build/fuzz-work}"
jobs="${JOBS:-1}"
mkdir -p "$work/artifacts"
# Seeds: scenes, --set lines, and edit lists for fuzz_initial_file and fuzz_resume (those two make
# the files they edit themselves: runs of tiny_run.toml and of the resume_*.toml scenes).
python3 "$root/tests/fuzz/make_corpus.py" "$work/seeds" || exit 1
# The raw-bytes harness starts from real files: the run file and checkpoint of tiny_run.toml.
if [[ " ${harnesses[*]} " == *" fuzz_initial_file_bytes "* ]]; then
  rm -rf "$work/tiny"
  "$build/scenarios/carom" run "$root/tests/fuzz/tiny_run.toml" --out "$work/tiny" --quiet || exit 1
  mkdir -p "$work/seeds/fuzz_initial_file_bytes"
  cp "$work/tiny/run.h5" "$work/tiny/checkpoint.h5" "$work/seeds/fuzz_initial_file_bytes/"
fi
status=0
for h in "${harnesses[@]}"; do
  binary="$build/tests/fuzz/$h"
  [ -x "$binary" ] || { echo "run.sh: $binary is missing (cmake --build --preset fuzz)"; exit 1; }
  corpus="$work/corpus/$h"
  mkdir -p "$corpus"
  options=(-max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1
           -artifact_prefix="$work/artifacts/$h-" -max_len=65536)
  case "$h" in
    fuzz_scene | fuzz_overrides) options+=(-dict="$work/seeds/scene.dict") ;;
    fuzz_initial_file_bytes) options+=(-max_len=400000) ;;
  esac
  [ "$jobs" -gt 1 ] && options+=(-fork="$jobs" -ignore_crashes=0)
  echo "=== $h: $seconds s"
  "$binary" "${options[@]}" "$corpus" "$work/seeds/$h" > "$work/$h.log" 2>&1
  rc=$?
  # The final statistics and the last coverage line.
  grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb" "$work/$h.log"
  grep -E "^#[0-9]+" "$work/$h.log" | tail -1
  if [ "$rc" -ne 0 ]; then
    status=1
    echo "=== $h FAILED (exit $rc); the log: $work/$h.log"
    grep -E "ERROR: |SUMMARY: |carom fuzz: |Test unit written to|runtime error" "$work/$h.log" | head -20
  else
    echo "=== $h: no crash, hang or sanitizer report"
  fi
done
exit $status
