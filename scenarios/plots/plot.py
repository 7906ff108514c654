#!/usr/bin/python3
"""Figures of one carom run file.

    /usr/bin/python3 scenarios/plots/plot.py RUN.h5 [--out DIR] [--snapshot K] [--axes xy] [--slab W]

Writes, as 150 dpi PNGs named after the run file:
  RUN_energies.png         kinetic (translational, rotational), potential, elastic, dissipated,
                           the gas's work and the total
                           energy against time (/timeseries);
  RUN_collision_rates.png  pair collisions per unit time for every species pair, measured over
                           each sample interval, with the Enskog prediction when the run is a
                           homogeneous gas (every axis periodic, no gravity, no walls);
  RUN_snapshot.png         one snapshot (the last by default) as circles of the particles' radii
                           in a slab around the box's mid-plane, coloured by species;
  RUN_gas.png              runs with a gas: the bed pressure drop against time and against the
                           inlet velocity, with the buoyant weight per area W/A of the particles
                           (the level a fluidized bed's pressure drop must reach);
  RUN_gas_field.png        runs with a gas: porosity and gas velocity of the snapshot;
  RUN_flow.png             runs with inflow or outflow: mass in and out against the set rates,
                           particles present (flow_plots.py);
  RUN_mixing.png, RUN_collisions.png   the run's analysis (analysis_plots.py).

Needs numpy, h5py and matplotlib (Debian: python3-numpy python3-h5py python3-matplotlib).
Enskog rate of s-t collisions in a mixture at granular temperature T (k = 1):
    omega_st = 4 n_t sigma_st^2 g_st sqrt(pi T / (2 mu_st)),  mu_st = m_s m_t / (m_s + m_t),
    rate_st = N_s omega_st (s != t),  rate_ss = N_s omega_ss / 2,
with g_st the Boublik-Mansoori-Carnahan-Starling-Leland contact value; for one species this is
omega = 4 n sigma^2 g0 sqrt(pi T / m) with the Carnahan-Starling g0 = (1 - phi/2) / (1 - phi)^3.
T = 2 K / (3 (N - 1)) from the translational kinetic energy K (total momentum is zero).
"""
import argparse
import os
import sys

# A run still being written holds its file open; HDF5 1.10's file locks would refuse to open it
# for reading. The writer flushes after every write, so what is read is complete.
os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")
import h5py  # noqa: E402
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import EllipseCollection  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from analysis_plots import analysis_figures  # noqa: E402
from flow_plots import plot_flow  # noqa: E402

DPI = 150
plt.rcParams.update({
    "font.size": 10,
    "axes.labelsize": 10,
    "legend.fontsize": 9,
    "legend.frameon": False,
    "axes.spines.top": False,
    "axes.spines.right": False,
})
COLOURS = plt.get_cmap("tab10").colors


def text(value):
    """h5py gives fixed-length strings as bytes."""
    return value.decode("utf-8") if isinstance(value, bytes) else str(value)


def species_names(run):
    return [text(name) for name in run["species/name"][()]]


def contact_values(diameter, number_density):
    """BMCSL contact values g_st of a hard-sphere mixture, and the volume fraction."""
    xi2 = np.pi / 6 * np.sum(number_density * diameter**2)
    phi = np.pi / 6 * np.sum(number_density * diameter**3)
    ratio = np.outer(diameter, diameter) / np.add.outer(diameter, diameter)
    g = 1 / (1 - phi) + 3 * xi2 * ratio / (1 - phi)**2 + 2 * xi2**2 * ratio**2 / (1 - phi)**3
    return g, phi


def is_homogeneous_gas(run):
    domain = run["domain"]
    return (bool(np.all(domain["periodic"][()] != 0)) and not np.any(domain["gravity"][()])
            and len(run["walls/name"]) == 0)


