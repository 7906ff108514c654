#!/bin/bash
# Wall time of a scene run by one carom binary against another, in alternating runs (the
# machine's drift and noise hit both), with identical results checked on the first pair.
#   tests/bench/alternate_runs.sh OLD_CAROM NEW_CAROM PAIRS SCENE [carom run options...]
# Environment: OLD_ENV and NEW_ENV, assignments for each side (e.g. NEW_ENV="CAROM_THREADS=2").
# Prints each pair's wall seconds (the whole process: settling, run and outputs) and their
# ratio old/new (> 1: new faster), then the median; exits 1 if the first pair's outputs differ.
set -euo pipefail
old=$1; new=$2; pairs=$3; scene=$4; shift 4
here="$(cd "$(dirname "$0")" && pwd)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
wall() {  # wall seconds of one run: BINARY OUT ENV
  local bin=$1 out=$2 env=$3
  shift 3
  /usr/bin/env $env /usr/bin/time -f %e -o "$work/time" "$bin" run "$scene" --out "$out" --quiet --overwrite "$@" > /dev/null
  cat "$work/time"
}
ratios=()
for ((k = 1; k <= pairs; k++)); do
  a=$(wall "$old" "$work/old" "${OLD_ENV:-}" "${@}")
  b=$(wall "$new" "$work/new" "${NEW_ENV:-}" "${@}")
  if ((k == 1)); then
    /usr/bin/python3 "$here/compare_runs.py" "$work/old" "$work/new" || exit 1
  fi
  r=$(echo "scale=4; $a / $b" | bc)
  ratios+=("$r")
  echo "pair $k: old ${a} s, new ${b} s, ratio old/new $r"
done
printf '%s\n' "${ratios[@]}" | sort -n | awk '{v[NR] = $1} END {m = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; print "median ratio old/new:", m, "(min", v[1] ", max", v[NR] ")"}'
