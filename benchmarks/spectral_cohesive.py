"""The spectral method's cohesive law against the BEM's cohesive zones, side by side.

    python benchmarks/spectral_cohesive.py [--zetas 1e-2,1,100] [--loads 0.05,0.2,0.5]
                                           [--repeats 3] [--tolerance 1e-3]

The scene (``docs/cohesive.md``, "The spectral cross-check"): ``Sinusoid(amplitude=0.1)`` on a
standard linear solid β = 10, ``MaugisDugdale(gamma=1e-4, range=1e-2)`` (Γ̃ = 0.01, η = 0.1,
λ = 1.36, zone a0 = 0.25), load control. Each point is solved by ``Spectral(tolerance=...)`` and by
the BEM (default mesh and solver, from first touch) in turn in this process, ``--repeats``
times each; the times are the medians (the problem's preparation included in both). Printed per
point: both times and their ratio, the differences of Ã (relative), μ (relative) and Δ̃
(relative), the grid's cells and error estimate, and its μ against the power it feeds into the
solid. The last line gives the median time ratio.
"""
from __future__ import annotations

import argparse
import time

import numpy as np

from viscocontact.adhesion import MaugisDugdale
from viscocontact.methods.spectral import Spectral
from viscocontact.problem import ContactProblem
from viscocontact.profiles import Sinusoid
from viscocontact.rheology import StandardLinearSolid
from viscocontact.solvers import Broyden
from viscocontact.methods.bem import BEM


def problem(zeta: float, load: float) -> ContactProblem:
    return ContactProblem(method=BEM(), profile=Sinusoid(amplitude=0.1),
                          rheology=StandardLinearSolid(beta=10.0),
                          adhesion=MaugisDugdale(gamma=1e-4, range=1e-2), solver=Broyden(),
                          mean_pressure=load, zeta=zeta)


def timed(solve, repeats: int):
    times, result = [], None
    for _ in range(repeats):
        t = time.perf_counter()
        result = solve()
        times.append(time.perf_counter() - t)
    return float(np.median(times)), result


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--zetas", default="1e-2,1,100")
    ap.add_argument("--loads", default="0.05,0.2,0.5")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--tolerance", type=float, default=1e-3)
    args = ap.parse_args(argv)
    if args.repeats < 1:
        ap.error("--repeats: an integer >= 1")
    method = Spectral(tolerance=args.tolerance)
    problem(1.0, 0.2).solve()                     # imports and compiled code, untimed
    print(f"{'ζ':>6} {'p̃∞':>5} {'grid s':>7} {'BEM s':>7} {'ratio':>6} {'ΔÃ':>9} {'Δμ':>9} "
          f"{'ΔΔ̃':>9} {'cells':>6} {'estimate':>8} {'μ/μ_diss-1':>10}")
    ratios = []
    for zeta in (float(z) for z in args.zetas.split(",")):
        for load in (float(p) for p in args.loads.split(",")):
            prob = problem(zeta, load)
            tg, g = timed(lambda: method.solve(prob), args.repeats)
            tb, b = timed(prob.solve, args.repeats)
            if not (g.converged and b.converged):
                print(f"{zeta:6.0e} {load:5.2f}  grid: {g.status.value}, BEM: {b.status.value}")
                continue
            ratios.append(tg / tb)
            print(f"{zeta:6.0e} {load:5.2f} {tg:7.3f} {tb:7.3f} {tg / tb:6.2f} "
                  f"{g.area / b.area - 1:+9.1e} "
                  f"{(g.friction - b.friction) / abs(b.friction):+9.1e} "
                  f"{g.penetration / b.penetration - 1:+9.1e} {g.extras['points']:6d} "
                  f"{g.extras['error_estimate']:8.1e} "
                  f"{g.friction / g.extras['friction_dissipation'] - 1:+10.1e}")
    if ratios:
        print(f"median time ratio grid/BEM: {np.median(ratios):.2f} over {len(ratios)} points")


if __name__ == "__main__":
    main()
