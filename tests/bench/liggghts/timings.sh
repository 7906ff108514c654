#!/bin/bash
# The LIGGGHTS timings of README.md: every case once per round, ROUNDS rounds (the machine is
# shared, so each case is run more than once, its runs spread over the whole session).
#   tests/bench/liggghts/timings.sh [ROUNDS] [SETTLED_BED.data] > timings.txt
# Cases: gas N = 10 000 for 2000 steps, gas N = 100 000 for 500 steps, column from the lattice
# for 4000 steps (mostly free fall), and, when a settled bed is given (write it with
#   run_liggghts.sh column --steps 120000 --every 2000 --write SETTLED_BED.data), the column
# from the settled bed for 4000 steps (every sphere in contact). Prints one result line per run
# (see run_liggghts.sh) and writes the outputs under ${OUT:-/tmp/liggghts_timings}.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
rounds=${1:-2}
bed=${2:-}
out=${OUT:-/tmp/liggghts_timings}
echo "# $(date -u +%F' '%H:%M' UTC') nproc=$(nproc) $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
for ((r = 1; r <= rounds; r++)); do
  "$here/run_liggghts.sh" gas --n 10000 --steps 2000 --out "$out/r$r/gas10k"
  "$here/run_liggghts.sh" gas --n 100000 --steps 500 --out "$out/r$r/gas100k"
  "$here/run_liggghts.sh" column --steps 4000 --out "$out/r$r/column_fall"
  if [[ -n $bed ]]; then
    "$here/run_liggghts.sh" column --steps 4000 --data "$bed" --out "$out/r$r/column_bed"
  fi
done
