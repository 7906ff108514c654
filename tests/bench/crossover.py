#!/usr/bin/python3
"""Which method is the fastest for the same error on a dilute elastic gas (the methods' crossover):
the CPU cost per simulated collision time of the event-driven, soft-sphere and Monte Carlo
methods against the particle count N and the solid fraction phi.

    tests/bench/crossover.py run   OUT [--carom build/release/scenarios/carom] [--n 500 2000 8000]
                                       [--phi 0.01 0.05 0.2] [--collisions 50] [--seed 1 2 3]
                                       [--methods event_driven soft_sphere monte_carlo]
    tests/bench/crossover.py plot  OUT FIGURE.png [--tolerance 0.02]

`run` runs scenarios/scenes/mc_gas.toml (elastic spheres in a periodic box) at each (N, phi),
once per method, for `--collisions` Enskog collision times (1 / nu, nu = 4 n d^2 g0 sqrt(pi T/m)),
and writes OUT/crossover.csv (a later run into the same OUT adds its rows): the method, N, phi, the process's CPU time (user + system, from
wait4 via os.wait4), the simulated time, the measured collision frequency (summary.json's
analysis.collision_frequency.grain-grain) and its error against the event-driven run of the same
N, phi and seed. The methods, each at the setting that reaches the dilute-gas chart's tolerance
(2 % on the collision frequency, scenarios/scenes/dilute_gas_chart.toml):
  event-driven  exact;
  soft sphere   linear contacts with a binary contact time of 0.015 mean free times and a step of
                a tenth of it (the chart's "soft tc=0.02 dt=tc/10": 0.015 mean free times there,
                -1.2 % +- 0.35 %, at 8 times the event-driven cost), the contact time at most
                0.015 s: longer, softer contacts overlap by more than max_overlap (a tenth of the
                radius) in the Maxwellian's fast tail (t_c = 0.108 s at phi = 0.01 stopped so);
  Monte Carlo   automatic step and cells, Enskog contact value, partners drawn from the cell's
                particles (no heating: scenarios/chart/CHARTS.md).
The cost is CPU seconds per simulated collision time of the run loop: each point is run twice,
for `--collisions` and for a fifth of it, and the cost is the difference of the two CPU times over
the difference of the simulated times times nu, so that process start, placing and outputs (about
0.1 CPU s a run) cancel. `plot` draws the cost
against N per phi, a method's point open where its measured error exceeds the tolerance, and
names the fastest method within the tolerance at each point. With several seeds, each point's
cost is the mean over the seeds, and a method is within the tolerance where one run's
root-mean-square error is, sqrt(mean^2 + sd^2) over the seeds: a user runs once, and the Monte
Carlo method's single runs scatter far more than their mean is biased.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenarios", "scenes", "mc_gas.toml")
METHODS = ["event_driven", "soft_sphere", "monte_carlo"]
LABELS = {"event_driven": "event-driven", "soft_sphere": "soft spheres (t_c = 0.015 mean free time, step t_c/10)",
          "monte_carlo": "Monte Carlo (Enskog, cell partners)"}


def enskog_frequency(phi):
    g0 = (1 - phi / 2) / (1 - phi) ** 3
    return 4 * (6 * phi / math.pi) * g0 * math.sqrt(math.pi)  # d = m = T = 1


def method_set(method, phi):
    if method == "event_driven":
        return ["method.kind=event_driven"]
    if method == "monte_carlo":
        return ["method.kind=monte_carlo", "monte_carlo.contact_value=enskog", "monte_carlo.partner=cell_particle"]
    tc = min(0.015 / enskog_frequency(phi), 0.015)
    return ["method.kind=soft_sphere", "soft_sphere.contact_model=linear", "soft_sphere.contact_time=%.6g" % tc,
            "soft_sphere.step_fraction=0.1"]


def run_case(carom, out, method, n, phi, collisions, seed):
    edge = (n * math.pi / 6 / phi) ** (1 / 3)
    end = collisions / enskog_frequency(phi)
    case = os.path.join(out, "cases", "%s_n%d_phi%g_c%g_s%d" % (method, n, phi, collisions, seed))
    sets = ["domain.max=[%.6g,%.6g,%.6g]" % (edge, edge, edge), "species.grain.fill.count=%d" % n,
            "time.end=%.6g" % end, "output.snapshot_every=%.6g" % end, "output.checkpoint_every=%.6g" % end,
            "output.sample_every=%.6g" % (end / 20)] + method_set(method, phi)
    cmd = ["nice", carom, "run", SCENE, "--out", case, "--overwrite", "--quiet", "--seed", str(seed)]
    for s in sets:
        cmd += ["--set", s]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    err = proc.stderr.read().decode()
    if status != 0:
        print("failed: " + " ".join(cmd) + "\n" + err, file=sys.stderr)
        return None
    summary = json.load(open(os.path.join(case, "summary.json")))
    return {"method": method, "n": n, "phi": phi, "seed": seed, "cpu_seconds": usage.ru_utime + usage.ru_stime,
            "simulated_seconds": summary["end_time"],
            "frequency": summary["analysis"]["collision_frequency"]["grain-grain"],
            "enskog_frequency": enskog_frequency(phi)}


def run(a):
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for phi, n, seed in ((phi, n, seed) for phi in a.phi for n in a.n for seed in a.seed):
            exact = None
            for method in a.methods:
                short = run_case(a.carom, a.out, method, n, phi, a.collisions / 5, seed)
                r = run_case(a.carom, a.out, method, n, phi, a.collisions, seed)
                if r is None or short is None:
                    continue
                r["cpu_seconds_short"] = short["cpu_seconds"]
                r["cost"] = (r["cpu_seconds"] - short["cpu_seconds"]) / (
                    (r["simulated_seconds"] - short["simulated_seconds"]) * r["enskog_frequency"])
                if method == "event_driven":
                    exact = r["frequency"]
                r["error"] = r["frequency"] / exact - 1 if exact else float("nan")
                rows.append(r)
                print("%-13s N=%-6d phi=%-5g seed %d cpu %.3f s  cost %.4g CPU s per collision time  error %+.2f %%" %
                      (method, n, phi, seed, r["cpu_seconds"], r["cost"], 100 * r["error"]), flush=True)
    path = os.path.join(a.out, "crossover.csv")
    old = os.path.exists(path)  # a run into the same OUT adds its rows (other N, phi or methods)
    with open(path, "a" if old else "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        if not old:
            w.writeheader()
        w.writerows(rows)


def mean_over_seeds(rows):
    """One row per (method, N, phi): the mean cost and error over its seeds, the standard deviation
    of one run's error (0 with one seed) and the number of seeds."""
    groups = {}
    for r in rows:
        groups.setdefault((r["method"], r["n"], r["phi"]), []).append(r)
    out = []
    for (method, n, phi), rs in groups.items():
        errors = [r["error"] for r in rs]
        mean = sum(errors) / len(errors)
        sd = math.sqrt(sum((e - mean) ** 2 for e in errors) / (len(errors) - 1)) if len(errors) > 1 else 0.0
        out.append({"method": method, "n": n, "phi": phi, "cost": sum(r["cost"] for r in rs) / len(rs),
                    "mean_error": mean, "error_sd": sd, "error": math.sqrt(mean ** 2 + sd ** 2),
                    "seeds": len(rs)})
    return out


