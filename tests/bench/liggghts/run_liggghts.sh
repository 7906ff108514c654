#!/bin/bash
# One LIGGGHTS 3.8 run of a benchmark case, timed, serial (one MPI rank, as carom runs).
#
#   tests/bench/liggghts/run_liggghts.sh [--install] CASE [options] [-- NAME VALUE ...]
#
# CASE: gas (in.gas: cooling granular gas, periodic cube) or column (in.column: settling column).
# Options (each maps onto a LIGGGHTS -var of the input; the input's defaults otherwise):
#   --n N          gas: particles (default 10000)
#   --steps S      timed steps (gas 2000, column 4000)
#   --E PA         Young's modulus (1e7)       --dt S    time step (1.25e-6)
#   --e E          restitution (gas 0.9, column 0.5)   --mu MU   friction (0.3)
#   --data FILE    start from this LIGGGHTS data file (read_data; e.g. from to_liggghts_data.py)
#   --write FILE   gas: write the initial state (write_data); column: the final state
#   --every K      steps between rows of the energy time series
#   --out DIR      where the outputs go (default: a new folder under /tmp)
#   --nice K       niceness of the run (default 10: the machine is shared)
#   --no-setup-run skip the 0-step run that measures the set-up's CPU time (see below)
#   --install      apt-get install -y liggghts first (only when asked; needs root)
#   -- NAME VALUE  further -var pairs passed through, e.g. -- vrms 0.2 skin 6e-5
# Environment: LIGGGHTS=binary (default: liggghts on PATH).
#
# Writes in DIR: log.liggghts (LIGGGHTS' log; screen.txt, its screen: -screen none crashes
# LIGGGHTS 3.8 in Region::reset_random), time.txt (/usr/bin/time -v), ke.dat (gas: step,
# time, translational and rotational KE, granular temperature) or column.dat (column: KE, top of
# the bed, mean height, floor force, weight), and result.txt, one line that is also printed:
#   case=gas atoms=10000 steps=2000 loop_s=... wall_s=... particle_steps_per_s=... dt=... E=...
# particle_steps_per_s = atoms * steps / loop_s, where loop_s is LIGGGHTS' own "Loop time" of
# the timed run (wall clock; the set-up, insertion and output of the data file are outside it);
# wall_s and cpu_s (user + system) are the whole process (/usr/bin/time), set-up included.
# On a shared machine the wall clock also counts the time other processes held the core, so the
# CPU time is given too: a first run of the same input with 0 steps (in DIR/setup) measures the
# set-up's CPU time, loop_cpu_s = cpu_s - setup_cpu_s, and
# particle_steps_per_cpu_s = atoms * steps / loop_cpu_s.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

