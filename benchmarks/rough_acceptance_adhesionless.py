"""Every adhesionless point of the rough acceptance grid through the planned method.

    python benchmarks/rough_acceptance_adhesionless.py [--seeds 0,1,2]

The thesis scene (``SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=s)``,
``StandardLinearSolid(beta=10)``, half-plane), adhesionless, at ζ = 1e-6, 1, 1e4 and
p̃∞ = 0.05, 0.3, 0.6, each point from scratch; prints one line per point (method, Ã, contacts,
error estimate, smallest gap, seconds) and the count of converged points.
"""
from __future__ import annotations

import argparse
import time

from viscocontact.problem import ContactProblem
from viscocontact.profiles import SelfAffineProfile
from viscocontact.rheology import StandardLinearSolid
from viscocontact.solvers import Bisection
from viscocontact.methods.auto import Auto


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", default="0,1,2")
    args = ap.parse_args(argv)
    ok = total = 0
    for seed in (int(s) for s in args.seeds.split(",")):
        profile = SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=seed)
        for zeta in (1e-6, 1.0, 1e4):
            for load in (0.05, 0.3, 0.6):
                problem = ContactProblem(profile=profile, rheology=StandardLinearSolid(beta=10.0),
                                         solver=Bisection(), mean_pressure=load, zeta=zeta,
                                         method=Auto())
                t = time.perf_counter()
                r = problem.solve()
                total += 1
                ok += bool(r.converged and r.min_gap >= 0)
                print(f"seed {seed} ζ = {zeta:g} p̃∞ = {load}: {r.status.value} by {r.method}, "
                      f"Ã = {r.area:.6f}, {r.n_contacts} contacts, estimate "
                      f"{r.error_estimate:.1e}, min gap {r.min_gap:.1e}, "
                      f"{time.perf_counter() - t:.2f} s", flush=True)
    print(f"{ok} of {total} converged without interpenetration")
    return 0 if ok == total else 1


if __name__ == "__main__":
    raise SystemExit(main())
