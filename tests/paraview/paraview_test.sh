#!/bin/sh
# ParaView on a carom run: a short fluidized-bed run with a gas, its XDMF sidecars
# read by ParaView's three .xmf readers (check_paraview_output.py), and a snapshot rendered by
# scenarios/plots/paraview_snapshot.py checked for not being blank.
#
#   paraview_test.sh CAROM SOURCE_DIR WORK_DIR
#
# Exit status 77 (ctest: Skipped) with a message when pvpython, xvfb-run or xauth is missing
# (Debian: apt-get install paraview python3-paraview xvfb xauth).
set -eu
carom=$1 source_dir=$2 work=$3

missing=""
for program in pvpython xvfb-run xauth; do
  command -v "$program" > /dev/null 2>&1 || missing="$missing $program"
done
if [ -n "$missing" ]; then
  echo "SKIPPED: the ParaView test needs$missing (Debian: apt-get install paraview python3-paraview xvfb xauth)"
  exit 77
fi

# `pvpython --force-offscreen-rendering` crashes (XSync) on machines without a GPU: a virtual X
# server instead. -noreset: without it the server resets when ParaView's first connection
# closes, and about one run in three then fails with "bad X server connection".
headless() {
  xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" pvpython "$@"
}

rm -rf "$work"
mkdir -p "$work"
# 60 beads of the fluidized bed settled for 0.05 s and run for 0.1 s: five snapshots of the
# particles and the gas (4 x 1 x 20 cells). About a second.
"$carom" run "$source_dir/scenarios/scenes/fluidized_bed.toml" --out "$work/run" --quiet \
  --set species.glass.fill.count=60 --set initial.settle_time=0.05 --set time.end=0.1 \
  --set output.snapshot_every=0.025

headless "$source_dir/scenarios/plots/paraview_snapshot.py" "$work/run/run.xmf" --time 0.06 \
  --out "$work/snapshot.png" --size 800 600
headless "$source_dir/tests/paraview/check_paraview_output.py" "$work/run" "$work/snapshot.png"
