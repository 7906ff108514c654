"""The figure of a run with inflow and outflow (scenes with [[inflow]] or [[outflow]]).

RUN_flow.png, two panels against time:
  left:  mass entered through each inflow and mass left through each outflow (kg, cumulative,
         /timeseries/entered_mass and left_mass), with each inflow's set rate as the line
         mass_flow * t (the inflows place what they owe exactly: the points sit on the line
         within one particle's mass unless the inlet slab was full);
  right: particles present of each species (/timeseries/particles_present).
"""
import matplotlib.pyplot as plt

import style


def flow_definitions(run):
    """(name, set mass flow in kg/s, species index) of each inflow and the name of each outflow,
    read from the scene stored in the run file (names default as carom's: inflow_1, outflow_1,
    ...)."""
    scene = run.scene_table
    names = run.species_names
    inflows = [(entry.get("name", f"inflow_{k + 1}"), float(entry["mass_flow"]),
                names.index(entry["species"]) if entry.get("species") in names else k)
               for k, entry in enumerate(scene.get("inflow", []))]
    outflows = [entry.get("name", f"outflow_{k + 1}") for k, entry in enumerate(scene.get("outflow", []))]
    return inflows, outflows


def plot_flow(run, path, dpi):
    """Draws RUN_flow.png of `run` (a carom.Output with particles_present) at `path`."""
    series = run.series_names
    t = run.series("time").values
    fig, (mass, count) = plt.subplots(1, 2, figsize=(9.6, 3.8))
    inflows, outflows = flow_definitions(run)
    names = run.species_names
    # Inflows in the colour of the species they feed (one marker per inflow); outflows, which
    # take any species, in black and grey.
    if "entered_mass" in series:
        entered = run.series("entered_mass").values.reshape(len(t), -1)
        for j, (name, rate, species) in enumerate(inflows[:entered.shape[1]]):
            c = style.species_colour(species)
            marker = style.partner_marker(j)
            mass.plot(t, entered[:, j], marker, ms=3, color=c,
                      label=f"entered through {name} ({names[species]})")
            mass.plot(t, rate * (t - t[0]), "-", lw=1, color=c,
                      label=f"{name}'s set rate {rate:g} kg/s")
    if "left_mass" in series:
        left = run.series("left_mass").values.reshape(len(t), -1)
        for j, name in enumerate(outflows[:left.shape[1]]):
            mass.plot(t, left[:, j], "s", ms=3, mfc="none", color="black" if j == 0 else "0.5",
                      label=f"left through {name}")
    mass.set_xlabel("time $t$ (s)")
    mass.set_ylabel("cumulative mass (kg)")
    mass.set_title("Mass in and out")
    mass.legend(loc="upper left")
    present = run.series("particles_present").values.reshape(len(t), -1)
    for s in range(present.shape[1]):
        count.plot(t, present[:, s], "-", lw=1.4, color=style.species_colour(s), label=names[s])
    count.set_xlabel("time $t$ (s)")
    count.set_ylabel("particles present (count)")
    count.set_title("Particles in the domain")
    count.set_ylim(bottom=0)
    count.legend(loc="best")
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
