#!/usr/bin/python3
"""The convergent duct's section numbers (convergent_duct.md): each run's profiles
([analysis.profiles] in summary.json) reduced to a few figures per section, and its collision
frequencies per bead present.

    /usr/bin/python3 scenarios/plots/duct_sections.py LABEL=RUN_DIR [LABEL=RUN_DIR ...]

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


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    print("| run | wall s | z (m) | solid fraction, centre 4 cm | mean Vz (m/s) | sd Vx (m/s) | sd Vz (m/s) |")
    print("|---|---|---|---|---|---|---|")
    frequencies = []
    for arg in argv[1:]:
        label, _, folder = arg.partition("=")
        with open(os.path.join(folder, "summary.json")) as f:
            summary = json.load(f)
        for k, (z, phi, vz, sx, sz) in enumerate(reduce(summary)):
            head = f"| {label} | {summary['wall_seconds']:.0f}" if k == 0 else "| |"
            print(f"{head} | {z:.2f} | {phi:.3g} | {vz:.2f} | {sx:.2f} | {sz:.2f} |")
        cf = summary["analysis"].get("collision_frequency", {})
        frequencies.append((label, cf.get("glass-glass"), cf.get("glass@walls")))
    print()
    print("| run | glass-glass (1/s) | walls (1/s) |")
    print("|---|---|---|")
    for label, gg, gw in frequencies:
        print(f"| {label} | {gg:.3g} | {gw:.3g} |")


if __name__ == "__main__":
    main(sys.argv)
