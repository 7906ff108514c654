#!/usr/bin/python3
"""The convergent duct's section numbers (convergent_duct.md): each run's profiles
([analysis.profiles] in summary.json) reduced to a few figures per section, and its collision
frequencies per bead present.

    /usr/bin/python3 scenarios/plots/duct_sections.py LABEL=RUN_DIR [LABEL=RUN_DIR ...]
    /usr/bin/python3 scenarios/plots/duct_sections.py --sweep SWEEP_OUT

With --sweep, the completed cases of a sweep (convergent_duct_sweep.toml) are grouped by their
varied keys, and each number is the mean +- the standard deviation over the group's seeds.

Per section: the solid fraction over the bins whose centres lie within 2 cm of the duct's
middle (x = 0.15 m), the mean Vz averaged over the section's bins weighted by their solid
fraction, and the spreads of Vx and Vz: the root of the bins' variances averaged with the same
weights (the spread within the bins; the mean's change across the section is not in it). Prints a markdown table, then the
collision frequencies (glass-glass and glass with the walls, per bead present, 1/s).
"""
import json
import os
import sys

import numpy as np

MIDDLE, HALF_WIDTH = 0.15, 0.02  # m


def reduce(summary):
    p = summary["analysis"]["profiles"]
    x = np.asarray(p["bin_centres"], dtype=float)
    centre = np.abs(x - MIDDLE) <= HALF_WIDTH + 1e-12
    rows = []
    for s in p["sections"]:
        phi = np.asarray(s["solid_fraction"], dtype=float)
        mean = np.array([[np.nan if v is None else v for v in b] for b in s["mean_velocity"]])
        std = np.array([[np.nan if v is None else v for v in b] for b in s["std_velocity"]])
        ok = np.isfinite(mean[:, 2]) & (phi > 0)
        w = phi[ok] / phi[ok].sum()
        rows.append((s["height"], phi[centre].mean(), (w * mean[ok, 2]).sum(),
                     np.sqrt((w * std[ok, 0] ** 2).sum()), np.sqrt((w * std[ok, 2] ** 2).sum())))
    return rows


def read_summary(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


def frequencies_of(summary):
    cf = summary["analysis"].get("collision_frequency", {})
    return cf.get("glass-glass"), cf.get("glass@walls")


def sweep_groups(out):
    """{label: [case folder, ...]} of the completed cases, in case order."""
    groups = {}
    cases = os.path.join(out, "cases")
    for name in sorted(os.listdir(cases)):
        folder = os.path.join(cases, name)
        try:
            with open(os.path.join(folder, "result.json")) as f:
                if json.load(f)["status"] != "completed":
                    continue
            with open(os.path.join(folder, "case.json")) as f:
                case = json.load(f)
        except (OSError, ValueError, KeyError):
            continue
        label = ", ".join(key.split(".")[-1] + " " + value.strip('"')
                          for key, value in (o.split("=", 1) for o in case["overrides"]))
        groups.setdefault(label, []).append(folder)
    return groups


def pm(values, fmt):
    values = np.asarray(values, dtype=float)
    if len(values) < 2:
        return format(values[0], fmt)
    return f"{format(values.mean(), fmt)} +- {format(values.std(ddof=1), fmt)}"


def main_sweep(out):
    groups = sweep_groups(out)
    print("| case (seeds) | CPU s | z (m) | solid fraction x 1e3, centre 4 cm | mean Vz (m/s) | sd Vx (m/s) | sd Vz (m/s) |")
    print("|---|---|---|---|---|---|---|")
    frequencies = []
    for label, folders in groups.items():
        summaries = [read_summary(f) for f in folders]
        cpu = []
        for f in folders:
            with open(os.path.join(f, "result.json")) as r:
                cpu.append(json.load(r)["cpu_seconds"])
        rows = np.array([reduce(s) for s in summaries])  # case, section, quantity
        for k in range(rows.shape[1]):
            head = f"| {label} ({len(folders)}) | {pm(cpu, '.0f')}" if k == 0 else "| |"
            r = rows[:, k, :]
            print(f"{head} | {r[0, 0]:.2f} | {pm(r[:, 1] * 1e3, '.2f')} | {pm(r[:, 2], '.2f')} | "
                  f"{pm(r[:, 3], '.2f')} | {pm(r[:, 4], '.2f')} |")
        f = np.array([frequencies_of(s) for s in summaries], dtype=float)
        frequencies.append((label, pm(f[:, 0], ".2f"), pm(f[:, 1], ".2f")))
    print()
    print("| case | glass-glass (1/s) | walls (1/s) |")
    print("|---|---|---|")
    for label, gg, gw in frequencies:
        print(f"| {label} | {gg} | {gw} |")


def main(argv):
    if len(argv) == 3 and argv[1] == "--sweep":
        return main_sweep(argv[2])
    if len(argv) < 2:
        sys.exit(__doc__)
    print("| run | wall s | z (m) | solid fraction, centre 4 cm | mean Vz (m/s) | sd Vx (m/s) | sd Vz (m/s) |")
    print("|---|---|---|---|---|---|---|")
    frequencies = []
    for arg in argv[1:]:
        label, _, folder = arg.partition("=")
        summary = read_summary(folder)
        for k, (z, phi, vz, sx, sz) in enumerate(reduce(summary)):
            head = f"| {label} | {summary['wall_seconds']:.0f}" if k == 0 else "| |"
            print(f"{head} | {z:.2f} | {phi:.3g} | {vz:.2f} | {sx:.2f} | {sz:.2f} |")
        frequencies.append((label, *frequencies_of(summary)))
    print()
    print("| run | glass-glass (1/s) | walls (1/s) |")
    print("|---|---|---|")
    for label, gg, gw in frequencies:
        print(f"| {label} | {gg:.3g} | {gw:.3g} |")


if __name__ == "__main__":
    main(sys.argv)
