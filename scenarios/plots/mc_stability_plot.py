#!/usr/bin/python3
"""The Monte Carlo stability map (scenarios/scenes/stability_monte_carlo.toml): the Monte Carlo
model's collision frequency and mean temperature against the exact event-driven result of the
same scene and seeds, against solid fraction, with the 5 % boundary drawn.

    mc_stability_plot.py EXACT_OUT MC_OUT FIGURE.png [--tolerance 0.05] [--csv TABLE.csv]

EXACT_OUT and MC_OUT are the two sweeps' output folders (summary.csv, cases/NNNN/result.json).
Per solid fraction and variant: the mean m and standard error s (sd / sqrt(n), n - 1 in the sd)
over the completed seeds; the relative error E = m_mc / m_ed - 1 with the uncertainty
u = sqrt(s_mc^2 + (m_mc / m_ed)^2 s_ed^2) / |m_ed| (as carom chart computes it, CHARTS.md); the
boundary is the solid fraction where |E| - u first exceeds the tolerance (the error is outside it
by more than its uncertainty), interpolated linearly in log(phi) between the two sweep points
around it. Prints the table (and writes it with --csv).
"""
import argparse
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

N_PARTICLES = 2000  # mc_gas.toml
SPHERE = math.pi / 6.0  # volume of a sphere of diameter 1
OBSERVABLES = [
    ("analysis.collision_frequency.grain-grain", "collision frequency"),
    ("mean_temperature", "mean temperature (velocity variance)"),
]


def fail(message):
    sys.exit("mc_stability_plot.py: error: " + message)


def rows(out):
    path = os.path.join(out, "summary.csv")
    if not os.path.exists(path):
        fail(path + " not found (run the sweep first)")
    with open(path, newline="") as f:
        table = list(csv.DictReader(f))
    for r in table:
        result = os.path.join(out, "cases", "%04d" % int(r["case"]), "result.json")
        r["cpu_seconds"] = json.load(open(result)).get("cpu_seconds", float("nan")) if os.path.exists(result) else float("nan")
    return table


def phi_of(row):
    edge = float(row["domain.max"].strip("[]").split(",")[0])
    return N_PARTICLES * SPHERE / edge**3


def stats(values):
    v = np.array([x for x in values if math.isfinite(x)])
    if len(v) == 0:
        return float("nan"), float("nan"), 0
    return float(v.mean()), float(v.std(ddof=1) / math.sqrt(len(v))) if len(v) > 1 else float("nan"), len(v)


def group(table, label_of):
    groups = {}
    for r in table:
        if r["status"] != "completed":
            continue
        groups.setdefault((label_of(r), round(phi_of(r), 5)), []).append(r)
    return groups


