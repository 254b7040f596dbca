"""Run a fixed set of solves and print one JSON line per case with every scalar output, the
contact edges and the event log: two source trees that give the same lines compute the same
results (used to show that a restructuring changed no number).

    PYTHONPATH=TREE python benchmarks/same_results.py [--cases a,b] > out.jsonl
"""
from __future__ import annotations

import argparse
import json
import sys
import time

import numpy as np


def cases():
    from viscocontact.adhesion import EnergyBalance, NoAdhesion
    from viscocontact.problem import ContactProblem, Discretization
    from viscocontact.methods.bem import BEM
    from viscocontact.profiles import SelfAffineProfile, Sinusoid
    from viscocontact.rheology import Elastic, StandardLinearSolid
    from viscocontact.solvers import Bisection, Broyden, Newton, NonlinearCG

    sls = StandardLinearSolid(beta=10.0)
    wavy = Sinusoid(amplitude=0.1)
    rough = SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=0)
    small = SelfAffineProfile(hurst=0.8, scales=12, rms=0.01, seed=3)

    def P(**kw):
        kw.setdefault("rheology", sls)
        kw.setdefault("solver", Newton())
        return ContactProblem(method=BEM(), **kw)

    return {
        "westergaard": (P(profile=wavy, rheology=Elastic(), mean_pressure=0.3), None),
        "wavy-adh-z1e-3": (P(profile=wavy, adhesion=EnergyBalance(gamma=1e-4),
                             mean_pressure=0.1, zeta=1e-3), None),
        "wavy-adh-broyden-z1": (P(profile=wavy, adhesion=EnergyBalance(gamma=1e-4),
                                  solver=Broyden(), mean_pressure=0.1, zeta=1.0), None),
        "johnson-tensile": (P(profile=wavy, rheology=Elastic(),
                              adhesion=EnergyBalance(gamma=5e-4), mean_pressure=-0.02), None),
        "wavy-penetration": (P(profile=wavy, penetration=0.5, zeta=0.1), None),
        "no-contact": (P(profile=wavy, penetration=-0.1), None),
        "full-contact": (P(profile=wavy, mean_pressure=2.0, zeta=0.1), None),
        "rough-small-elastic": (P(profile=small, rheology=Elastic(), mean_pressure=0.3,
                                  discretization=Discretization(elements=32)), None),
        "rough-small-adh-cg": (P(profile=small, adhesion=EnergyBalance(gamma=2.387e-7),
                                 solver=NonlinearCG(), mean_pressure=0.2, zeta=0.1,
                                 discretization=Discretization(elements=32)), None),
        "rough-adhless-z1e-2": (P(profile=rough, mean_pressure=0.3, zeta=1e-2,
                                  solver=Broyden(), discretization=Discretization(elements=32)),
                                None),
        "rough-adh-z1": (P(profile=rough, adhesion=EnergyBalance(gamma=2.387e-7),
                           mean_pressure=0.3, zeta=1.0,
                           discretization=Discretization(elements=32)), None),
        "continuation": (P(profile=wavy, adhesion=EnergyBalance(gamma=1e-4),
                           mean_pressure=0.2, zeta=0.01, solver=Bisection()), "wavy-adh-z1e-3"),
    }


def record(name, r):
    out = r.to_dict()
    out["case"] = name
    out["events"] = list(r.extras.get("events", []))
    out["history_len"] = len(r.extras.get("residual_history", []))
    out["conformity"] = r.extras.get("conformity")
    return out


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--cases", default=None)
    args = ap.parse_args(argv)
    table = cases()
    names = args.cases.split(",") if args.cases else list(table)
    results = {}
    for name in names:
        problem, start_from = table[name]
        initial = None
        if start_from is not None:
            if start_from not in results:
                results[start_from] = table[start_from][0].solve()
            initial = results[start_from]
        t = time.perf_counter()
        r = problem.solve(initial)
        results[name] = r
        rec = record(name, r)
        rec["seconds"] = round(time.perf_counter() - t, 2)
        print(json.dumps(rec, default=float), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