def enskog_pair_rates(run, temperature):
    """Enskog s-t collision rates (1/s) for each temperature: array (len(T), S, S)."""
    diameter = run["species/diameter"][()]
    mass = run["species/mass"][()]
    count = run["species/count"][()].astype(float)
    volume = run["domain"].attrs["volume"]
    density = count / volume
    g, _ = contact_values(diameter, density)
    sigma = 0.5 * np.add.outer(diameter, diameter)
    mu = np.outer(mass, mass) / np.add.outer(mass, mass)
    # omega[s, t]: collisions per unit time of one s particle with t particles.
    omega_per_sqrt_t = 4 * density[None, :] * sigma**2 * g * np.sqrt(np.pi / (2 * mu))
    rate = count[:, None] * omega_per_sqrt_t
    rate[np.diag_indices_from(rate)] *= 0.5
    return np.sqrt(np.maximum(temperature, 0))[:, None, None] * rate[None, :, :]


def plot_energies(run, path):
    series = run["timeseries"]
    t = series["time"][()]
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    if len(t) == 0:
        ax.text(0.5, 0.5, "no samples", ha="center", transform=ax.transAxes)
    else:
        curves = [("kinetic_translational", "kinetic, translational", "-"),
                  ("kinetic_rotational", "kinetic, rotational", "-"),
                  ("potential", "potential", "-"),
                  ("elastic", "elastic (soft-sphere contacts)", "-"),
                  ("dissipated", "dissipated", "--"),
                  ("gas_work", "work done by the gas", "-."),
                  ("total_energy", "total (kinetic + potential + elastic\n+ dissipated - gas work)", ":")]
        scale = np.max(np.abs(series["total_energy"][()])) or 1.0
        for k, (name, label, style) in enumerate(curves):
            if name not in series:
                continue  # run files written before the column existed
            values = series[name][()]
            if name in ("kinetic_rotational", "potential", "elastic", "gas_work") and \
                    np.max(np.abs(values)) < 1e-12 * scale:
                continue  # zero up to round-off (smooth spheres, no gravity): only clutter
            ax.plot(t, values, style, color=COLOURS[k], lw=1.6 if name == "total_energy" else 1.2,
                    label=label)
        ax.legend(loc="best")
    ax.set_xlabel("time $t$ (s)")
    ax.set_ylabel("energy (J)")
    ax.set_title("Energies")
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def plot_collision_rates(run, path):
    series = run["timeseries"]
    t = series["time"][()]
    names = species_names(run)
    s_count = len(names)
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    if len(t) < 2:
        ax.text(0.5, 0.5, "fewer than two samples", ha="center", transform=ax.transAxes)
    else:
        counts = series["pair_collisions"][()].reshape(len(t), s_count, s_count).astype(float)
        dt = np.diff(t)
        keep = dt > 0
        middle = 0.5 * (t[1:] + t[:-1])[keep]
        measured = (np.diff(counts, axis=0)[keep] / dt[keep, None, None])
        theory = None
        if is_homogeneous_gas(run):
            kinetic = series["kinetic_translational"][()]
            n = float(np.sum(run["species/count"][()]))
            temperature = 2 * kinetic / (3 * max(n - 1, 1))
            # Mean temperature over each interval (exact for a linear change).
            theory = enskog_pair_rates(run, 0.5 * (temperature[1:] + temperature[:-1])[keep])
        k = 0
        for s in range(s_count):
            for u in range(s, s_count):
                label = names[s] if s_count == 1 else f"{names[s]}–{names[u]}"
                colour = COLOURS[k % len(COLOURS)]
                ax.plot(middle, measured[:, s, u], "o", ms=3, color=colour, alpha=0.8,
                        label=f"{label}, measured")
                if theory is not None:
                    ax.plot(middle, theory[:, s, u], "-", lw=1.4, color=colour,
                            label=f"{label}, Enskog")
                k += 1
        ax.set_ylim(bottom=0)
        ax.legend(loc="best")
    ax.set_xlabel("time $t$ (s)")
    ax.set_ylabel("pair collisions per unit time (1/s)")
    ax.set_title("Collision rates per species pair")
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def plot_snapshot(run, path, index, axes, slab):
    groups = sorted(run["snapshots"].keys())
    lower, upper = run["domain/lower"][()], run["domain/upper"][()]
    a, b = ("xyz".index(axes[0]), "xyz".index(axes[1]))
    aspect = (upper[b] - lower[b]) / (upper[a] - lower[a])
    height = 5.2 if aspect >= 1 else max(2.5, 4.0 * aspect + 1.2)
    width = min(max(4.0 / max(aspect, 1) + 1.8, 3.5), 9.0) if aspect >= 1 else 6.4
    fig, ax = plt.subplots(figsize=(width, height))
    if not groups:
        ax.text(0.5, 0.5, "no snapshots", ha="center", transform=ax.transAxes)
        fig.savefig(path, dpi=DPI)
        plt.close(fig)
        return
    snapshot = run["snapshots"][groups[index]]
    position = snapshot["position"][()]
    radius = snapshot["radius"][()]
    species = snapshot["species"][()]
    names = species_names(run)
    depth_axis = 3 - a - b
    middle = 0.5 * (lower[depth_axis] + upper[depth_axis])
    if slab is None:
        slab = 4 * radius.max() if len(radius) else 0.0
    chosen = (np.abs(position[:, depth_axis] - middle) <= 0.5 * slab) if slab > 0 else \
        np.ones(len(radius), bool)
    order = np.argsort(position[chosen, depth_axis])  # nearer particles drawn last
    p, r, s = position[chosen][order], radius[chosen][order], species[chosen][order]
    colours = np.array([COLOURS[k % len(COLOURS)] for k in s]).reshape(-1, 3)
    ax.add_collection(EllipseCollection(2 * r, 2 * r, np.zeros_like(r), units="xy",
                                        offsets=p[:, [a, b]], transOffset=ax.transData,
                                        facecolors=colours, edgecolors="black", linewidths=0.3))
    ax.add_patch(plt.Rectangle((lower[a], lower[b]), upper[a] - lower[a], upper[b] - lower[b],
                               fill=False, lw=0.8, color="0.3"))
    margin = 0.03 * max(upper[a] - lower[a], upper[b] - lower[b])
    ax.set_xlim(lower[a] - margin, upper[a] + margin)
    ax.set_ylim(lower[b] - margin, upper[b] + margin)
    ax.set_aspect("equal")
    ax.set_xlabel(f"${axes[0]}$ (m)")
    ax.set_ylabel(f"${axes[1]}$ (m)")
    handles = [Line2D([], [], marker="o", ls="", ms=8, markerfacecolor=COLOURS[k % len(COLOURS)],
                      markeredgecolor="black", label=name) for k, name in enumerate(names)]
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    what = (f"slab $|{'xyz'[depth_axis]} - {middle:.3g}| \\leq {0.5 * slab:.3g}$ m"
            if slab > 0 else "all particles")
    ax.set_title(f"$t$ = {snapshot.attrs['time']:.4g} s: {len(r)} of {len(radius)} particles\n"
                 f"({what})", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def buoyant_weight_per_area(run):
    """W/A = sum m_i |g| (1 - rho_g/rho_p) / (area normal to gravity), Pa."""
    lower, upper = run["domain/lower"][()], run["domain/upper"][()]
    gravity = np.asarray(run["domain/gravity"][()])
    down = int(np.argmax(np.abs(gravity)))
    area = np.prod([upper[k] - lower[k] for k in range(3) if k != down])
    rho_g = run["gas"].attrs["density"]
    species = run["species"]
    weight = sum(n * m * np.linalg.norm(gravity) * (1 - rho_g / rho)
                 for n, m, rho in zip(species["count"][()], species["mass"][()],
                                      species["density"][()]))
    return weight / area


def measured_minimum_fluidization(inlet, drop, weight):
    """U_mf of a ramp: where the packed-bed branch (Ergun's form a U + b U^2, least squares over
    the points below 70 % of W/A) reaches the plateau W/A. None without such points."""
    packed = (inlet > 0) & (drop < 0.7 * weight)
    if packed.sum() < 5 or drop.max() < 0.9 * weight:
        return None
    u, p = inlet[packed], drop[packed]
    (a, b), *_ = np.linalg.lstsq(np.column_stack([u, u * u]), p, rcond=None)
    if b <= 0:
        return weight / a if a > 0 else None
    return (-a + np.sqrt(a * a + 4 * b * weight)) / (2 * b)


def carrying_pressure_drop(run):
    """The part of the gas pressure drop that carries the particles, Pa: gas_pressure_drop less
    the gas's own weight per area (rho_g |g| H) plus the net momentum per area the gas brings in
    (gas_momentum_inflow; absent from files of older carom versions)."""
    series = run["timeseries"]
    lower, upper = run["domain/lower"][()], run["domain/upper"][()]
    gravity = np.asarray(run["domain/gravity"][()])
    height = upper[2] - lower[2]
    drop = series["gas_pressure_drop"][()] - run["gas"].attrs["density"] * abs(gravity[2]) * height
    if "gas_momentum_inflow" in series:
        drop = drop + series["gas_momentum_inflow"][()]
    return drop


def plot_gas(run, path):
    series = run["timeseries"]
    t = series["time"][()]
    drop = carrying_pressure_drop(run)
    inlet = series["gas_inlet_velocity"][()].max(axis=1)
    weight = buoyant_weight_per_area(run)
    fig, (left, right) = plt.subplots(1, 2, figsize=(9.6, 3.8))
    left.plot(t, drop, color=COLOURS[0], lw=1.0, label="pressure drop carrying the beads")
    left.axhline(weight, color="0.3", ls="--", lw=0.8, label=f"W/A = {weight:.4g} Pa")
    left.set_xlabel("$t$ (s)")
    left.set_ylabel(r"$\Delta p$ (Pa)")
    twin = left.twinx()
    twin.plot(t, inlet, color=COLOURS[1], lw=1.0, label="inlet velocity $U$")
    twin.set_ylabel("inlet velocity $U$ (m/s)", color=COLOURS[1])
    twin.spines["right"].set_visible(True)
    # The legends sit below the axes: inside, wherever they go, some run's curve runs under them.
    lines = left.get_legend_handles_labels()
    twin_lines = twin.get_legend_handles_labels()
    left.legend(lines[0] + twin_lines[0], lines[1] + twin_lines[1], loc="upper center",
                bbox_to_anchor=(0.5, -0.2), ncol=2, fontsize="small", frameon=False)
    right.plot(inlet, drop, ".", ms=2, color=COLOURS[0], label="carom")
    right.axhline(weight, color="0.3", ls="--", lw=0.8)
    measured = measured_minimum_fluidization(inlet, drop, weight)
    if measured is not None:
        right.axvline(measured, color=COLOURS[0], lw=0.8, label=f"measured $U_{{mf}}$ = {measured:.3f} m/s")
    attrs = run["gas"].attrs
    if "closure_minimum_fluidization" in attrs:
        right.axvline(attrs["closure_minimum_fluidization"], color=COLOURS[2], ls=":", lw=1.0,
                      label=f"closure at $\\varepsilon_{{mf}}$ = 0.4: "
                            f"{attrs['closure_minimum_fluidization']:.3f} m/s")
        right.axvline(attrs["wen_yu_minimum_fluidization"], color=COLOURS[3], ls="-.", lw=1.0,
                      label=f"Wen-Yu: {attrs['wen_yu_minimum_fluidization']:.3f} m/s")
    right.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=2, fontsize=7, frameon=False)
    right.set_xlabel("inlet superficial velocity $U$ (m/s)")
    right.set_ylabel(r"$\Delta p$ (Pa)")
    right.set_title(f"closure: {text(run['gas/closure'][()])}", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=DPI, bbox_inches="tight")
    plt.close(fig)