def boundary(phis, errors, uncertainties, tolerance):
    """First phi where |E| - u > tolerance (the error exceeds the tolerance by more than its
    uncertainty), interpolated linearly in log(phi) on |E| - u; None: never; phis[0]: always."""
    m = [abs(e) - u for e, u in zip(errors, uncertainties)]
    for k, p in enumerate(phis):
        if m[k] > tolerance:
            if k == 0:
                return p
            f = (tolerance - m[k - 1]) / (m[k] - m[k - 1])
            return math.exp(math.log(phis[k - 1]) + f * (math.log(p) - math.log(phis[k - 1])))
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("exact")
    parser.add_argument("mc")
    parser.add_argument("figure")
    parser.add_argument("--tolerance", type=float, default=0.05)
    parser.add_argument("--csv")
    a = parser.parse_args()

    exact = group(rows(a.exact), lambda r: "event-driven")
    mc = group(rows(a.mc), lambda r: "%s, %s" % (r["monte_carlo.contact_value"], r["monte_carlo.partner"]))
    variants = sorted({k[0] for k in mc}, key=lambda s: (not s.startswith("enskog"), s))
    phis = sorted({k[1] for k in exact})
    table = []
    results = {}
    for v in variants:
        for p in phis:
            ref, cur = exact.get(("event-driven", p)), mc.get((v, p))
            if not ref or not cur:
                continue
            line = {"variant": v, "phi": p, "seeds": len(cur)}
            for key, _ in OBSERVABLES:
                mr, sr, _ = stats([float(r[key]) for r in ref])
                mv, sv, _ = stats([float(r[key]) for r in cur])
                e = mv / mr - 1.0
                u = math.sqrt(sv**2 + (mv / mr) ** 2 * sr**2) / abs(mr)
                line[key + ":exact"], line[key + ":mc"] = mr, mv
                line[key + ":error"], line[key + ":uncertainty"] = e, u
                results.setdefault((v, key), []).append((p, e, u))
            cpu_ed = stats([float(r["cpu_seconds"]) for r in ref])[0]
            cpu_mc = stats([float(r["cpu_seconds"]) for r in cur])[0]
            line["cpu_exact"], line["cpu_mc"] = cpu_ed, cpu_mc
            table.append(line)

    keys = list(table[0].keys()) if table else []
    print("\t".join(keys))
    for line in table:
        print("\t".join(("%.4g" % line[k]) if isinstance(line[k], float) else str(line[k]) for k in keys))
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=keys)
            w.writeheader()
            w.writerows(table)

    colours = {"enskog, gaussian": "#1f77b4", "enskog, cell_particle": "#2ca02c",
               "none, gaussian": "#d62728", "none, cell_particle": "#ff7f0e"}
    markers = {"gaussian": "o", "cell_particle": "s"}
    fig, axes = plt.subplots(1, 2, figsize=(10.5, 4.2), sharex=True)
    tol = 100 * a.tolerance
    x = np.geomspace(min(phis) * 0.8, max(phis) * 1.25, 200)
    g0 = (1 - x / 2) / (1 - x) ** 3
    print("\nboundaries (|error| - uncertainty > %g %%):" % tol)
    for ax, (key, title) in zip(axes, OBSERVABLES):
        ax.axhspan(-tol, tol, color="0.92", zorder=0)
        ax.axhline(0, color="0.5", lw=0.8)
        if key.startswith("analysis.collision"):
            ax.plot(x, 100 * (1 / g0 - 1), color="0.4", ls=":", lw=1.2,
                    label="Boltzmann / Enskog - 1 (1/g0 - 1)")
        for v in variants:
            pts = results.get((v, key), [])
            if not pts:
                continue
            p, e, u = (np.array(c) for c in zip(*pts))
            ax.errorbar(p, 100 * e, yerr=100 * u, color=colours.get(v, "k"), marker=markers[v.split(", ")[1]],
                        ms=4.5, lw=1.3, capsize=2.5, label="contact value " + v.replace(", ", ", partner "))
            b = boundary(list(p), list(e), list(u), a.tolerance)
            print("  %-40s %-24s %s" % (key, v, "none up to %g" % max(p) if b is None else "phi = %.3g" % b))
            if b is not None:
                ax.axvline(b, color=colours.get(v, "k"), ls="--", lw=1.0, alpha=0.8)
        ax.set_xscale("log")
        ax.set_xlabel("solid fraction $\\phi$")
        ax.set_ylabel("Monte Carlo / event-driven $-$ 1 (%)")
        ax.set_title(title, fontsize=11)
        ax.text(0.02, 0.96, "shaded: $\\pm$%g %%; dashed: |error| $-$ uncertainty = %g %%" % (tol, tol),
                transform=ax.transAxes, fontsize=8, va="top", color="0.3")
        ax.grid(True, which="major", color="0.85", lw=0.6)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=3, fontsize=8.5, frameon=False)
    fig.suptitle("Monte Carlo collisions against exact events: 2000 elastic spheres, mean $\\pm$ standard error "
                 "over seeds", fontsize=11)
    fig.tight_layout(rect=(0, 0.1, 1, 0.95))
    fig.savefig(a.figure, dpi=150)
    print("wrote " + a.figure)


if __name__ == "__main__":
    main()
