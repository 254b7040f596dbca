"""Iterations, residual evaluations and time of each nonlinear solver on the thesis's rough profile.

    python benchmarks/solvers_rough.py [--elements 32] [--cases adhesionless,adhesive]

The scene is ``examples/scenes/thesis_rough.toml`` (seed 0, γ̃ = 2.3885e-7), every solve from
first touch with the given elements per contact:

* ``adhesionless``: no adhesion, ζ = 0.01, p̃∞ = 0.3, with Newton, Broyden, bisection and
  nonlinear CG;
* ``adhesive``: ζ = 1, p̃∞ = 0.3, with Newton, Broyden and nonlinear CG.

Each solve runs in this process one after the other (the tables of ``docs/verification.md``,
"Solvers"); prints one line per solve: case, solver, iterations, evaluations, seconds, Ã,
contacts, converged.
"""
from __future__ import annotations

import argparse
import os
import time
from pathlib import Path

import attrs

from viscocontact.adhesion import NoAdhesion
from viscocontact.methods.bem import BEM
from viscocontact.problem import ContactProblem, Discretization
from viscocontact.scene import Scene
from viscocontact.solvers import Bisection, Broyden, NonlinearCG, Newton

SCENE = Path(__file__).resolve().parents[1] / "examples" / "scenes" / "thesis_rough.toml"
CASES = {
    "adhesionless": dict(zeta=1e-2, adhesive=False,
                         solvers=(Newton, Broyden, Bisection, NonlinearCG)),
    "adhesive": dict(zeta=1.0, adhesive=True, solvers=(Newton, Broyden, NonlinearCG)),
}


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--elements", type=int, default=32)
    parser.add_argument("--cases", default=",".join(CASES))
    args = parser.parse_args(argv)
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    base = ContactProblem.from_scene(Scene.from_toml(SCENE),
                                     discretization=Discretization(elements=args.elements))
    print(f"{'case':13s} {'solver':12s} {'it':>6s} {'ev':>6s} {'s':>7s} {'area':>10s} n  ok")
    for name in args.cases.split(","):
        case = CASES[name]
        # the boundary-element method, whose nonlinear solvers these are (`auto` would solve
        # the adhesionless case with the spectral method, which uses none of them)
        prob = attrs.evolve(base, zeta=case["zeta"], mean_pressure=0.3, method=BEM())
        if not case["adhesive"]:
            prob = attrs.evolve(prob, adhesion=NoAdhesion())
        for solver in case["solvers"]:
            started = time.perf_counter()
            r = attrs.evolve(prob, solver=solver()).solve()
            seconds = time.perf_counter() - started
            print(f"{name:13s} {solver.__name__:12s} {r.iterations:6d} "
                  f"{r.function_evaluations:6d} {seconds:7.1f} {r.area:10.7f} "
                  f"{r.n_contacts:d}  {r.converged}", flush=True)


if __name__ == "__main__":
    main()
