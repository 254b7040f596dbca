"""Fit the sub-cell edge maps of the spectral method on Westergaard's solution.

    python benchmarks/spectral_edges.py [--degree-pressure 4] [--degree-gap 5]

Westergaard's contact (rigid sinusoid on an elastic half-plane) has its edges at ``±Ã/2`` in
closed form. It is solved on grids of 8192-8600 cells (``h/a`` below 1e-3) at two loads whose
edges fall at every offset ``θ`` from the outermost loaded centre, and at each right edge the
ratios ``ρ = p_out/p_next`` (pressure side) and ``γ = g_1/g_2`` (gaps of the first two free
cells) are recorded against the exact ``θ``. The least-squares polynomials ``θ(ρ)`` and ``θ(γ)``
are printed with their largest residuals, in cells, on these grids and on grids four times
coarser at two other loads: the coefficients of ``PRESSURE_MAP`` and ``GAP_MAP`` in
``viscocontact/methods/spectral/edges.py``.
"""
from __future__ import annotations

import argparse

import numpy as np

from viscocontact.contact.fields import NormalizedProfile
from viscocontact.kernels.half_plane import HalfPlane
from viscocontact.methods.spectral.grid import UniformGrid
from viscocontact.methods.spectral.operator import Circulant, convolve
from viscocontact.methods.spectral.solvers import polonsky_keer
from viscocontact.profiles import Sinusoid
from viscocontact.reference import westergaard_area
from viscocontact.rheology import Elastic

FIT = ((0.37, range(8192, 8192 + 64 * 6, 6)), (0.73, range(8194, 8194 + 40 * 8, 8)))
CHECK = ((0.1, range(2000, 2100, 4)), (0.6, range(2002, 2102, 4)))


def samples(loads):
    """Rows ``(θ, ρ, γ)`` at the right edge of Westergaard's contact."""
    shape = NormalizedProfile.of(Sinusoid(amplitude=0.1))
    kernel = HalfPlane().prepare(Elastic(), 0.0)
    rows = []
    for load, sizes in loads:
        edge = 0.5 * float(westergaard_area(load))
        for n in sizes:
            grid = UniformGrid.of(shape, n)
            op = Circulant.build(kernel, n)
            sol = polonsky_keer(op.eigenvalues, grid.heights, mean_pressure=load,
                                tolerance=1e-13, max_iterations=20000, preconditioner=op.inverse)
            p = sol.pressure
            gap = convolve(p, op.eigenvalues) - (grid.heights - 1.0 + sol.penetration)
            k = int(np.flatnonzero(p[: n // 2] > 0)[-1])        # outermost loaded cell, x > 0
            theta = (edge - grid.x[k]) / grid.cell
            rows.append((theta, p[k] / p[k - 1], gap[k + 1] / gap[k + 2]))
    return np.array(rows)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--degree-pressure", type=int, default=4)
    ap.add_argument("--degree-gap", type=int, default=5)
    args = ap.parse_args(argv)
    fit, check = samples(FIT), samples(CHECK)
    print(f"{len(fit)} fitting samples, θ in [{fit[:, 0].min():.3f}, {fit[:, 0].max():.3f}]")
    for name, col, degree in (("PRESSURE_MAP", 1, args.degree_pressure),
                              ("GAP_MAP", 2, args.degree_gap)):
        coef = np.polyfit(fit[:, col], fit[:, 0], degree)
        res = np.abs(fit[:, 0] - np.polyval(coef, fit[:, col])).max()
        res_check = np.abs(check[:, 0] - np.polyval(coef, check[:, col])).max()
        print(f"{name} = ({', '.join(f'{c:.6f}' for c in coef)})")
        print(f"    largest residual {res:.1e} cells on the fitting grids, {res_check:.1e} on "
              "grids four times coarser")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
