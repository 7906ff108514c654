#!/usr/bin/python3
"""The cloud-drag study (scenarios/scenes/cloud_drag.toml, cloud_drag.md): figures and a table.

    /usr/bin/python3 scenarios/plots/cloud_drag_plot.py LABEL=DIR[,DIR...] [LABEL=DIR...] [--out DIR]

Each LABEL names a group of runs (e.g. the cloud seeds of one method): `ed=runs/ed1,runs/ed2`.
A DIR may also be a sweep's output (OUT/cases/*): then every case is a group of its own, keyed by
the tagged group's initial speed. Reads each run's run.h5 (/timeseries tagged_mean_velocity,
tagged_mean_force) and summary.json (wall_seconds, analysis.tagged_bodies), and writes to --out
(default: the current directory):
  cloud_drag_velocity.png  Vz(t) of the tagged group, mean over the runs of each label with the
                           band of +- one standard deviation over them;
  cloud_drag_force.png     the mean collision force along z per sample window against time, mean
                           over the runs, beside Syamlal's solid-solid drag (below) evaluated at
                           the measured mean velocity;
and prints a Markdown table per label: k of 1/V = 1/V0 + k t over the whole record (carom's
summary.json fit: mean and standard deviation over the runs, and the mean of the fits' own
standard errors) and over the first EARLY seconds only (the same least squares, here), the
equivalent drag coefficient C_D = F / (rho_bulk A V^2 / 2) = (4/3) rho_b D k / (phi rho_s) of
each, the drag's own k = -F / (m V^2) in the first sample window and over the last 4 ms
(F: the window-mean collision force; V: the mean velocity over the same samples), and the wall
time per run.

Syamlal's solid-solid momentum exchange coefficient (Syamlal 1987, as MFiX states and codes it:
"Summary of MFIX Equations 2005-4", Benyahia, Syamlal & O'Brien, section D "Solids/solids
momentum exchange coefficient"; MFiX source drag_ss.f, subroutines DRAG_SS and DES_DRAG_SS):
  F_lm = 3 (1 + e) (pi/2 + C_f pi^2/8) (d_l + d_m)^2 / (2 pi (rho_l d_l^3 + rho_m d_m^3))
         * rho_l eps_l * rho_m eps_m * g0_lm * |v_l - v_m|      (kg/(m^3 s), force per volume / dv)
  g0_lm = 1/eps_g + 3 d_l d_m / (eps_g^2 (d_l + d_m)) * sum_k eps_k / d_k     (Lebowitz)
For one big sphere l (eps_l -> 0) the force on it is F_lm |dv| V_l / eps_l, i.e.
  F = 3 (1 + e)(pi/2 + C_f pi^2/8)(D + d)^2 / (2 pi (rho_b D^3 + rho_s d^3)) rho_b phi rho_s g0 V^2 (pi/6) D^3,
with C_f the friction coefficient (the scene's mu) and e the restitution, eps_g = 1 - phi.
Needs numpy, h5py and matplotlib (Debian packages); run files are read by carom_reader.py.
"""
import argparse
import glob
import math
import os
import sys

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from carom_reader import open_run  # noqa: E402

# The study (cloud_drag.toml).
D, RHO_B = 3.6e-3, 500.0       # big sphere: m, kg/m^3
d, RHO_S = 0.3e-3, 2500.0      # cloud: m, kg/m^3
PHI, E, MU = 0.05, 0.7, 0.3    # solid fraction, restitution, friction
EARLY = 5e-3                   # s: the early window of the second fit


def syamlal_k():
    """k = F / (m V^2) of Syamlal's drag on one big sphere in the cloud, 1/m."""
    eps_g = 1.0 - PHI
    g0 = 1.0 / eps_g + 3.0 * D * d / (eps_g ** 2 * (D + d)) * (PHI / d)
    const = 3.0 * (1.0 + E) * (math.pi / 2 + MU * math.pi ** 2 / 8) * (D + d) ** 2 / (
        2.0 * math.pi * (RHO_B * D ** 3 + RHO_S * d ** 3))
    force_per_v2 = const * RHO_B * PHI * RHO_S * g0 * math.pi / 6 * D ** 3
    return force_per_v2 / (RHO_B * math.pi / 6 * D ** 3)


def drag_coefficient(k):
    """C_D of F = C_D rho_bulk A V^2 / 2 from F = m k V^2."""
    return 4.0 / 3.0 * RHO_B * D * k / (PHI * RHO_S)


def fit_k(t, v):
    """Least-squares slope k of 1/V = a + k t (V > 0), as scenarios/analysis/drag_fit.cpp."""
    keep = v > 0
    return np.polyfit(t[keep], 1.0 / v[keep], 1)[0]


def read_run(path):
    run = open_run(path)
    velocity = run.series("tagged_mean_velocity")
    t, v = velocity.time, velocity.values
    force = run.series("tagged_mean_force").values
    summary = run.summary
    fit = summary["analysis"]["tagged_bodies"]["inverse_speed_fit"]
    return {"t": t, "vz": v[:, 2], "fz": force[:, 2], "k": fit["k"], "k_error": fit["k_error"],
            "wall": summary.get("wall_seconds", float("nan")), "status": summary.get("status")}


