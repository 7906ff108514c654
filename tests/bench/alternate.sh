#!/bin/bash
# Speed of a binary against another in alternating runs (the machine's drift and noise hit both).
#   tests/bench/alternate.sh OLD_BENCH NEW_BENCH PAIRS [carom_bench options...]
# Prints each pair's collisions per CPU second and their ratio new/old, then the median ratio
# and its spread (the least and the greatest).
set -euo pipefail
old=$1; new=$2; pairs=$3; shift 3
rate() { local bin=$1; shift; "$bin" "$@" 2>/dev/null | sed -n 's/.*collisions_per_cpu_second=\([0-9.]*\).*/\1/p'; }
ratios=()
for ((k = 1; k <= pairs; k++)); do
  a=$(rate "$old" "$@"); b=$(rate "$new" "$@")
  r=$(echo "scale=4; $b / $a" | bc)
  ratios+=("$r")
  echo "pair $k: old $a new $b ratio $r"
done
printf '%s\n' "${ratios[@]}" | sort -n | awk '{v[NR] = $1 + 0} END {m = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; print "median ratio new/old:", m, "(min", v[1] ", max", v[NR] ")"}'
