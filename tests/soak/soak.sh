#!/usr/bin/env bash
# Soak test (tests/soak/README.md): long runs of shipped scenes with the process's memory
# sampled, checkpoints taken about every minute of wall time, and several of those checkpoints
# resumed with `carom resume` and compared with the next one, bit for bit.
#
#   tests/soak/soak.sh [CASE ...]      CASE: gas (elastic_gas.toml), fines (fines_bed.toml); default both
#
# Environment: CAROM (the binary; default build/release/scenarios/carom), OUT (default
# /tmp/carom_soak), GAS_END (simulated s, default 36000: ten hours), FINES_END (simulated s,
# default 30), CHECKPOINT_WALL (wall s between checkpoints, default 60), RESUMES (checkpoints
# resumed per case, default 3), GROWTH_MB (allowed RSS growth, default 8; see README.md),
# WALL_BUDGET (wall s per long run; when set, the end is shortened to what the calibrated speed
# reaches in that time, and the log says so).
# Exit status 0 when every run completed, memory stayed within GROWTH_MB after the first
# quarter of the run, and every resumed checkpoint reproduced the next one bit for bit.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
carom="${CAROM:-$root/build/release/scenarios/carom}"
out="${OUT:-/tmp/carom_soak}"
checkpoint_wall="${CHECKPOINT_WALL:-60}"
resumes="${RESUMES:-3}"
growth_mb="${GROWTH_MB:-8}"
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(gas fines)
mkdir -p "$out"
status=0

# elapsed START: wall seconds since START (an $EPOCHREALTIME), to a tenth.
elapsed() {
  local now=$EPOCHREALTIME
  local tenths=$(( (${now/./} - ${1/./}) / 100000 ))
  echo "$((tenths / 10)).$((tenths % 10))"
}

# json_field FILE KEY: a number from summary.json.
json_field() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$1" "$2"; }

# soak NAME SCENE END CALIBRATION_END SETS...: one case.
soak() {
  local name="$1" scene="$2" end="$3" calibration_end="$4"
  shift 4
  local dir="$out/$name"
  rm -rf "$dir" "$dir.calibration" "$dir.checkpoints" "$dir.resume"*
  mkdir -p "$dir.checkpoints"
  # 1. Simulated seconds per wall second, from a short run, to space checkpoints a minute apart.
  "$carom" run "$scene" --set time.end="$calibration_end" --set output.checkpoint_every=0 "$@" \
    --out "$dir.calibration" --quiet
  local wall every
  wall="$(json_field "$dir.calibration/summary.json" wall_seconds)"
  every="$(python3 -c "import sys; from math import floor, log10
x = float(sys.argv[1]) / float(sys.argv[2]) * float(sys.argv[3])
print(float(f'{x:.2g}'))" "$calibration_end" "$wall" "$checkpoint_wall")"
  echo "soak $name: calibration $calibration_end s simulated in $wall s wall: checkpoint_every = $every s" \
    | tee "$dir.log"
  if [ -n "${WALL_BUDGET:-}" ]; then
    local reachable
    reachable="$(python3 -c "import sys
x = float(sys.argv[1]) / float(sys.argv[2]) * float(sys.argv[3])
print(min(float(sys.argv[4]), float(f'{x:.2g}')))" "$calibration_end" "$wall" "$WALL_BUDGET" "$end")"
    if python3 -c "import sys; sys.exit(not float(sys.argv[1]) < float(sys.argv[2]))" "$reachable" "$end"; then
      echo "soak $name: WALL_BUDGET = $WALL_BUDGET s reaches t = $reachable s at the calibrated speed: end shortened from $end s" \
        | tee -a "$dir.log"
      end="$reachable"
    fi
  fi
  # 2. The long run, its memory sampled every second, every new checkpoint copied aside
  #    (checkpoint.h5 is replaced by a rename, so a copy is always a whole file).
  local started=$EPOCHREALTIME
  "$carom" run "$scene" --set time.end="$end" --set output.checkpoint_every="$every" "$@" --out "$dir" --quiet &
  local pid=$! last="" k=0
  echo "wall_s,rss_kB" > "$dir.rss.csv"
  while kill -0 "$pid" 2>/dev/null; do
    local rss
    rss="$(awk '/^VmRSS:/ {print $2}' "/proc/$pid/status" 2>/dev/null || true)"
    # (bash arithmetic, not a python3 per sample: on a loaded machine that alone took seconds)
    [ -n "$rss" ] && echo "$(elapsed "$started"),$rss" >> "$dir.rss.csv"
    if [ -f "$dir/checkpoint.h5" ]; then
      local stamp
      stamp="$(stat -c %Y.%Z.%i "$dir/checkpoint.h5" 2>/dev/null || true)"
      if [ -n "$stamp" ] && [ "$stamp" != "$last" ]; then
        cp "$dir/checkpoint.h5" "$(printf '%s/%03d.h5' "$dir.checkpoints" "$k")" 2>/dev/null && k=$((k + 1))
        last="$stamp"
      fi
    fi
    sleep 1
  done
  local rc=0
  wait "$pid" || rc=$?
  echo "soak $name: carom run exited $rc after $(elapsed "$started") s wall; $k checkpoints copied" | tee -a "$dir.log"
  [ "$rc" -eq 0 ] || return 1
  # 3. Memory and resumes, judged by check.py.
  "${PYTHON:-python3}" "$here/check.py" --carom "$carom" --run "$dir" --growth-mb "$growth_mb" --resumes "$resumes" \
    | tee -a "$dir.log"
  return "${PIPESTATUS[0]}"
}

for c in "${cases[@]}"; do
  case "$c" in
    gas)
      # Snapshots every minute of simulated time (the shipped scene's 1 s would write 1 GB per
      # hour simulated), samples every second.
      soak gas "$root/scenarios/scenes/elastic_gas.toml" "${GAS_END:-36000}" 200 \
        --set output.snapshot_every=60 --set output.sample_every=1 || status=1 ;;
    fines)
      soak fines "$root/scenarios/scenes/fines_bed.toml" "${FINES_END:-30}" 0.3 || status=1 ;;
    *) echo "soak: unknown case $c (gas, fines)" >&2; exit 2 ;;
  esac
done
exit $status
