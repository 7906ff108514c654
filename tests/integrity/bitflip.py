#!/usr/bin/python3
"""Bit-flip campaign on the restore path: per method, a short run, then FLIPS copies of its
checkpoint.h5 each with one random bit of one dataset's stored values flipped, each resumed
for a few steps with `carom resume`. Every flip must be refused (exit 1 or 2, no signal) or
give the same final state as the undamaged resume (a bit that carries no information);
a crash (a signal) or a silent change (exit 0, another final state) fails the campaign.

Usage: bitflip.py CAROM [--flips N] [--seed S] [--methods m1,m2] [--work DIR]
Methods: event_driven, soft_sphere, monte_carlo (a small gas of two species), and the shipped
scenes made small: gas (fluidized_bed.toml, event-driven with its gas) and inflow
(duct_flow.toml with its inflow and outflow, soft spheres).
Prints one row per method: method, flips, refused, same, crashes, silent. Exit 0 when crashes
and silent changes are both 0. Needs Debian's python3-h5py and python3-numpy.
"""
import argparse
import os
import random
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

GAS = """[domain]
min = [0, 0, 0]
max = [8.0, 8.0, 8.0]
periodic = ["x", "y", "z"]
[[species]]
name = "a"
diameter = 1.0
density = 1.909859317102744
fill = { volume_fraction = 0.25 }
young_modulus = 1e6
poisson_ratio = 0.3
[[species]]
name = "b"
diameter = 0.6
density = 1.909859317102744
fill = { count = 100 }
young_modulus = 1e6
poisson_ratio = 0.3
[collisions]
default = { e = 0.95, mu = 0.2, beta0 = 0.3 }
[initial]
temperature = 1.0
[time]
end = 1.0
[output]
snapshot_every = 0.5
sample_every = 0.1
"""


def datasets_with_storage(path):
    """(name, file offset, bytes) of every contiguous dataset holding data."""
    found = []
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                offset = obj.id.get_offset()
                size = obj.id.get_storage_size()
                if offset is not None and size > 0:
                    found.append((name, offset, size))
        f.visititems(visit)
    return found


def final_state(folder):
    """Every dataset of the checkpoint's /state, as bytes (NaN-safe comparison)."""
    state = {}
    with h5py.File(os.path.join(folder, "checkpoint.h5"), "r") as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                state[name] = np.asarray(obj[()]).tobytes()
        f["state"].visititems(visit)
        state["time"] = np.float64(f["state"].attrs["time"]).tobytes()
    return state


def resume(carom, folder, end):
    result = subprocess.run([carom, "resume", folder, "--end", str(end), "--quiet"],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60)
    return result.returncode, result.stdout.decode(errors="replace")


SCENES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenarios", "scenes")

# The other cases: (scene, extra arguments of `carom run`, time to resume to).
CASES = {
    "gas": ("fluidized_bed.toml",
            ["--set", "species.glass.fill.count=150", "--set", "domain.max=[0.008, 0.004, 0.03]",
             "--set", "regions.bed.max=[0.008, 0.004, 0.015]", "--set", "gas.cells=[4, 1, 10]",
             "--set", "initial.settle_time=0.05", "--set", "time.end=0.02"], 0.022),
    "inflow": ("duct_flow.toml", ["--method", "soft_sphere", "--set", "time.end=0.05"], 0.052),
}


def campaign(carom, method, flips, rng, work):
    base = os.path.join(work, method)
    if method in CASES:
        name, extra, end = CASES[method]
        scene = os.path.join(SCENES, name)
        subprocess.run([carom, "run", scene, "--out", base, "--quiet"] + extra, check=True)
    else:
        scene = os.path.join(work, "gas.toml")
        with open(scene, "w") as out:
            out.write(GAS)
        subprocess.run([carom, "run", scene, "--method", method, "--out", base, "--quiet"], check=True)
        end = 1.1
    reference = os.path.join(work, method + "_reference")
    shutil.copytree(base, reference)
    code, text = resume(carom, reference, end)
    if code != 0:
        raise SystemExit(f"{method}: the undamaged resume failed ({code}): {text}")
    expected = final_state(reference)
    targets = datasets_with_storage(os.path.join(base, "checkpoint.h5"))
    total = sum(size for _, _, size in targets)
    counts = {"refused": 0, "same": 0, "crashes": 0, "silent": 0}
    for k in range(flips):
        # A byte uniformly over all stored values, then one of its bits.
        at = rng.randrange(total)
        for name, offset, size in targets:
            if at < size:
                break
            at -= size
        bit = rng.randrange(8)
        damaged = os.path.join(work, f"{method}_flip")
        shutil.rmtree(damaged, ignore_errors=True)
        shutil.copytree(base, damaged)
        with open(os.path.join(damaged, "checkpoint.h5"), "r+b") as f:
            f.seek(offset + at)
            byte = f.read(1)[0]
            f.seek(offset + at)
            f.write(bytes([byte ^ (1 << bit)]))
        code, text = resume(carom, damaged, end)
        where = f"{name} byte {at} bit {bit}"
        if code < 0 or code >= 128:
            counts["crashes"] += 1
            print(f"  CRASH {method}: {where}: exit {code}: {text[-300:]}", file=sys.stderr)
        elif code != 0:
            counts["refused"] += 1
        elif final_state(damaged) == expected:
            counts["same"] += 1
        else:
            counts["silent"] += 1
            print(f"  SILENT {method}: {where}", file=sys.stderr)
    return counts


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("carom")
    parser.add_argument("--flips", type=int, default=200)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--methods", default="event_driven,soft_sphere,monte_carlo,gas,inflow")
    parser.add_argument("--work", default=None, help="folder for the runs (default: a temporary one, removed)")
    args = parser.parse_args()
    rng = random.Random(args.seed)
    work = args.work or tempfile.mkdtemp(prefix="carom_bitflip_")
    failed = False
    try:
        print(f"{'method':<14} {'flips':>6} {'refused':>8} {'same':>6} {'crashes':>8} {'silent':>7}")
        for method in args.methods.split(","):
            c = campaign(args.carom, method, args.flips, rng, work)
            print(f"{method:<14} {args.flips:>6} {c['refused']:>8} {c['same']:>6} {c['crashes']:>8} {c['silent']:>7}",
                  flush=True)
            failed |= c["crashes"] > 0 or c["silent"] > 0
    finally:
        if args.work is None:
            shutil.rmtree(work, ignore_errors=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
