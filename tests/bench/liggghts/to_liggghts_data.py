#!/usr/bin/python3
"""Write a LIGGGHTS data file (atom_style sphere) from one snapshot of a carom run file.

    /usr/bin/python3 tests/bench/liggghts/to_liggghts_data.py RUN.h5 OUT.data [--snapshot K]

Reads snapshots/<K>/{id, position, velocity, spin, radius, species} (SI units: m, m/s, rad/s)
and the box domain/{lower, upper, periodic} of a carom run.h5 (the file `carom run` writes),
the density of each species from species/density (or from the stored scene text when that
dataset is missing; --density overrides both) and writes

    Atoms       atom-ID atom-type diameter density x y z
    Velocities  atom-ID vx vy vz wx wy wz

for LIGGGHTS' read_data (in.gas / in.column with -var data 1 -var datafile OUT.data).
atom-ID = carom id + 1 (LIGGGHTS ids start at 1), atom-type = carom species + 1. Positions on
periodic axes are wrapped into [lower, upper). K counts like carom's initial.from_file.snapshot:
0 the first snapshot (default), -1 the last. Needs python3-h5py and python3-numpy (Debian).
"""

import argparse
import sys
import tomllib

import h5py
import numpy as np


def species_density(f, n_species, override):
    if override is not None:
        return np.full(n_species, override)
    if "species" in f and "density" in f["species"]:
        return np.asarray(f["species/density"][()], dtype=float)
    scene = tomllib.loads(f["scene"][()].decode())
    return np.array([float(s["density"]) for s in scene["species"]])


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("run", help="carom run.h5")
    ap.add_argument("out", help="LIGGGHTS data file to write")
    ap.add_argument("--snapshot", type=int, default=0, help="snapshot index (0 first, -1 last)")
    ap.add_argument("--density", type=float, default=None, help="kg/m^3 for every particle")
    a = ap.parse_args(argv)

    with h5py.File(a.run, "r") as f:
        names = sorted(f["snapshots"].keys())
        k = a.snapshot if a.snapshot >= 0 else len(names) + a.snapshot
        if not 0 <= k < len(names):
            sys.exit(f"{a.run}: snapshot {a.snapshot} out of range (0 ... {len(names) - 1}, or -1 ...)")
        g = f["snapshots"][names[k]]
        time = float(g.attrs.get("time", 0.0))
        ids = np.asarray(g["id"][()], dtype=np.int64)
        pos = np.asarray(g["position"][()], dtype=float)
        vel = np.asarray(g["velocity"][()], dtype=float)
        spin = np.asarray(g["spin"][()], dtype=float)
        radius = np.asarray(g["radius"][()], dtype=float)
        species = np.asarray(g["species"][()], dtype=np.int64)
        lower = np.asarray(f["domain/lower"][()], dtype=float)
        upper = np.asarray(f["domain/upper"][()], dtype=float)
        periodic = np.asarray(f["domain/periodic"][()], dtype=bool)
        n_species = int(species.max()) + 1 if species.size else 1
        if "species" in f and "name" in f["species"]:
            n_species = max(n_species, len(f["species/name"]))
        rho = species_density(f, n_species, a.density)
        scene_name = f.attrs.get("scene_name", b"?")
        scene_name = scene_name.decode() if isinstance(scene_name, bytes) else str(scene_name)

    order = np.argsort(ids, kind="stable")
    ids, pos, vel, spin, radius, species = ids[order], pos[order], vel[order], spin[order], radius[order], species[order]
    length = upper - lower
    for ax in range(3):
        if periodic[ax]:
            pos[:, ax] = lower[ax] + np.mod(pos[:, ax] - lower[ax], length[ax])
    outside = np.any((pos < lower) | (pos > upper), axis=1)
    if outside.any():
        print(f"warning: {int(outside.sum())} particle centres lie outside the box", file=sys.stderr)

    with open(a.out, "w") as o:
        o.write(f"LIGGGHTS data file from carom {a.run} snapshot {names[k]} (scene {scene_name}, t = {time:.17g} s), "
                f"periodic xyz = {''.join('p' if p else 'f' for p in periodic)}\n\n")
        o.write(f"{len(ids)} atoms\n{n_species} atom types\n\n")
        for ax, nm in enumerate("xyz"):
            o.write(f"{lower[ax]:.17g} {upper[ax]:.17g} {nm}lo {nm}hi\n")
        o.write("\nAtoms\n\n")
        for i in range(len(ids)):
            o.write(f"{ids[i] + 1} {species[i] + 1} {2.0 * radius[i]:.17g} {rho[species[i]]:.17g} "
                    f"{pos[i, 0]:.17g} {pos[i, 1]:.17g} {pos[i, 2]:.17g}\n")
        o.write("\nVelocities\n\n")
        for i in range(len(ids)):
            o.write(f"{ids[i] + 1} {vel[i, 0]:.17g} {vel[i, 1]:.17g} {vel[i, 2]:.17g} "
                    f"{spin[i, 0]:.17g} {spin[i, 1]:.17g} {spin[i, 2]:.17g}\n")
    print(f"{a.out}: {len(ids)} particles, {n_species} type(s), box {lower.tolist()} .. {upper.tolist()}, "
          f"snapshot {names[k]} t = {time:g} s")


if __name__ == "__main__":
    main()
