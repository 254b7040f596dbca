"""Seconds of the LU factorisation of influence matrices: one ``scipy.linalg.lu_factor`` call
against the blocked factorisation of :mod:`viscocontact._lu` on one thread and on two, side by
side in one run, and whether their factors are the same bits.

    python benchmarks/factorisation.py [--sizes 1024,1500,2136,2600] [--repeats 5]

The matrices are the viscoelastic influence matrices of the thesis scene's kernel
(``StandardLinearSolid(beta=10)``, ζ = 1e-2) on meshes of random element widths over the period.
BLAS runs on one thread throughout (as in a solve); the blocked factorisation's second thread is
the process's own. Prints the median seconds of each and the ratios.
"""
from __future__ import annotations

import argparse
import time

import numpy as np


def influence_matrix(n: int, seed: int = 0) -> np.ndarray:
    from viscocontact.problem import ContactProblem
    from viscocontact.methods.bem import BEM
    from viscocontact.profiles import Sinusoid
    from viscocontact.rheology import StandardLinearSolid
    from viscocontact.solvers import Broyden

    kernel = ContactProblem(method=BEM(),
                            profile=Sinusoid(amplitude=0.1),
                            rheology=StandardLinearSolid(beta=10.0),
                            solver=Broyden(), mean_pressure=0.1, zeta=1e-2).prepare().kernel
    rng = np.random.default_rng(seed)
    nodes = np.sort(rng.uniform(-np.pi, np.pi, n + 1))
    left, right = nodes[:-1], nodes[1:]
    return kernel.influence(0.5 * (left + right), left, right)


def median_seconds(f, repeats: int) -> tuple[float, object]:
    times, out = [], None
    for _ in range(repeats):
        t = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t)
    return float(np.median(times)), out


def main(argv=None) -> None:
    from scipy.linalg import lu_factor

    from viscocontact import _lu
    from viscocontact._blas import single_blas_thread
    from viscocontact._threads import set_threads

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="1024,1500,2136,2600")
    ap.add_argument("--repeats", type=int, default=5)
    args = ap.parse_args(argv)
    print(f"{'N':>5s} {'lu_factor':>10s} {'1 thread':>9s} {'2 threads':>9s} {'ratio 2':>8s} "
          "same bits as lu_factor (1 thread, 2 threads)")
    with single_blas_thread():
        for n in (int(s) for s in args.sizes.split(",")):
            a = influence_matrix(n)
            t_ref, ref = median_seconds(lambda: lu_factor(a, check_finite=False), args.repeats)
            got = {}
            for count in (1, 2):
                set_threads(count)
                got[count] = median_seconds(lambda: _lu.lu_factor(a), args.repeats)
            set_threads(None)
            same = [bool(np.array_equal(got[c][1][0], ref[0])
                         and np.array_equal(got[c][1][1], ref[1])) for c in (1, 2)]
            print(f"{n:5d} {t_ref:10.4f} {got[1][0]:9.4f} {got[2][0]:9.4f} "
                  f"{t_ref / got[2][0]:7.2f}x {same[0]}, {same[1]}", flush=True)


if __name__ == "__main__":
    main()
