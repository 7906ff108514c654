#!/bin/bash
# The Monte Carlo method's mean energy drift in an elastic gas (scenarios/chart/CHARTS.md,
# "Record: the Monte Carlo method heats an elastic gas"). Runs scenarios/scenes/dilute_gas.toml
# with method.kind = monte_carlo for seeds 1..N and any further --set changes, and prints the
# mean and standard error of E_end/E_start (translational kinetic energy), the collisions per
# particle, and ln(E_end/E_start) per collision.
#
#   tests/bench/mc_elastic_heating.sh LABEL N [--set KEY=VALUE ...]
#   e.g. tests/bench/mc_elastic_heating.sh k10 32 --set monte_carlo.cell_size=4.8
#
# Environment: CAROM (default build/release/scenarios/carom), OUT (default /tmp/mc_heating).
# Needs /usr/bin/python3 with numpy and h5py. About 0.6 s a run for the 1320 spheres.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
carom=${CAROM:-$root/build/release/scenarios/carom}
out=${OUT:-/tmp/mc_heating}
label=$1
n=$2
shift 2
for s in $(seq 1 "$n"); do
  rm -rf "$out/$label/s$s"
  nice "$carom" run "$root/scenarios/scenes/dilute_gas.toml" --out "$out/$label/s$s" --quiet \
    --set method.kind=monte_carlo --set initial.seed="$s" "$@"
done
/usr/bin/python3 - "$out/$label" "$n" "$label" <<'PY'
import json, sys
import h5py, numpy as np
folder, n, label = sys.argv[1], int(sys.argv[2]), sys.argv[3]
ratio, collisions = [], []
for s in range(1, n + 1):
    with h5py.File(f"{folder}/s{s}/run.h5") as f:
        k = f["timeseries"]["kinetic_translational"][()]
    ratio.append(k[-1] / k[0])
    j = json.load(open(f"{folder}/s{s}/summary.json"))
    collisions.append(j["method"]["travelling_collisions"] / j["particles"])
r, c = np.array(ratio), np.array(collisions)
per = np.log(r) / c
print(f"{label}: E_end/E_start {r.mean():.4f} +- {r.std(ddof=1) / np.sqrt(n):.4f} (sd {r.std(ddof=1):.4f}, "
      f"{n} seeds), {c.mean():.1f} collisions per particle, ln(E_end/E_start) per collision "
      f"{per.mean():+.5f} +- {per.std(ddof=1) / np.sqrt(n):.5f}")
PY
