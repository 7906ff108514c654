#!/bin/bash
# carom's soft-sphere method against LIGGGHTS 3.8 on the same granular gas, from the same
# initial state, in alternating runs (the LIGGGHTS comparison's case (a)).
#
#   tests/bench/soft_sphere/bench_vs_liggghts.sh CAROM N STEPS PAIRS [--event-driven]
#   tests/bench/soft_sphere/bench_vs_liggghts.sh CAROM column STEPS PAIRS
#
# CAROM: the carom binary. Writes a carom run of N particles at t = 0 (gas.toml with the cube
# edge for N; the timed carom runs start from the same state: same scene and seed), converts its snapshot into a LIGGGHTS data file (../liggghts/to_liggghts_data.py),
# then runs carom (the same scene, STEPS steps) and LIGGGHTS (in.gas, read_data, STEPS steps)
# alternately PAIRS times, and prints each run's loop wall time and particle-steps per second
# (carom: summary.json's wall_seconds of the loop; LIGGGHTS: its own Loop time), and the median
# ratio. --event-driven runs carom's event-driven method on the same gas instead (hard spheres,
# same e and mu, beta0 = 0): which method is faster for the same simulated time.
# Needs liggghts (run ../liggghts/run_liggghts.sh --install once) and /usr/bin/python3 with h5py.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
carom=$1; n=$2; steps=$3; pairs=$4; mode=${5:-soft}
work=$(mktemp -d /tmp/soft_bench.XXXXXX)
end=$(/usr/bin/python3 -c "print(${steps}*1.25e-6)")
if [[ $n == column ]]; then
  n=10000; scene=$here/column.toml; input=$here/../liggghts/in.column; common=(--quiet); lig=(-var skin 1.0e-4)
else
  edge=$(/usr/bin/python3 -c "import math; print((${n}*math.pi*(3e-4)**3/(6*0.3))**(1/3))")
  scene=$here/gas.toml; input=$here/../liggghts/in.gas; lig=(-var skin 3.0e-5)
  common=(--set "domain.max=[${edge}, ${edge}, ${edge}]" --set "species.glass.fill.count=${n}" --quiet)
fi
# The initial state: carom places and writes it (t = 0 snapshot), LIGGGHTS reads it.
"$carom" run "$scene" "${common[@]}" --set time.end=1.25e-6 --out "$work/init" >/dev/null
/usr/bin/python3 "$here/../liggghts/to_liggghts_data.py" "$work/init/run.h5" "$work/gas.data" --snapshot 0 >/dev/null
extra=()
if [[ $mode == --event-driven ]]; then
  extra=(--set 'method.kind="event_driven"' --set 'collisions.default={ e = 0.9, mu = 0.3, beta0 = 0.0 }')
fi
for ((k = 1; k <= pairs; ++k)); do
  rm -rf "$work/carom"
  # The same scene and seed: the same initial state as the one LIGGGHTS reads.
  "$carom" run "$scene" "${common[@]}" --set time.end=$end "${extra[@]}" --out "$work/carom" >/dev/null
  carom_s=$(/usr/bin/python3 -c "import json; print(json.load(open('$work/carom/summary.json'))['wall_seconds'])")
  (cd "$work" && liggghts -in "$input" -var data 1 -var datafile "$work/gas.data" -var steps "$steps" \
     "${lig[@]}" -var out "$work/" -log "$work/log.liggghts" > "$work/screen.txt" 2>&1)
  lig_s=$(grep -m1 "^Loop time" "$work/log.liggghts" | awk '{print $4}')
  /usr/bin/python3 -c "
n, s, c, l = $n, $steps, $carom_s, $lig_s
print(f'pair $k: carom {c:.3f} s ({n*s/c/1e6:.2f} M particle-steps/s), LIGGGHTS {l:.3f} s ({n*s/l/1e6:.2f} M), LIGGGHTS/carom {l/c:.2f}')
" | tee -a "$work/pairs.txt"
done
/usr/bin/python3 -c "
import re, statistics
r = [float(re.search(r'LIGGGHTS/carom ([0-9.]+)', l).group(1)) for l in open('$work/pairs.txt')]
print(f'median LIGGGHTS/carom wall-time ratio {statistics.median(r):.2f} (range {min(r):.2f}-{max(r):.2f}, {len(r)} pairs, N = $n, $steps steps)')
"
echo "outputs in $work"
