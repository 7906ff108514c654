#!/bin/sh
# A full disk ends a run cleanly: exit 1 with a message, never a signal, and no temporary files
# left. Needs a small tmpfs (mount as root); exits 77 (skipped) where mounting is not permitted.
# Usage: disk_full.sh CAROM
set -u
carom="$1"
work=$(mktemp -d)
trap 'umount "$work/full" 2>/dev/null; rm -rf "$work"' EXIT
mkdir "$work/full"
if ! mount -t tmpfs -o size=400k tmpfs "$work/full" 2>/dev/null; then
  echo "skipped: cannot mount a small tmpfs here (needs root)"
  exit 77
fi
cat > "$work/gas.toml" <<'SCENE'
[domain]
min = [0, 0, 0]
max = [8.0, 8.0, 8.0]
periodic = ["x", "y", "z"]
[[species]]
name = "a"
diameter = 1.0
density = 1.909859317102744
fill = { volume_fraction = 0.25 }
[initial]
temperature = 1.0
[time]
end = 20.0
[output]
snapshot_every = 0.1
sample_every = 0.1
max_bytes = 1e9
SCENE
"$carom" run "$work/gas.toml" --out "$work/full/run" --quiet > "$work/log" 2>&1
code=$?
cat "$work/log"
if [ "$code" -ne 1 ]; then
  echo "FAIL: a full disk gave exit $code, expected 1 (a message, no signal)"
  exit 1
fi
if ! grep -q "carom: failed:" "$work/log"; then
  echo "FAIL: no message naming the failure"
  exit 1
fi
if ls "$work/full/run" | grep -q '\.tmp$'; then
  echo "FAIL: temporary files left behind:"; ls "$work/full/run"
  exit 1
fi
echo "ok: exit 1 with a message on a full disk"