def plot(a):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    with open(os.path.join(a.out, "crossover.csv"), newline="") as f:
        rows = [dict(r) for r in csv.DictReader(f)]
    for r in rows:
        for k in ("n", "phi", "cost", "error", "cpu_seconds"):
            r[k] = float(r[k])
    rows = mean_over_seeds(rows)
    phis = sorted({r["phi"] for r in rows})
    colours = {"event_driven": "#1f77b4", "soft_sphere": "#d62728", "monte_carlo": "#2ca02c"}
    markers = {"event_driven": "o", "soft_sphere": "s", "monte_carlo": "^"}
    fig, axes = plt.subplots(1, len(phis), figsize=(3.6 * len(phis), 3.9), sharex=True, sharey=True)
    axes = [axes] if len(phis) == 1 else axes
    print("fastest within %g %%:" % (100 * a.tolerance))
    for ax, phi in zip(axes, phis):
        for m in METHODS:
            pts = sorted((r for r in rows if r["phi"] == phi and r["method"] == m), key=lambda r: r["n"])
            if not pts:
                continue
            ax.plot([r["n"] for r in pts], [r["cost"] for r in pts], color=colours[m], lw=1.2, alpha=0.6)
            for r in pts:
                ok = abs(r["error"]) <= a.tolerance
                ax.plot(r["n"], r["cost"], marker=markers[m], ms=6, color=colours[m],
                        mfc=colours[m] if ok else "white", ls="none")
                print("  phi = %-5g N = %-6d %-13s cost %.3g  error: mean %+.2f %%, sd of one run %.2f %%, "
                      "rms %.2f %% (%d seeds)" % (phi, r["n"], m, r["cost"], 100 * r["mean_error"],
                                                  100 * r["error_sd"], 100 * r["error"], r["seeds"]))
        for n in sorted({r["n"] for r in rows if r["phi"] == phi}):
            ok = [r for r in rows if r["phi"] == phi and r["n"] == n and abs(r["error"]) <= a.tolerance]
            if ok:
                best = min(ok, key=lambda r: r["cost"])
                ax.plot(best["n"], best["cost"], marker="o", ms=14, mfc="none", mec="k", mew=1.0, ls="none")
                print("  phi = %-5g N = %-6d %s (%.3g CPU s per collision time)" % (phi, n, best["method"], best["cost"]))
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("particles N")
        ax.set_title("$\\phi$ = %g" % phi, fontsize=11)
        ax.grid(True, which="major", color="0.85", lw=0.6)
    axes[0].set_ylabel("CPU s per simulated collision time")
    handles = [plt.Line2D([], [], color=colours[m], marker=markers[m], lw=1.2, label=LABELS[m]) for m in METHODS]
    handles.append(plt.Line2D([], [], color="0.3", marker="o", mfc="white", ls="none",
                              label="open: one run's rms error of the collision frequency above %g %%" % (100 * a.tolerance)))
    handles.append(plt.Line2D([], [], color="k", marker="o", ms=12, mfc="none", ls="none",
                              label="ringed: the fastest within %g %%" % (100 * a.tolerance)))
    fig.legend(handles=handles, loc="lower center", ncol=3, fontsize=8.5, frameon=False)
    fig.suptitle("Cost at the dilute-gas chart's tolerance (%g %% on the collision frequency): elastic gas, "
                 "mean of %d seed(s), run loop only" % (100 * a.tolerance, max(r["seeds"] for r in rows)), fontsize=11)
    fig.tight_layout(rect=(0, 0.13, 1, 0.95))
    fig.savefig(a.figure, dpi=150)
    print("wrote " + a.figure)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    r = sub.add_parser("run")
    r.add_argument("out")
    r.add_argument("--carom", default="build/release/scenarios/carom")
    r.add_argument("--n", type=int, nargs="+", default=[500, 2000, 8000])
    r.add_argument("--phi", type=float, nargs="+", default=[0.01, 0.05, 0.2])
    r.add_argument("--collisions", type=float, default=50.0)
    r.add_argument("--seed", type=int, nargs="+", default=[1])
    r.add_argument("--methods", nargs="+", default=METHODS, choices=METHODS,
                   help="event_driven first: the others' errors are against it")
    p = sub.add_parser("plot")
    p.add_argument("out")
    p.add_argument("figure")
    p.add_argument("--tolerance", type=float, default=0.02)
    a = parser.parse_args()
    run(a) if a.command == "run" else plot(a)


if __name__ == "__main__":
    main()
