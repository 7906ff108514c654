#!/bin/bash
# carom against another event-driven code, in alternating runs pinned to one core (the machine's
# drift and noise hit both): the monodisperse elastic fluid at the same N and phi, both timed over
# about WINDOW collisions per particle (default 20) after the lattice start has melted. carom runs
# on one thread (carom_bench's default), as the peer does.
#   tests/bench/alternate_peer.sh CAROM_BENCH PEER_KIND PEER_BINARY PAIRS N PHI [WINDOW]
# Prints each pair's collisions per CPU second, the ratio carom/peer and both codes' pressure and
# collision rate per particle (a physics check), then the median, min and max ratio.
#
# PEER_KIND edmd: Smallenburg's EDMD, "Single" variant (https://github.com/FSmallenburg/EDMD, used
# at commit 2d0c86293f7ff1ca4674681ff9e1eefa3797377e). Its code stays outside this repository:
#   git clone https://github.com/FSmallenburg/EDMD /tmp/edmd/src && cp -r /tmp/edmd/src/Single /tmp/edmd/single
#   cd /tmp/edmd/single && sed -i 's/^const int usethermostat = 1;/const int usethermostat = 0;/;
#     s/^int main()$/int main(int argc, char** argv)/;
#     s/^    init();$/    if (argc > 1) maxtime = atof(argv[1]);\n    init();/' mdSingle.c && make
# (its Makefile: gcc -Wall -Ofast -funroll-loops -march=native). The edits touch only its settings:
# the published Single turns on a velocity-kicking thermostat (its README and paper run at constant
# energy, as carom does), and the run length (maxtime, compiled in) becomes the first argument.
# It reads init.sph in the working directory, redraws Maxwell velocities (fixed seed) and runs to
# simulated time maxtime, printing the collision count every unit of time. Window: an FCC start is
# run for carom's equilibration (150 collisions per particle at phi >= 0.4, else 10); from its end
# snapshot, a run of K whole time units (K ~ WINDOW / collision rate, so the count is printed at
# its end) minus a run of 0 (loading, neighbour lists, output) gives the window's user+sys CPU
# time. That difference of two runs is noisy when the window is short (at N = 32000 and the
# default 20, about 0.4 s): a WINDOW of 200 makes each run several seconds.
# Another peer: write prep_KIND (run once in $tmp) and rate_KIND (prints "rate pressure coll_rate").
set -euo pipefail
carom=$1; kind=$2; peer=$3; pairs=$4; n=$5; phi=$6; window=${7:-20}
here="$(cd "$(dirname "$0")" && pwd)"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
TIMEFORMAT='%3U %3S'
cpu() { { time taskset -c 1 "$@" >"$tmp/out" 2>/dev/null; } 2>&1 | awk '{print $1 + $2}'; }

prep_edmd() {  # FCC lattice (as EDMD's own fcc()), melted; K from the Enskog collision rate
  "$here/edmd_fcc.sh" "$n" "$phi" >"$tmp/init.sph"
  read -r teq K < <(awk -v phi="$phi" -v window="$window" 'BEGIN { g = (1 - phi / 2) / (1 - phi) ^ 3
    rate = 24 * phi * g / sqrt(atan2(0, -1)); eq = phi >= 0.4 ? 150 : 10
    k = int(window / rate + 0.5); print int(eq / rate) + 1, (k < 1 ? 1 : k) }')
  (cd "$tmp" && taskset -c 1 "$peer" "$teq" >/dev/null && mv snapshot_end.sph init.sph)
}
rate_edmd() {
  local t0 t1; cd "$tmp"
  t0=$(cpu "$peer" 0); t1=$(cpu "$peer" "$K")
  awk -v t="$t1" -v t0="$t0" -v K="$K" '/^Simtime/ { gsub(",", ""); c = $4 } /^Measured pressure/ { p = $NF }
    END { if (c == "" || t <= t0) { print "no collision count or no time in the peer'"'"'s output" > "/dev/stderr"; exit 1 }
          printf "%.0f %.4f %.4f\n", c / (t - t0), p, 2 * c / (NN * K) }' NN="$n" "$tmp/out"
  cd - >/dev/null
}
carom_rate() {
  taskset -c 1 "$carom" --n "$n" --phi "$phi" --measure "$window" 2>/dev/null | awk -F= '/^pressure=/ { p = $2 } /^collision_rate=/ { c = $2 }
    /collisions_per_cpu_second=/ { sub(/.*collisions_per_cpu_second=/, ""); r = $0 } END { print r, p, c }'
}

"prep_$kind"
ratios=()
for ((k = 1; k <= pairs; k++)); do
  read -r a ap ac < <(carom_rate); read -r b bp bc < <("rate_$kind")
  r=$(echo "scale=4; $a / $b" | bc); ratios+=("$r")
  echo "pair $k: carom $a $kind $b ratio $r | pressure $ap $bp | collision rate $ac $bc"
done
printf '%s\n' "${ratios[@]}" | sort -n | awk '{v[NR] = $1} END {
  m = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
  print "ratio carom/'"$kind"': median", m, "min", v[1], "max", v[NR] }'
