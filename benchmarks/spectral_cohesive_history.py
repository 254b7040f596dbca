"""The spectral method's Maugis-Dugdale solves along the approach from first touch: result,
grid solves along the path, evaluations and seconds per point, and the BEM's from first touch.

    python benchmarks/spectral_cohesive_history.py [--cases 0:0.5,100:0.5] [--bem]

The scene: ``Sinusoid(amplitude=0.1)``, ``MaugisDugdale(gamma=5e-4, range=7.95e-3)`` (Γ̃ = 0.05,
η = 0.0795, λ = 5), penetration control; a case ``ζ:Δ̃`` is an elastic solid at ζ = 0, else a
standard linear solid β = 10 at ζ. Printed per case: status, Ã, p̃∞, the final grid and its
estimate, the approach's accepted states and events, the evaluations (FFT products) and the
seconds. With ``--bem`` the BEM's Ã and p̃∞ from first touch follow. Run it under two versions
of the package (``PYTHONPATH``) to compare them: it uses only ``Spectral().solve``.
"""
from __future__ import annotations

import argparse
import time

from viscocontact.adhesion import MaugisDugdale
from viscocontact.methods.bem import BEM
from viscocontact.methods.spectral import Spectral
from viscocontact.problem import ContactProblem
from viscocontact.profiles import Sinusoid
from viscocontact.rheology import Elastic, StandardLinearSolid
from viscocontact.solvers import Broyden


def problem(zeta: float, penetration: float) -> ContactProblem:
    rheology = Elastic() if zeta == 0 else StandardLinearSolid(beta=10.0)
    return ContactProblem(method=BEM(), profile=Sinusoid(amplitude=0.1), rheology=rheology,
                          adhesion=MaugisDugdale(gamma=5e-4, range=7.95e-3), solver=Broyden(),
                          zeta=zeta, penetration=penetration)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", default="0:0.3,0:0.5,0:0.7,100:0.5,10:0.9")
    ap.add_argument("--bem", action="store_true")
    args = ap.parse_args(argv)
    print(f"{'ζ':>6} {'Δ̃':>5} {'status':>14} {'Ã':>10} {'p̃∞':>10} {'cells':>6} {'estimate':>8} "
          f"{'states':>6} {'events':>6} {'evals':>7} {'s':>7}", flush=True)
    for case in args.cases.split(","):
        zeta, pen = (float(v) for v in case.split(":"))
        prob = problem(zeta, pen)
        t = time.perf_counter()
        r = Spectral().solve(prob)
        dt = time.perf_counter() - t
        x = r.extras
        print(f"{zeta:6g} {pen:5.2f} {r.status.value:>14} {r.area:10.6f} {r.mean_pressure:10.6f} "
              f"{x['points']:6d} {x['error_estimate']:8.1e} {len(x.get('history', [])):6d} "
              f"{len(x.get('path_events', [])):6d} {r.function_evaluations:7d} {dt:7.2f}",
              flush=True)
        if args.bem:
            b = prob.solve()
            print(f"{'':>6} {'BEM':>5} {b.status.value:>14} {b.area:10.6f} {b.mean_pressure:10.6f}",
                  flush=True)


if __name__ == "__main__":
    main()
