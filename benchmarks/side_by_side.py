"""Time two source trees of viscocontact on the same solves, alternating, in fresh processes.

    python benchmarks/side_by_side.py OLD_TREE NEW_TREE [--cases wavy,rough,rough-b] [--repeats 2]

Each run imports viscocontact from the given tree (``PYTHONPATH``) in a new interpreter, so the
two codes see the same machine load in turn; this is how the before/after measurements of
``benchmarks/results`` are made (a git worktree of the old commit serves as OLD_TREE).
Prints one JSON line per run: tree, case, seconds, Ã, residual evaluations, converged.

Cases (the thesis's units, from first touch):

* ``wavy``: sinusoid Λ̃ = 0.1, SLS β = 10, γ̃ = 1e-4, p̃∞ = 0.1, ζ = 1e-3, default mesh, Newton;
* ``rough``: thesis rough profile (seed 0), γ̃ = 2.387e-7, p̃∞ = 0.3, ζ = 1, 32 elements, Newton;
* ``rough-b``: the same at ζ = 1e-6 with Broyden.
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys

CASES = ("wavy", "rough", "rough-b")

_CHILD = r"""
import json, sys, time
from viscocontact.adhesion import EnergyBalance
from viscocontact.problem import ContactProblem, Discretization
from viscocontact.profiles import SelfAffineProfile, Sinusoid
from viscocontact.rheology import StandardLinearSolid
from viscocontact.solvers import Broyden, Newton

case = sys.argv[1]
sls = StandardLinearSolid(beta=10.0)
if case == "wavy":
    prob = ContactProblem(profile=Sinusoid(amplitude=0.1), rheology=sls, solver=Newton(),
                          adhesion=EnergyBalance(gamma=1e-4), mean_pressure=0.1, zeta=1e-3)
else:
    zeta, solver = (1.0, Newton()) if case == "rough" else (1e-6, Broyden())
    prob = ContactProblem(profile=SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=0),
                          rheology=sls, solver=solver, adhesion=EnergyBalance(gamma=2.387e-7),
                          mean_pressure=0.3, zeta=zeta,
                          discretization=Discretization(elements=32))
t = time.perf_counter()
r = prob.solve()
print(json.dumps({"case": case, "seconds": time.perf_counter() - t, "area": r.area,
                  "evaluations": r.function_evaluations, "converged": r.converged}))
"""


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--cases", default=",".join(CASES))
    ap.add_argument("--repeats", type=int, default=2)
    args = ap.parse_args(argv)
    cases = args.cases.split(",")
    bad = [c for c in cases if c not in CASES]
    if bad or args.repeats < 1:
        ap.error(f"--cases must be a subset of {','.join(CASES)} and --repeats >= 1")
    for tree in (args.old, args.new):
        if not os.path.isdir(os.path.join(tree, "viscocontact")):
            ap.error(f"{tree!r} holds no viscocontact package")
    for _ in range(args.repeats):
        for case in cases:
            for label, tree in (("old", args.old), ("new", args.new)):
                env = dict(os.environ, PYTHONPATH=os.path.abspath(tree))
                # cwd = the tree: ``python -c`` puts the working folder first on sys.path
                out = subprocess.run([sys.executable, "-c", _CHILD, case], env=env,
                                     cwd=os.path.abspath(tree), capture_output=True, text=True)
                lines = out.stdout.strip().splitlines()
                row = json.loads(lines[-1]) if out.returncode == 0 and lines else {
                    "case": case, "error": out.stderr.strip().splitlines()[-1:]}
                print(json.dumps({"tree": label, **row}), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
