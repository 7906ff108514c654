#!/usr/bin/python3
"""Draws the stability maps of the shipped stability sweeps (scenarios/scenes/stability_*.toml;
scenarios/chart/CHARTS.md, "Stability maps") from each sweep's OUT/summary.csv: every case at
its place in the map, marked by how its run ended (completed, or the status of the detector that
stopped it), with the predicted failure boundary drawn and the detector named.

    stability_plot.py kick OUT [--before OUT_OLD]     # stability_kick.toml
    stability_plot.py collapse OUT_NO_TC OUT_TC       # stability_collapse.toml, _tc.toml
    stability_plot.py soft_step OUT                   # stability_soft_step.toml
    stability_plot.py soft_load OUT                   # stability_soft_load.toml
    ... --out FILE.png                                # default: OUT/stability_MODE.png

The boundaries are computed here from the scenes' physics (the formulas are in each function),
independently of carom; the points are carom's runs.
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.lines as mlines  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

STYLE = {  # how a case ended -> marker, colour, label
    "completed": ("o", "#2a9d4b", "completed"),
    "kick_unstable": ("X", "#d62728", "stopped: kick_unstable"),
    "inelastic_collapse": ("X", "#d62728", "stopped: inelastic_collapse (stall detector)"),
    "lasting_contacts": ("^", "#ff7f0e", "stopped: lasting_contacts"),
    "soft_sphere_unstable": ("X", "#d62728", "stopped: soft_sphere_unstable (energy drift)"),
    "soft_sphere_overlap": ("s", "#9467bd", "stopped: soft_sphere_overlap"),
}


def fail(message):
    sys.exit("stability_plot.py: error: " + message)


def cases(out):
    path = os.path.join(out, "summary.csv")
    if not os.path.exists(path):
        fail(path + " does not exist: run the sweep first (see its file's header)")
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def num(row, key):
    value = row.get(key, "")
    return float(value) if value not in ("", None) else math.nan


def style(status):
    return STYLE.get(status, ("D", "black", "ended: " + status))


def legend_handles(statuses, extra=()):
    handles, seen = [], set()
    for s in statuses:
        m, c, label = style(s)
        if label in seen:
            continue
        seen.add(label)
        handles.append(mlines.Line2D([], [], ls="", marker=m, color=c, ms=8, label=label))
    return handles + list(extra)


# ---------------------------------------------------------------------------------------------
# Kick scheme: settling_sphere.toml, air (rho_g = 1.2 kg/m^3, mu = 1.8e-5 Pa s), glass 2500 kg/m^3,
# Schiller-Naumann drag F = K(s) s, K = 3 pi mu d (1 + 0.15 Re^0.687), Re = rho_g s d / mu; the
# gas at rest; buoyancy from the hydrostatic pressure gradient.
RHO_G, MU, RHO_P, G = 1.2, 1.8e-5, 2500.0, 9.81


def drag_rate(s, d):
    """K(s)/m, 1/s: the secant drag rate (1/tau)."""
    re = RHO_G * abs(s) * d / MU
    f = 1.0 + 0.15 * re**0.687 if re < 1000.0 else 0.44 * re / 24.0
    return 3.0 * math.pi * MU * d * f / (RHO_P * math.pi / 6.0 * d**3)


def terminal_speed(d):
    gp = G * (1.0 - RHO_G / RHO_P)
    v = 0.1
    for _ in range(500):
        v = gp / drag_rate(v, d)
    return v


def longitudinal_rate(s, d):
    """(1/m) d(K s)/ds, 1/s, by a central difference."""
    h = 1e-6 * s
    return ((s + h) * drag_rate(s + h, d) - (s - h) * drag_rate(s - h, d)) / (2.0 * h)


def exact_fall(d, t_end):
    """The exact distance fallen from rest by t_end, m (RK4 at 1e-4 s: converged to 1e-10)."""
    gp = G * (1.0 - RHO_G / RHO_P)
    acc = lambda v: gp - drag_rate(v, d) * v  # noqa: E731
    v, z, dt = 0.0, 0.0, 1e-4
    for _ in range(int(round(t_end / dt))):
        k1 = acc(v)
        k2 = acc(v + 0.5 * dt * k1)
        k3 = acc(v + 0.5 * dt * k2)
        k4 = acc(v + dt * k3)
        z += dt * (v + dt * (k1 + k2 + k3) / 6.0)
        v += dt * (k1 + 2 * k2 + 2 * k3 + k4) / 6.0
    return z


def kick_fall(out, row):
    """The distance the bead fell over the run, m: its height in the first snapshot less that in
    the last (run.h5). Kicks make the velocity a sawtooth of amplitude g dt_p between kicks, so
    the fall (the mean settling velocity times the time) is the fair comparison."""
    # Here, not at the top: only the kick map reads run files (carom.open needs h5py).
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from carom_reader import open_run

    run = open_run(os.path.join(out, "cases", "%04d" % int(row["case"]), "run.h5"))
    return run.particles(index=0)["position"][0][2] - run.particles(index=-1)["position"][0][2]


def plot_kick(out, before, path):
    rows = cases(out)
    old = cases(before) if before else []
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12.5, 5.0))
    diameters = sorted({num(r, "species.glass.diameter") for r in rows})
    ds = np.linspace(4.5e-4, 1.05e-3, 200)
    tau = np.array([1.0 / drag_rate(terminal_speed(d), d) for d in ds])
    lim = np.array([2.0 / longitudinal_rate(terminal_speed(d), d) for d in ds])
    ax.fill_between(ds * 1e3, lim, 3.0, color="#d62728", alpha=0.08, lw=0)
    ax.plot(ds * 1e3, lim, "k-", lw=2, label=r"largest stable step $2m/(dF/ds)$ at $v_t$")
    ax.plot(ds * 1e3, 2 * tau, "k--", lw=1.2, label=r"$2\tau$ ($\tau=m/K$ at $v_t$)")
    ax.plot(ds * 1e3, tau / 5, "k:", lw=1.2, label=r"$\tau/5$ (first-order accurate)")
    statuses = []
    for r in rows:
        m, c, _ = style(r["status"])
        statuses.append(r["status"])
        ax.plot(num(r, "species.glass.diameter") * 1e3, num(r, "flight.particle_step"), m, color=c, ms=7,
                mec="white", mew=0.5)
    ax.set_yscale("log")
    ax.set_ylim(0.007, 2.2)
    ax.set_xlabel("bead diameter d (mm)")
    ax.set_ylabel(r"particle step $\Delta t_p$ (s)")
    ax.set_title("(a) kick flights: where the detector stops the run")
    ax.legend(handles=legend_handles(statuses, ax.get_legend_handles_labels()[0]), loc="lower right",
              fontsize=8, framealpha=0.95)
    ax.grid(alpha=0.3, which="both")

    colours = ["#1f77b4", "#ff7f0e", "#2ca02c"]
    for k, d in enumerate(diameters):
        t_end = max(num(r, "end_time") for r in rows if r["status"] == "completed")
        exact = exact_fall(d, t_end)
        vt = terminal_speed(d)
        t = 1.0 / drag_rate(vt, d)
        for source, filled in ((old, False), (rows, True)):
            pts = [r for r in source if num(r, "species.glass.diameter") == d]
            pts.sort(key=lambda r: num(r, "flight.particle_step"))
            x = [num(r, "flight.particle_step") / t for r in pts if r["status"] == "completed"]
            y = [abs(kick_fall(out if filled else before, r) / exact - 1.0) for r in pts if r["status"] == "completed"]
            y = [max(v, 1e-9) for v in y]
            if filled:
                bx.plot(x, y, "o-", color=colours[k], ms=5, label="d = %.2f mm, $\\tau$ = %.3f s" % (d * 1e3, t))
                xs = [num(r, "flight.particle_step") / t for r in pts if r["status"] == "kick_unstable"]
                bx.plot(xs, [3.0] * len(xs), "X", color=colours[k], ms=8)
            elif x:
                bx.plot(x, y, "o", color=colours[k], ms=7, mfc="none", alpha=0.7)
        bx.axvline(2.0 / (longitudinal_rate(vt, d) / drag_rate(vt, d)), color=colours[k], lw=1, ls="-", alpha=0.6)
    bx.axvline(2.0, color="k", ls="--", lw=1.2)
    bx.text(2.03, 1.3e-3, r"$2\tau$", fontsize=9)
    bx.axhline(3.0, color="#d62728", lw=0.5, alpha=0.4)
    bx.text(0.03, 3.6, "stopped: kick_unstable (X)", fontsize=8, color="#d62728")
    if old:
        bx.plot([], [], "o", color="grey", mfc="none", label="2 tau check only (before): ran on")
    bx.set_xscale("log")
    bx.set_yscale("log")
    bx.set_ylim(1e-3, 10)
    bx.set_xlabel(r"$\Delta t_p/\tau$ ($\tau$ at the terminal velocity)")
    bx.set_ylabel("|distance fallen in 2 s / exact - 1|")
    bx.set_title("(b) error of the mean settling velocity; lines: $2m/(dF/ds)$")
    bx.legend(fontsize=8, loc="center left")
    bx.grid(alpha=0.3, which="both")
    fig.suptitle("Explicit drag kicks on a glass bead settling in air (stability_kick.toml)", fontsize=11)
    fig.tight_layout()
    fig.savefig(path, dpi=130)


# ---------------------------------------------------------------------------------------------
def plot_collapse(out_none, out_tc, path):
    panels = [(out_none, "0.0", "no TC model, no low-speed rule"),
              (out_none, "0.01", "low-speed rule (elastic below 0.01 m/s)"),
              (out_tc, "0.0", "TC model (t_c = 1e-3 s)"),
              (out_tc, "0.01", "TC model and low-speed rule")]
    fig, axes = plt.subplots(1, 4, figsize=(15, 4.2), sharey=True)
    statuses = []
    for ax, (out, rule, title) in zip(axes, panels):
        rows = [r for r in cases(out) if abs(num(r, "collisions.collapse.elastic_below_speed") - float(rule)) < 1e-12]
        groups = {}
        for r in rows:
            key = (num(r, "species.grain.fill.volume_fraction"), num(r, "collisions.default.e"))
            groups.setdefault(key, []).append(r["status"])
        phis = sorted({k[0] for k in groups})
        es = sorted({k[1] for k in groups})
        for (phi, e), st in groups.items():
            x, y = phis.index(phi), es.index(e)
            n = len(st)
            for j, s in enumerate(sorted(st)):
                m, c, _ = style(s)
                statuses.append(s)
                ax.plot(x + (j - (n - 1) / 2) * 0.22, y, m, color=c, ms=9, mec="white", mew=0.5)
        # The boundary: for each phi, above the largest e at which some seed stopped.
        xs, ys = [], []
        for i, phi in enumerate(phis):
            bad = [es.index(e) for (p, e), st in groups.items() if p == phi and any(s != "completed" for s in st)]
            if bad or xs:  # from the first column that collapsed on (the map's collapses are contiguous)
                top = max(bad) + 0.5 if bad else -0.5
                if not xs:
                    xs, ys = [i - 0.5], [-0.5]
                xs += [i - 0.5, i + 0.5]
                ys += [top, top]
        if xs:
            ax.plot(xs, ys, "k-", lw=2)
            ax.fill_between(xs, -0.6, ys, color="#d62728", alpha=0.08, lw=0)
        else:
            title += ": all finished"
        ax.set_xticks(range(len(phis)))
        ax.set_xticklabels(["%g" % p for p in phis])
        ax.set_yticks(range(len(es)))
        ax.set_yticklabels(["%g" % e for e in es])
        ax.set_xlim(-0.6, len(phis) - 0.4)
        ax.set_ylim(-0.6, len(es) - 0.4)
        ax.set_xlabel(r"solid fraction $\phi$")
        ax.set_title(title, fontsize=10)
        ax.grid(alpha=0.2)
    axes[0].set_ylabel("restitution e")
    line = mlines.Line2D([], [], color="k", lw=2, label="boundary: collapse below (any seed)")
    fig.legend(handles=legend_handles(statuses, [line]), loc="lower center", ncol=4, fontsize=9,
               bbox_to_anchor=(0.5, -0.01))
    fig.suptitle("Inelastic collapse of a freely cooling gas, 500 s, two seeds per point "
                 "(collapse_box.toml: 12 d periodic box; stability_collapse*.toml)", fontsize=11)
    fig.tight_layout(rect=(0, 0.08, 1, 1))
    fig.savefig(path, dpi=130)


# ---------------------------------------------------------------------------------------------
# Soft spheres: soft_column.toml, glass beads d = 2 mm, 2500 kg/m^3, nu = 0.3; Hertz contacts.
R_BEAD, RHO_BEAD, NU = 1.0e-3, 2500.0, 0.3
M_BEAD = RHO_BEAD * 4.0 / 3.0 * math.pi * R_BEAD**3


def hertz_peak_overlap(v, e_star, r_star, m_star):
    """Peak overlap of an elastic Hertz impact at speed v, m (Johnson)."""
    return (15.0 * m_star * v**2 / (16.0 * e_star * math.sqrt(r_star))) ** 0.4


def plot_soft_step(out, path):
    rows = cases(out)
    # The real impacts: the fall from the top of the box, sqrt(2 g h) with h = 0.06 m less a
    # radius (carom's estimate, 1.085 m/s). Hertz: t_c ~ v^-1/5, so a step of f t_c(v_decl) is
    # f (v_real / v_decl)^(1/5) of the real contact time.
    v_real = math.sqrt(2 * 9.81 * 0.06)
    # Velocity Verlet is stable for dt < 2/omega, omega^2 = k(delta_max)/m*, k = 2 E* sqrt(R* delta)
    # the tangent Hertz stiffness at the peak overlap, against the contact time t_c of the same
    # impact (pi / omega_mean for a damped linear spring; carom check prints t_c = 2.006e-4 s and
    # the peak overlap 0.07395 R for bead-bead at 1.085 m/s):
    e_star = 1.0e7 / (2 * (1 - NU**2))
    delta = 0.07395 * R_BEAD
    omega = math.sqrt(2 * e_star * math.sqrt(0.5 * R_BEAD * delta) / (0.5 * M_BEAD))
    limit = 2.0 / omega / 2.006e-4
    all_rows = rows
    limits = sorted({num(r, "soft_sphere.max_overlap") for r in all_rows})
    fig, axes = plt.subplots(1, len(limits), figsize=(6.6 * len(limits), 5.0), sharey=True)
    axes = np.atleast_1d(axes)
    speeds = sorted({num(r, "soft_sphere.impact_speed") for r in all_rows})
    ylab = {v: ("%g (estimated: %.3g)" % (v, v_real) if v == 0 else "%g" % v) for v in speeds}
    ypos = {v: i for i, v in enumerate(sorted(speeds, key=lambda v: -(v if v > 0 else v_real)))}
    statuses = [r["status"] for r in all_rows]
    for ax, lim_overlap in zip(axes, limits):
        rows = [r for r in all_rows if num(r, "soft_sphere.max_overlap") == lim_overlap]
        ax.axvspan(limit, 3, color="#d62728", alpha=0.08, lw=0)
        ax.axvline(limit, color="k", lw=2)
        for v, y in ypos.items():
            xr = limit * (v_real / (v if v > 0 else v_real)) ** 0.2
            ax.plot([xr, xr], [y - 0.35, y + 0.35], color="#555555", lw=3, solid_capstyle="butt")
        for r in rows:
            v = num(r, "soft_sphere.impact_speed")
            f = num(r, "soft_sphere.step_fraction")
            x = f * (v_real / (v if v > 0 else v_real)) ** 0.2
            m, c, _ = style(r["status"])
            ax.plot(x, ypos[v], m, color=c, ms=9, mec="white", mew=0.5)
            ov = num(r, "method.largest_overlap")
            if not math.isnan(ov):
                ax.annotate("%.2f" % ov, (x, ypos[v]), textcoords="offset points", xytext=(-9, 8), fontsize=6.5,
                            color="#444444")
        ax.set_xscale("log")
        ax.set_xlim(0.015, 1.6)
        ax.set_ylim(-0.6, len(ypos) - 0.4)
        ax.set_xlabel(r"step / contact time of the real impacts ($\Delta t / t_c$, $t_c$ = 0.2 ms at 1.085 m/s)")
        ax.set_title("soft_sphere.max_overlap = %g%s" % (lim_overlap, " (default)" if lim_overlap == 0.1 else ""),
                     fontsize=10)
        ax.grid(alpha=0.3, which="both")
    axes[0].set_yticks(list(ypos.values()))
    axes[0].set_yticklabels([ylab[v] for v in ypos])
    axes[0].set_ylabel("declared impact speed soft_sphere.impact_speed (m/s)")
    extra = [mlines.Line2D([], [], color="k", lw=2,
                           label=r"velocity Verlet limit $2/\omega$ of the real impacts (%.2f $t_c$)" % limit),
             mlines.Line2D([], [], color="#555555", lw=3, label="start-up refusal beyond (exit 2, carom check)")]
    fig.legend(handles=legend_handles(statuses, extra), loc="lower center", ncol=3, fontsize=8.5,
               bbox_to_anchor=(0.5, -0.01))
    fig.suptitle("Soft-sphere step against the contact time: 150 Hertz beads falling 60 mm "
                 "(stability_soft_step.toml); numbers: largest overlap / R", fontsize=11)
    fig.tight_layout(rect=(0, 0.1, 1, 1))
    fig.savefig(path, dpi=130)


def plot_soft_load(out, path):
    rows = cases(out)
    fig, ax = plt.subplots(figsize=(7.5, 5.0))
    statuses = []
    for r in rows:
        g = -num(r, "domain.gravity.2") if "domain.gravity.2" in r else math.nan
        if math.isnan(g):
            g = abs(float(r["domain.gravity"].strip("[]").split(",")[2]))
        e = num(r, "species.bead.young_modulus")
        m, c, _ = style(r["status"])
        statuses.append(r["status"])
        ax.plot(g, e, m, color=c, ms=10, mec="white", mew=0.5)
        ov = num(r, "method.largest_overlap")
        if not math.isnan(ov):
            ax.annotate("%.2g" % ov, (g, e), textcoords="offset points", xytext=(7, -3), fontsize=7, color="#444444")
    # The boundary: the first impact on the floor at sqrt(2 g h), h = 0.06 m - R, peak overlap
    # 0.1 R (max_overlap), bead on an E = 1e7 Pa wall: E*(E) = 1 / ((1-nu^2)/E + (1-nu^2)/1e7),
    # R* = R, m* = m; and bead on bead at the same speed (E* = E / (2 (1-nu^2)), R* = R/2, m* = m/2).
    gs = np.logspace(-0.2, 2.2, 100)
    for label, ls, wall in (("bead on the 1e7 Pa floor", "-", True), ("bead on bead", "--", False)):
        es = []
        for g in gs:
            v = math.sqrt(2 * g * (0.06 - R_BEAD))
            lo, hi = 1e2, 1e9
            for _ in range(200):
                mid = math.sqrt(lo * hi)
                if wall:
                    e_star = 1.0 / ((1 - NU**2) / mid + (1 - NU**2) / 1e7)
                    dmax = hertz_peak_overlap(v, e_star, R_BEAD, M_BEAD)
                else:
                    dmax = hertz_peak_overlap(v, mid / (2 * (1 - NU**2)), R_BEAD / 2, M_BEAD / 2)
                lo, hi = (mid, hi) if dmax > 0.1 * R_BEAD else (lo, mid)
            es.append(math.sqrt(lo * hi))
        ax.plot(gs, es, "k" + ls, lw=2 if wall else 1.2,
                label="peak overlap 0.1 R: Hertz impact at $\\sqrt{2gh}$, h = 59 mm (%s)" % label)
    ax.fill_between(gs, 1e3, ax.get_lines()[-2].get_ydata(), color="#9467bd", alpha=0.07, lw=0)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylim(5e3, 2.5e8)
    ax.set_xlabel(r"gravity $|g|$ (m/s$^2$): the load")
    ax.set_ylabel("bead Young modulus E (Pa)")
    fig.legend(handles=legend_handles(statuses, ax.get_legend_handles_labels()[0]), fontsize=8,
               loc="lower center", ncol=2, bbox_to_anchor=(0.5, -0.005))
    ax.grid(alpha=0.3, which="both")
    ax.set_title("Soft-sphere stiffness against the load; numbers: largest overlap / R\n"
                 "(stability_soft_load.toml, 400 beads, max_overlap = 0.1)", fontsize=10)
    fig.set_size_inches(8.5, 6.0)
    fig.tight_layout(rect=(0, 0.1, 1, 1))
    fig.savefig(path, dpi=130)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("mode", choices=["kick", "collapse", "soft_step", "soft_load"])
    p.add_argument("out", nargs="+", help="the sweep's output directory (collapse: without, then with TC)")
    p.add_argument("--before", help="kick: a run of the same sweep by a carom that checked 2 tau only")
    p.add_argument("--out", dest="path", help="the figure (PNG)")
    a = p.parse_args()
    need = 2 if a.mode == "collapse" else 1
    if len(a.out) != need:
        fail("%s takes %d output director%s" % (a.mode, need, "ies" if need > 1 else "y"))
    path = a.path or os.path.join(a.out[0], "stability_%s.png" % a.mode)
    if a.mode == "kick":
        plot_kick(a.out[0], a.before, path)
    elif a.mode == "collapse":
        plot_collapse(a.out[0], a.out[1], path)
    elif a.mode == "soft_step":
        plot_soft_step(a.out[0], path)
    else:
        plot_soft_load(a.out[0], path)
    print("stability_plot.py: wrote " + path)


if __name__ == "__main__":
    main()
