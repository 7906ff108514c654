#!/usr/bin/python3
"""Why Gaussian partners heat an elastic gas (scenarios/chart/CHARTS.md, "Record: the Monte
Carlo method heats an elastic gas"), without carom: k particles with Maxwellian velocities
(T = m = 1) in a cell; each collides with partners drawn from the Gaussian of the other k - 1
particles' mean and population standard deviation per component (the default partner), with
the hard-sphere weight |V1 - V0|. An elastic smooth collision of equal masses with the impact
point uniform over the cross-section gives particle 1, on average, (|V0|^2 - |V1|^2) / 4 of
kinetic energy. Prints the mean energy change per collision over the mean energy 3/2: for
partners drawn from the other particles themselves it is 0 (to round-off: the sum is
antisymmetric), for the Gaussian it is positive, about 0.18/k for independent Maxwellian
samples (carom's cells, whose velocities are correlated by earlier collisions, measure 0.09/k).

    /usr/bin/python3 tests/bench/mc_gaussian_partner_bias.py      # about 5 CPU minutes
"""
import numpy as np

rng = np.random.default_rng(1)
DRAWS = 4000  # partner draws per particle
for k in [3, 5, 10, 21, 49, 100]:
    gained = 0.0
    weight = 0.0
    gained_particles = 0.0
    for _ in range(max(20, 20000 // k)):
        v = rng.normal(size=(k, 3))
        for i in range(k):
            others = np.delete(v, i, axis=0)
            v0 = others.mean(0) + others.std(0) * rng.normal(size=(DRAWS, 3))
            g = np.linalg.norm(v[i] - v0, axis=1)
            gained += np.mean(g * ((v0**2).sum(1) - (v[i]**2).sum()) / 4)
            weight += np.mean(g)
            g_particles = np.linalg.norm(v[i] - others, axis=1)
            gained_particles += np.mean(g_particles * ((others**2).sum(1) - (v[i]**2).sum()) / 4)
    print(f"k = {k:3d}: energy change per collision / (3/2): Gaussian partners {gained / weight / 1.5:+.5f} "
          f"(x k = {k * gained / weight / 1.5:.3f}); the particles themselves {gained_particles / weight / 1.5:+.1e}",
          flush=True)
