#!/usr/bin/env bash
# Makes the benchmark table of tests/bench/README.md ("Where the speed stands"): elastic hard-sphere fluid, collisions per second.
#   tests/bench/table.sh [path/to/carom_bench] [--no-million] > table.md
# (--no-million leaves out the N = 1e6 rows, which take tens of minutes.)
# Each case starts from a lattice (monodisperse) or random insertion (mixtures), runs 10
# collisions per particle to equilibrate (150 at phi >= 0.4, where the lattice melts slowly)
# and measures the next 20 (10 for N = 1e6).
set -euo pipefail
bench=${1:-build/release/tests/bench/carom_bench}
million=${2:-}
printf '| case | N | phi | collisions/s | P d^3/kT (Enskog) | rate per particle (Enskog) |\n'
printf '|---|---|---|---|---|---|\n'
run() {
  local label=$1; shift
  local out
  out=$("$bench" "$@")
  local n=$(grep -oP 'particles=\K[0-9]+' <<<"$out")
  local p=$(grep -oP '^pressure=\K[0-9.]+' <<<"$out")
  local pe=$(grep -oP '^enskog_pressure=\K[0-9.]+' <<<"$out" || echo "-")
  local r=$(grep -oP '^collision_rate=\K[0-9.]+' <<<"$out")
  local re=$(grep -oP '^enskog_collision_rate=\K[0-9.]+' <<<"$out" || echo "-")
  local c=$(grep -oP '^collisions_per_second=\K[0-9]+' <<<"$out")
  local phi=$(grep -oP -- '--phi \K[0-9.]+' <<<"$*")
  printf '| %s | %s | %s | %s | %s (%s) | %s (%s) |\n' "$label" "$n" "$phi" "$c" "$p" "$pe" "$r" "$re"
}
for n in 10000 100000; do
  for phi in 0.1 0.3 0.45; do run "monodisperse" --n $n --phi $phi; done
done
if [[ $million != --no-million ]]; then
  for phi in 0.1 0.3 0.45; do run "monodisperse" --n 1000000 --phi $phi --measure 10; done
fi
run "DynamO/literature case" --n 32000 --phi 0.40
run "fines 1:5, 97% by number" --n 100000 --phi 0.3 --ratio 0.2 --fines 0.97
run "fines 1:10, 99% by number" --n 100000 --phi 0.3 --ratio 0.1 --fines 0.99
run "fines 1:10, 99% by number, one grid" --n 100000 --phi 0.3 --ratio 0.1 --fines 0.99 --grid-ratio 0
