#!/bin/bash
# Smallenburg's EDMD ("Single") alone: its collisions per CPU second at N particles, phi = 0.40,
# for comparing its fall-off with N against carom_bench's (the large-N speed goal).
#   tests/bench/edmd_rate.sh EDMD_BINARY N K TEQ
# The peer is built outside this repository as tests/bench/alternate_peer.sh's header says. An
# FCC lattice (edmd_fcc.sh) is run for TEQ units of EDMD's time (about 10
# collisions per particle each at phi = 0.40) to melt it; from its end snapshot, a run of K units
# minus a run of 0 (loading and output) gives the window's user+sys CPU time. Pinned to core 1.
set -euo pipefail
peer=$1; n=$2; K=$3; teq=$4; phi=0.40
here="$(cd "$(dirname "$0")" && pwd)"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
"$here/edmd_fcc.sh" "$n" "$phi" >init.sph
taskset -c 1 "$peer" "$teq" >/dev/null && mv snapshot_end.sph init.sph
TIMEFORMAT='%3U %3S'
cpu() { { time taskset -c 1 "$peer" "$1" >"$2"; } 2>&1 | awk '{print $1 + $2}'; }
t0=$(cpu 0 out0); t1=$(cpu "$K" out)
awk -v t="$t1" -v t0="$t0" -v n="$n" '/^Simtime/ { gsub(",", ""); c = $4 }
  END { if (c == "" || t <= t0) { print "no collision count or no time in the output" > "/dev/stderr"; exit 1 }
        printf "edmd N=%d collisions=%d cpu_seconds=%.3f collisions_per_cpu_second=%.0f\n", n, c, t - t0, c / (t - t0) }' out
