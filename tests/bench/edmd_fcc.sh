#!/bin/bash
# An FCC lattice of N unit-diameter spheres (rounded to 4 k^3) at packing fraction PHI, in the
# init.sph format of Smallenburg's EDMD (as its own fcc() places them), on standard output.
#   tests/bench/edmd_fcc.sh N PHI > init.sph
# Used by alternate_peer.sh and edmd_rate.sh.
set -euo pipefail
awk -v n="$1" -v phi="$2" 'BEGIN { k = int((n / 4) ^ (1 / 3) + 0.5); n = 4 * k ^ 3
  L = (n * atan2(0, -1) / (6 * phi)) ^ (1 / 3); s = L / k; printf "%d\n%.12f %.12f %.12f\n", n, L, L, L
  split("0.25 0.25 0.25 0.75 0.75 0.25 0.75 0.25 0.75 0.25 0.75 0.75", o, " ")
  for (i = 0; i < k; i++) for (j = 0; j < k; j++) for (l = 0; l < k; l++) for (b = 0; b < 4; b++)
    printf "a %.12f %.12f %.12f 0.5\n", (i + o[3*b+1]) * s, (j + o[3*b+2]) * s, (l + o[3*b+3]) * s }'
