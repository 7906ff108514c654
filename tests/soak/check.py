#!/usr/bin/env python3
"""Judges one soak run (soak.sh): memory over time, and checkpoints that resume bit for bit.

Memory: the run's RSS sampled every second (RUN.rss.csv). The baseline is the largest RSS in
the second quarter of the run (after the start-up: placement, settling, the first outputs),
the final the largest in the last quarter; their difference must stay below --growth-mb. A
leak per event or per output would grow with the run's length; output buffers (HDF5's chunk
caches, the series' rows being filled) are bounded and reached early.

Resumes: --resumes pairs of consecutive copied checkpoints (K, K+1), evenly spread over the
run. For each, a fresh folder gets the finished run's run.h5 and checkpoint K; `carom resume
--end t_(K+1)` must exit 0 and write a checkpoint whose /state and /gas (every dataset and
attribute) are byte for byte those of checkpoint K+1, which the uninterrupted run wrote. The
one exception is /gas/wall_seconds: the wall-clock time the gas coupling spent (mapping, solve,
interpolation; fluid/coupling_state.cpp), a profile of the machine, not the simulation's state.
"""

# Stored wall-clock times: they differ between any two runs on a real machine.
WALL_CLOCK = {"/gas/wall_seconds"}
import argparse
import csv
import glob
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np


def memory(run, growth_mb):
    rows = [(float(w), float(r) / 1024.0) for w, r in csv.reader(open(run + ".rss.csv")) if w != "wall_s"]
    if len(rows) < 8:
        print(f"memory: only {len(rows)} samples, too few to judge")
        return False
    end = rows[-1][0]
    quarter = lambda a, b: [r for w, r in rows if a * end <= w <= b * end]
    baseline, final, peak = max(quarter(0.25, 0.5)), max(quarter(0.75, 1.0)), max(r for _, r in rows)
    half = np.array([(w, r) for w, r in rows if w >= 0.5 * end])
    slope = np.polyfit(half[:, 0], half[:, 1], 1)[0] * 3600.0 if len(half) > 2 else float("nan")
    ok = final - baseline <= growth_mb
    print(f"memory: {len(rows)} samples over {end:.0f} s wall; RSS first sample {rows[0][1]:.1f} MiB, "
          f"second-quarter max {baseline:.1f} MiB, last-quarter max {final:.1f} MiB, peak {peak:.1f} MiB; "
          f"growth {final - baseline:+.2f} MiB (allowed {growth_mb}), second-half slope {slope:+.2f} MiB/h: "
          f"{'ok' if ok else 'GROWS'}")
    return ok


def state_items(path):
    """Every dataset's bytes and every attribute of /state and /gas, by path."""
    items = {}
    with h5py.File(path, "r") as f:
        for top in ("state", "gas"):
            if top not in f:
                continue
            def visit(name, obj, top=top):
                key = f"/{top}/{name}"
                if isinstance(obj, h5py.Dataset):
                    items[key] = (obj.dtype.str, obj.shape, obj[()].tobytes() if obj.size else b"")
                for a, v in obj.attrs.items():
                    items[f"{key}@{a}"] = np.asarray(v).tobytes()
            visit("", f[top])
            f[top].visititems(visit)
    return items


def checkpoint_time(path):
    with h5py.File(path, "r") as f:
        return float(f["state"].attrs["time"])


def resumes(carom, run, count):
    copies = sorted(glob.glob(run + ".checkpoints/*.h5")) + [os.path.join(run, "checkpoint.h5")]
    timed, seen = [], set()
    for c in copies:
        t = checkpoint_time(c)
        if t not in seen:
            seen.add(t)
            timed.append((t, c))
    timed.sort()
    pairs = len(timed) - 1
    print(f"checkpoints: {len(timed)} distinct, at t = " + ", ".join(f"{t:g}" for t, _ in timed) + " s")
    if pairs < 1:
        print("resume: fewer than two checkpoints, nothing to compare")
        return False
    chosen = sorted({round(i * (pairs - 1) / max(count - 1, 1)) for i in range(count)}) if count > 1 else [0]
    ok = True
    for k in chosen:
        (t0, c0), (t1, c1) = timed[k], timed[k + 1]
        folder = f"{run}.resume{k:03d}"
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(folder)
        shutil.copy(os.path.join(run, "run.h5"), os.path.join(folder, "run.h5"))
        shutil.copy(c0, os.path.join(folder, "checkpoint.h5"))
        rc = subprocess.run([carom, "resume", folder, "--end", repr(t1), "--quiet"]).returncode
        if rc != 0:
            print(f"resume {k}: carom resume from t = {t0!r} to {t1!r} exited {rc}")
            ok = False
            continue
        a, b = state_items(os.path.join(folder, "checkpoint.h5")), state_items(c1)
        differ = sorted(key for key in a.keys() | b.keys() if a.get(key) != b.get(key) and key not in WALL_CLOCK)
        same = not differ
        compared = len(a.keys() - WALL_CLOCK)
        print(f"resume {k}: from t = {t0!r} s to {t1!r} s: {compared} datasets and attributes of /state and /gas "
              + ("identical to the uninterrupted run's checkpoint" if same else f"DIFFER: {differ[:8]}"))
        ok &= same
        if same:
            shutil.rmtree(folder)
    return ok


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--carom", required=True)
    parser.add_argument("--run", required=True, help="the run's output folder")
    parser.add_argument("--growth-mb", type=float, default=8.0)
    parser.add_argument("--resumes", type=int, default=3)
    args = parser.parse_args()
    ok = memory(args.run, args.growth_mb)
    ok &= resumes(args.carom, args.run, args.resumes)
    print("soak: " + ("passed" if ok else "FAILED"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
