#!/bin/bash
# Smallenburg's EDMD ("Single") alone: its collisions per CPU second at N particles, phi = 0.40,
# for comparing its fall-off with N against carom_bench's (issue 19, goal 1).
#   tests/bench/edmd_rate.sh EDMD_BINARY N K TEQ
# The peer is built outside this repository as tests/bench/alternate_peer.sh's header says. An
# FCC lattice (as alternate_peer.sh writes it) is run for TEQ units of EDMD's time (about 10
# collisions per particle each at phi = 0.40) to melt it; from its end snapshot, a run of K units
# minus a run of 0 (loading and output) gives the window's user+sys CPU time. Pinned to core 1.
set -euo pipefail
peer=$1; n=$2; K=$3; teq=$4; phi=0.40
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
awk -v n="$n" -v phi="$phi" 'BEGIN { k = int((n / 4) ^ (1 / 3) + 0.5); n = 4 * k ^ 3
  L = (n * atan2(0, -1) / (6 * phi)) ^ (1 / 3); s = L / k; printf "%d\n%.12f %.12f %.12f\n", n, L, L, L
  split("0.25 0.25 0.25 0.75 0.75 0.25 0.75 0.25 0.75 0.25 0.75 0.75", o, " ")
  for (i = 0; i < k; i++) for (j = 0; j < k; j++) for (l = 0; l < k; l++) for (b = 0; b < 4; b++)
    printf "a %.12f %.12f %.12f 0.5\n", (i + o[3*b+1]) * s, (j + o[3*b+2]) * s, (l + o[3*b+3]) * s }' >init.sph
taskset -c 1 "$peer" "$teq" >/dev/null && mv snapshot_end.sph init.sph
TIMEFORMAT='%3U %3S'
cpu() { { time taskset -c 1 "$peer" "$1" >"$2"; } 2>&1 | awk '{print $1 + $2}'; }
t0=$(cpu 0 out0); t1=$(cpu "$K" out)
awk -v t="$t1" -v t0="$t0" -v n="$n" '/^Simtime/ { gsub(",", ""); c = $4 }
  END { if (c == "" || t <= t0) { print "no collision count or no time in the output" > "/dev/stderr"; exit 1 }
        printf "edmd N=%d collisions=%d cpu_seconds=%.3f collisions_per_cpu_second=%.0f\n", n, c, t - t0, c / (t - t0) }' out
