#!/usr/bin/python3
"""Granular temperature decay of a cooling-gas run against Haff's law.

    /usr/bin/python3 tests/bench/liggghts/haff.py KE.DAT [--e 0.9] [--phi 0.3] [--d 3e-4] [--every K]

KE.DAT is the ke.dat that in.gas writes (columns: step, time s, translational KE J, rotational
KE J, Tg = 2 KE/(3N) J, <v^2>/3 m^2/s^2). Prints T(t)/T0 beside Haff's law for smooth inelastic
hard spheres,
    T(t) = T0 / (1 + t/tau)^2,   1/tau = (1 - e^2) nu0 / 6,
    nu0 = 4 n d^2 g0 sqrt(pi T0/m)  (Enskog collision frequency per particle at T0, with
          Carnahan-Starling g0 = (1 - phi/2)/(1 - phi)^3, n = 6 phi/(pi d^3), T0/m = <v^2>/3 at t=0),
and tau fitted to the run (least squares on 1/sqrt(T/T0) = 1 + t/tau). With friction the
translational temperature falls faster than this (tangential dissipation, energy into spin):
the smooth-sphere law is the check for mu = 0. The same script reads carom's series if it is
written in the same columns.
"""

import argparse
import math

import numpy as np


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("ke")
    ap.add_argument("--e", type=float, default=0.9)
    ap.add_argument("--phi", type=float, default=0.3)
    ap.add_argument("--d", type=float, default=3e-4)
    ap.add_argument("--every", type=int, default=10, help="print every K-th row")
    a = ap.parse_args()

    data = np.loadtxt(a.ke, comments="#")
    t, ke, rke, v2 = data[:, 1], data[:, 2], data[:, 3], data[:, 5]
    th0 = v2[0]                                      # T0/m, m^2/s^2
    g0 = (1 - a.phi / 2) / (1 - a.phi) ** 3
    n = 6 * a.phi / (math.pi * a.d ** 3)
    nu0 = 4 * n * a.d ** 2 * g0 * math.sqrt(math.pi * th0)
    tau = 6 / ((1 - a.e ** 2) * nu0)
    y = 1 / np.sqrt(v2 / th0) - 1
    tau_fit = float(np.sum(t * t) / np.sum(t * y)) if np.any(t > 0) else float("nan")
    print(f"# T0/m = {th0:.6g} m^2/s^2, Enskog nu0 = {nu0:.6g} /s, Haff tau = {tau:.6g} s, fitted tau = {tau_fit:.6g} s "
          f"(ratio {tau_fit / tau:.3f})")
    print("# time_s  T/T0  Haff_T/T0  rot/trans_KE  collisions_per_particle(Haff)")
    for i in range(0, len(t), max(1, a.every)):
        haff = 1 / (1 + t[i] / tau) ** 2
        coll = tau * nu0 * math.log(1 + t[i] / tau)  # integral of nu(t) dt, nu ~ sqrt(T) ~ 1/(1 + t/tau)
        print(f"{t[i]:.6g} {v2[i] / th0:.5f} {haff:.5f} {rke[i] / ke[i]:.4f} {coll:.1f}")


if __name__ == "__main__":
    main()
