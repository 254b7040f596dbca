"""Rough adhesive points from first touch at the default path step and at a finer one: the
equilibria reached, whether they agree, and the residual evaluations each path takes.

    python benchmarks/approach_paths.py [--finer 4] [--points 0,1,2] [--jsonl FILE]

The points (thesis §4.6 scene: ``SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=s)``,
``StandardLinearSolid(beta=10)``, ``EnergyBalance(gamma=2.387e-7)``, Broyden, default mesh):
seeds 11-16 at p̃∞ = 0.1, ζ = 1e-2, and seeds 11-13 at (p̃∞, ζ) = (0.3, 1e-2), (0.1, 1) and
(0.3, 1e-4); 15 in all. The approach locates its events (folds, births, merges) to a fraction of
the path step and crosses every fold by the edges' motion, so the equilibrium a point reaches
should not depend on the step: a path ``--finer`` times finer is the reference, and a change of
the approach is judged by the equilibria it reaches as well as by its evaluations. Each point
is solved at the default path step and at the finer one, and one line is printed per point;
``--jsonl`` also appends one JSON line per solve to FILE. About 40 minutes on one core.
"""
from __future__ import annotations

import argparse
import json
import time

POINTS = ([(seed, 1e-2, 0.1) for seed in range(11, 17)]
          + [(seed, zeta, load) for seed in range(11, 14)
             for zeta, load in ((1e-2, 0.3), (1.0, 0.1), (1e-4, 0.3))])
#: Areas within this relative distance are the same equilibrium (the solver's tolerance leaves
#: about 1e-9; other equilibria differ by 1e-3 and more).
SAME = 1e-6


def solve(seed: int, zeta: float, load: float, path_step: float):
    from viscocontact.adhesion import EnergyBalance
    from viscocontact.problem import ContactProblem, Discretization
    from viscocontact.methods.bem import BEM
    from viscocontact.profiles import SelfAffineProfile
    from viscocontact.rheology import StandardLinearSolid
    from viscocontact.solvers import Broyden

    problem = ContactProblem(method=BEM(),
                             profile=SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=seed),
                             rheology=StandardLinearSolid(beta=10.0), solver=Broyden(),
                             adhesion=EnergyBalance(gamma=2.387e-7), mean_pressure=load,
                             zeta=zeta, discretization=Discretization(path_step=path_step))
    t = time.perf_counter()
    r = problem.solve()
    return {"seed": seed, "zeta": zeta, "load": load, "path_step": path_step,
            "area": r.area, "evaluations": r.function_evaluations, "contacts": r.n_contacts,
            "converged": bool(r.converged), "seconds": round(time.perf_counter() - t, 2)}


def main(argv=None) -> None:
    from viscocontact.problem import Discretization

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--finer", type=float, default=4.0, help="path step divisor of the reference")
    ap.add_argument("--points", default=None, help="comma-separated indices into the 15 points")
    ap.add_argument("--jsonl", default=None, help="append one JSON line per solve to this file")
    args = ap.parse_args(argv)
    points = ([POINTS[int(i)] for i in args.points.split(",")] if args.points else POINTS)
    step = Discretization().path_step
    print(f"{'seed':>4s} {'zeta':>6s} {'p':>4s} | {'area':>10s} {'ev':>5s} | "
          f"{'area (finer)':>12s} {'ev':>5s} | same")
    totals, agree = [0, 0], 0
    for seed, zeta, load in points:
        default = solve(seed, zeta, load, step)
        finer = solve(seed, zeta, load, step / args.finer)
        same = (default["converged"] and finer["converged"]
                and abs(default["area"] - finer["area"]) <= SAME * abs(finer["area"]))
        agree += same
        totals[0] += default["evaluations"]
        totals[1] += finer["evaluations"]
        print(f"{seed:4d} {zeta:6.0e} {load:4.1f} | {default['area']:10.7f} "
              f"{default['evaluations']:5d} | {finer['area']:12.7f} {finer['evaluations']:5d} | "
              f"{'yes' if same else 'NO'}", flush=True)
        if args.jsonl:
            with open(args.jsonl, "a", encoding="utf-8") as f:
                for row in (default, finer):
                    f.write(json.dumps(row) + "\n")
    print(f"{agree} of {len(points)} points reach the finer path's equilibrium; evaluations "
          f"{totals[0]} (default path step) and {totals[1]} (finer)")


if __name__ == "__main__":
    main()