def groups_from(arguments):
    groups = {}
    for argument in arguments:
        label, _, dirs = argument.partition("=")
        for path in dirs.split(","):
            cases = sorted(glob.glob(os.path.join(path, "cases", "*")))
            if cases:  # a sweep: group by initial speed
                for case in cases:
                    run = read_run(case)
                    groups.setdefault(f"{label} V0={run['vz'][0]:g}", []).append(run)
            else:
                groups.setdefault(label, []).append(read_run(path))
    return groups


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("groups", nargs="+", help="LABEL=DIR[,DIR...]")
    parser.add_argument("--out", default=".")
    args = parser.parse_args()
    groups = groups_from(args.groups)
    k_s = syamlal_k()

    fig_v, ax_v = plt.subplots(figsize=(6.4, 4.2))
    fig_f, ax_f = plt.subplots(figsize=(6.4, 4.2))
    print("| runs | n | V(end) m/s, mean +- sd | k (1/m), whole record: mean +- sd over runs | "
          "mean fit s.e. | C_D | k, first 5 ms | C_D, first 5 ms | -F/(m V^2), first window | "
          "-F/(m V^2), last 4 ms | wall s per run |\n|---|---|---|---|---|---|---|---|---|---|---|")
    for label, runs in groups.items():
        rows = min(len(r["t"]) for r in runs)
        t = runs[0]["t"][:rows] * 1e3
        vz = np.array([r["vz"][:rows] for r in runs])
        fz = np.array([r["fz"][:rows] for r in runs])
        mean, sd = vz.mean(axis=0), vz.std(axis=0, ddof=1) if len(runs) > 1 else np.zeros(rows)
        line, = ax_v.plot(t, mean, label=f"{label} ({len(runs)} runs)")
        ax_v.fill_between(t, mean - sd, mean + sd, color=line.get_color(), alpha=0.25)
        f_mean = fz.mean(axis=0)  # row 0 (no window yet) is NaN
        ax_f.plot(t[1:], -f_mean[1:] * 1e3, color=line.get_color(), label=f"{label}: measured")
        ax_f.plot(t, k_s * RHO_B * math.pi / 6 * D ** 3 * mean ** 2 * 1e3, "--", color=line.get_color(),
                  label=f"{label}: Syamlal at measured V")
        ks = np.array([r["k"] for r in runs])
        early = np.array([fit_k(r["t"][r["t"] <= EARLY + 1e-12], r["vz"][r["t"] <= EARLY + 1e-12])
                          for r in runs])
        spread = (lambda x: x.std(ddof=1)) if len(runs) > 1 else (lambda x: float("nan"))
        mass = RHO_B * math.pi / 6 * D ** 3
        late = [r["t"] >= r["t"][-1] - 4e-3 + 1e-12 for r in runs]
        k_first = np.array([-r["fz"][1] / (mass * r["vz"][:2].mean() ** 2) for r in runs])
        k_last = np.array([-r["fz"][w].mean() / (mass * r["vz"][w].mean() ** 2) for r, w in zip(runs, late)])
        print(f"| {label} | {len(runs)} | {mean[-1]:.4f} +- {sd[-1]:.4f} | {ks.mean():.2f} +- "
              f"{spread(ks):.2f} | {np.mean([r['k_error'] for r in runs]):.2f} | "
              f"{drag_coefficient(ks.mean()):.3f} | {early.mean():.1f} +- {spread(early):.1f} | "
              f"{drag_coefficient(early.mean()):.3f} | {k_first.mean():.0f} +- {spread(k_first):.0f} | "
              f"{k_last.mean():.1f} +- {spread(k_last):.1f} | {np.mean([r['wall'] for r in runs]):.1f} |")
    ax_v.set_xlabel("t (ms)")
    ax_v.set_ylabel("V_z of the tagged group (m/s)")
    ax_v.set_title("Big sphere(s) in the cloud: mean +- sd over cloud seeds")
    ax_v.legend(fontsize=8)
    ax_v.grid(alpha=0.3)
    fig_v.tight_layout()
    fig_v.savefig(os.path.join(args.out, "cloud_drag_velocity.png"), dpi=120)
    ax_f.set_xlabel("t (ms)")
    ax_f.set_ylabel("drag: -F_z per sphere (mN)")
    ax_f.set_title("Collision force per sample window, mean over runs")
    ax_f.legend(fontsize=7)
    ax_f.grid(alpha=0.3)
    fig_f.tight_layout()
    fig_f.savefig(os.path.join(args.out, "cloud_drag_force.png"), dpi=120)
    print(f"\nSyamlal (e = {E}, C_f = {MU}, phi = {PHI}): k = {k_s:.3f} 1/m, C_D = {drag_coefficient(k_s):.3f}")


if __name__ == "__main__":
    main()