def plot_gas_field(run, path, index):
    groups = sorted(run["snapshots"].keys())
    snapshot = run["snapshots"][groups[index]]
    cells = run["gas/cells"][()]
    lower, spacing = run["gas/lower"][()], run["gas/spacing"][()]
    porosity = snapshot["gas/porosity"][()]        # (nz, ny, nx)
    velocity = snapshot["gas/velocity"][()]        # (nz, ny, nx, 3)
    mid = cells[1] // 2
    extent = [lower[0], lower[0] + cells[0] * spacing[0], lower[2], lower[2] + cells[2] * spacing[2]]
    fig, (left, right) = plt.subplots(1, 2, figsize=(7.2, 5.0))
    image = left.imshow(porosity[:, mid, :], origin="lower", extent=extent, cmap="viridis",
                        vmin=max(0.3, porosity.min()), vmax=1.0, aspect="equal")
    fig.colorbar(image, ax=left, label="porosity")
    speed = velocity[:, mid, :, 2]
    image = right.imshow(speed, origin="lower", extent=extent, cmap="magma", aspect="equal")
    fig.colorbar(image, ax=right, label="gas velocity $u_z$ (m/s)")
    for ax in (left, right):
        ax.set_xlabel("$x$ (m)")
        ax.set_ylabel("$z$ (m)")
    fig.suptitle(f"$t$ = {snapshot.attrs['time']:.4g} s", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("run", help="the run's HDF5 file")
    parser.add_argument("--out", help="directory for the PNGs (default: beside the run file)")
    parser.add_argument("--snapshot", type=int, default=-1, help="snapshot index (default: last)")
    parser.add_argument("--axes", default=None, choices=["xy", "xz", "yz", "yx", "zx", "zy"],
                        help="projection plane of the snapshot picture (default: a side view "
                             "with gravity pointing down, or xy without gravity)")
    parser.add_argument("--slab", type=float, default=None,
                        help="thickness (m) of the slab drawn around the mid-plane; 0 draws all "
                             "particles (default: 2 largest diameters)")
    args = parser.parse_args(argv)

    out = args.out or os.path.dirname(os.path.abspath(args.run))
    os.makedirs(out, exist_ok=True)
    stem = os.path.splitext(os.path.basename(args.run))[0]
    with h5py.File(args.run, "r") as run:
        if text(run.attrs.get("kind", b"")) != "carom run":
            sys.exit(f"{args.run}: not a carom run file")
        if args.axes is None:
            gravity = np.asarray(run["domain/gravity"][()]) if "domain/gravity" in run else np.zeros(3)
            if np.any(gravity != 0):
                down = int(np.argmax(np.abs(gravity)))  # vertical axis of the picture
                across = 0 if down != 0 else 1
                args.axes = "xyz"[across] + "xyz"[down]
            else:
                args.axes = "xy"
        written = []
        figures = [("energies", lambda p: plot_energies(run, p)),
                   ("collision_rates", lambda p: plot_collision_rates(run, p)),
                   ("snapshot", lambda p: plot_snapshot(run, p, args.snapshot, args.axes,
                                                        args.slab))]
        if "particles_present" in run["timeseries"]:
            figures.append(("flow", lambda p: plot_flow(run, p, DPI)))
        if "gas" in run:
            figures += [("gas", lambda p: plot_gas(run, p)),
                        ("gas_field", lambda p: plot_gas_field(run, p, args.snapshot))]
        figures += [(name, lambda p, draw=draw: draw(p, DPI))
                    for name, draw in analysis_figures(run, args.run)]
        for name, draw in figures:
            path = os.path.join(out, f"{stem}_{name}.png")
            draw(path)
            written.append(path)
    print("\n".join(written))


if __name__ == "__main__":
    main()