install=0
if [[ ${1:-} == --install ]]; then install=1; shift; fi
case_=${1:-}
[[ $case_ == gas || $case_ == column ]] || { sed -n '2,27p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
shift

vars=() out="" nice_=10 write="" setup_run=1
while (($#)); do
  case $1 in
    --n) vars+=(-var N "$2"); shift 2 ;;
    --steps) vars+=(-var steps "$2"); shift 2 ;;
    --E) vars+=(-var E "$2"); shift 2 ;;
    --dt) vars+=(-var dt "$2"); shift 2 ;;
    --e) vars+=(-var e "$2"); shift 2 ;;
    --mu) vars+=(-var mu "$2"); shift 2 ;;
    --every) vars+=(-var every "$2"); shift 2 ;;
    --data) vars+=(-var data 1 -var datafile "$(realpath "$2")"); shift 2 ;;
    --write) write=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --nice) nice_=$2; shift 2 ;;
    --install) install=1; shift ;;
    --no-setup-run) setup_run=0; shift ;;
    --) shift; while (($# >= 2)); do vars+=(-var "$1" "$2"); shift 2; done ;;
    *) echo "run_liggghts.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
[[ $case_ == column && " ${vars[*]} " == *" -var N "* ]] &&
  { echo "run_liggghts.sh: column takes its size from nx ny nz (-- nx 20 ny 20 nz 25)" >&2; exit 2; }

if ((install)); then
  apt-get install -y liggghts >&2
fi
bin=${LIGGGHTS:-liggghts}
command -v "$bin" >/dev/null || { echo "run_liggghts.sh: $bin not found (give --install, or set LIGGGHTS)" >&2; exit 1; }
[[ -x /usr/bin/time ]] || { echo "run_liggghts.sh: /usr/bin/time missing (apt-get install time)" >&2; exit 1; }

[[ -n $out ]] || out=$(mktemp -d "/tmp/liggghts_${case_}.XXXXXX")
mkdir -p "$out"
out=$(realpath "$out")
if [[ -n $write ]]; then vars+=(-var write 1 -var writefile "$(realpath -m "$write")"); fi

cpu_of() { awk -F': ' '/User time/ {u = $2} /System time/ {s = $2} END {print u + s}' "$1"; }
run_one() { # DIR, extra -var pairs (before the others: the first -var NAME given wins): one timed LIGGGHTS process
  local dir=$1; shift
  mkdir -p "$dir"
  (cd "$dir" && nice -n "$nice_" /usr/bin/time -v -o time.txt \
    "$bin" -in "$here/in.$case_" -var out "$dir/" "$@" "${vars[@]}" -echo none -log log.liggghts -screen screen.txt) ||
    { echo "run_liggghts.sh: LIGGGHTS failed; see $dir/log.liggghts" >&2; tail -5 "$dir/log.liggghts" >&2; exit 1; }
}

load0=$(cut -d" " -f1 /proc/loadavg)
setup_cpu=0
if ((setup_run)); then # the same input with 0 steps: its CPU time is the set-up's (insertion, reading, output)
  run_one "$out/setup" -var steps 0 -var write 0
  setup_cpu=$(cpu_of "$out/setup/time.txt")
fi
run_one "$out"

loop=$(grep '^Loop time of' "$out/log.liggghts" | tail -1)
loop_s=$(awk '{print $4}' <<<"$loop")
steps=$(awk '{for (i = 1; i <= NF; i++) if ($i == "for") print $(i + 1)}' <<<"$loop")
atoms=$(awk '{for (i = 1; i <= NF; i++) if ($i == "with") print $(i + 1)}' <<<"$loop")
wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$out/time.txt" |
  awk -F: '{s = 0; for (i = 1; i <= NF; i++) s = 60 * s + $i; print s}')
cpu=$(cpu_of "$out/time.txt")
pick() { grep -E "^variable +$1 +index" "$here/in.$case_" | awk '{print $4}'; }
val() { local k=$1 i; for ((i = 0; i < ${#vars[@]}; i++)); do [[ ${vars[i]} == -var && ${vars[i + 1]} == "$k" ]] && { echo "${vars[i + 2]}"; return; }; done; pick "$k"; }
pss=$(awk -v n="$atoms" -v s="$steps" -v t="$loop_s" 'BEGIN {printf "%.4g", n * s / t}')
loop_cpu=$(awk -v a="$cpu" -v b="$setup_cpu" -v r="$setup_run" 'BEGIN {if (r) printf "%.2f", a - b; else print "na"}')
pscpu=$(awk -v n="$atoms" -v s="$steps" -v t="$loop_cpu" 'BEGIN {if (t == "na" || t <= 0) print "na"; else printf "%.4g", n * s / t}')
line="case=$case_ atoms=$atoms steps=$steps loop_s=$loop_s wall_s=$wall cpu_s=$cpu setup_cpu_s=$setup_cpu"
line+=" loop_cpu_s=$loop_cpu particle_steps_per_s=$pss particle_steps_per_cpu_s=$pscpu"
line+=" dt=$(val dt) E=$(val E) e=$(val e) mu=$(val mu) load1_before=$load0 load1_after=$(cut -d" " -f1 /proc/loadavg) out=$out"
echo "$line" | tee "$out/result.txt"
