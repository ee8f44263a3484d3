#!/usr/bin/python3
"""Work of adhesion per unit area of the PD paper's contact model 1 between two flat half-spaces.

Two simple-cubic half-lattices of spacing h (coldspray's seeding) face each other across a gap
g; each pair of points across it interacts with eq 15's potential, cut off at R_c = 2.75 r0 as
coldspray's force is (pd/lennard_jones.cpp: the energy of a pair is phi(r) - phi(R_c) within R_c),
with alpha from eq 22 (K the bulk modulus, delta = 3 h, V = h^3) and r0 = 1.1 h (coldspray's
default). The energy per unit area E(g) is minimal at the equilibrium gap; the work of adhesion
is W = -min E. Every length scales with h and alpha with K h^3, so W = K h w(beta): a coarser
lattice adheres more at the same beta. The lattices' lateral registry changes W; the table
averages four offsets (aligned, half a spacing along x, along x and y, a quarter along both).

Usage: tools/lj_adhesion_work.py [--spacing 1.2e-6] [--bulk-modulus 129e9] [--r0 1.1]
       [--beta 0.0025 0.003 ...]
"""

import argparse

import numpy as np
from scipy.optimize import minimize_scalar

OFFSETS = [(0.0, 0.0), (0.5, 0.0), (0.5, 0.5), (0.25, 0.25)]  # in spacings


def work_of_adhesion(beta, h, K, r0_spacings=1.1, offset=(0.0, 0.0), cutoff_r0=2.75):
    """W (J/m^2) and the equilibrium gap (m) for one lateral offset of the lattices."""
    r0 = r0_spacings * h
    Rc = cutoff_r0 * r0
    delta = 3.0 * h
    c = 18.0 * K / (np.pi * delta**5)  # eq 21
    alpha = c * r0**2 * h**6 / (72.0 * beta ** (7.0 / 3.0))  # eq 22, V_x = V_y = h^3
    n = int(np.ceil(Rc / h)) + 1
    i, j, ka, kb = np.meshgrid(np.arange(-n, n + 1), np.arange(-n, n + 1), np.arange(n + 1),
                               np.arange(n + 1), indexing="ij")
    phi_c = (r0 / Rc) ** 12 - 2.0 * beta * (r0 / Rc) ** 6

    def energy(g):  # per unit area: one column of one lattice against the whole other
        r = np.sqrt(((i + offset[0]) * h) ** 2 + ((j + offset[1]) * h) ** 2
                    + (g + (ka + kb) * h) ** 2)
        x = r0 / r
        return alpha * np.where(r < Rc, x**12 - 2.0 * beta * x**6 - phi_c, 0.0).sum() / h**2

    # In units of h: minimize_scalar's tolerance is absolute.
    gaps = np.linspace(0.3, Rc / h, 300)
    g0 = gaps[int(np.argmin([energy(g * h) for g in gaps]))]
    best = minimize_scalar(lambda g: energy(g * h), bounds=(max(0.3, g0 - 0.02), g0 + 0.02),
                           method="bounded", options={"xatol": 1e-9})
    return max(0.0, -best.fun), best.x * h


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--spacing", type=float, default=1.2e-6, help="h, m")
    parser.add_argument("--bulk-modulus", type=float, default=129e9, help="K, Pa (cu-jc)")
    parser.add_argument("--r0", type=float, default=1.1, help="r0 in spacings")
    parser.add_argument("--beta", type=float, nargs="+",
                        default=[0.0025, 0.003, 0.0035, 0.004, 0.0045, 0.005, 0.006])
    a = parser.parse_args()
    print(f"h = {a.spacing:g} m, K = {a.bulk_modulus:g} Pa, r0 = {a.r0:g} h, R_c = 2.75 r0")
    print("beta    W per offset (J/m^2)                 mean W (J/m^2)  mean gap (h)")
    for beta in a.beta:
        runs = [work_of_adhesion(beta, a.spacing, a.bulk_modulus, a.r0, o) for o in OFFSETS]
        works = [w for w, _ in runs]
        gap = np.mean([g for _, g in runs]) / a.spacing
        print(f"{beta:.4f}  " + " ".join(f"{w:8.1f}" for w in works)
              + f"   {np.mean(works):10.1f}    {gap:.2f}")


if __name__ == "__main__":
    main()
