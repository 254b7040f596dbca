"""Seconds, residual evaluations and iterations of one rough adhesive point, from first touch,
next to a dense solve timed in the same run.

    python benchmarks/adhesive_point.py [--seeds 11,12,13] [--crowded] [--profile FILE] [--threads N]

The point (thesis §4.6 scene): ``SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=s)``,
``StandardLinearSolid(beta=10)``, ``EnergyBalance(gamma=2.387e-7)``, p̃∞ = 0.1, ζ = 1e-2, the
default mesh and the default solver of an adhesive scene (Broyden), from first touch.
``--crowded``: the crowded corner instead, ζ = 1e-6, p̃∞ = 0.6, seeds 0-2 by default.
``--elastic``: the same point on ``Elastic()`` (the relaxed solid, whose half-plane kernel is the
Clausen function alone).

The yardstick is ``numpy.linalg.solve`` of a 2000 × 2000 dense system with one BLAS thread,
measured in the same run so that the ratio does not depend on the machine's load: the median of
five at the start, and of three right before and right after each seed, whose mean is that
seed's unit (a shared machine's speed drifts by a third within minutes, which a single yardstick
for a four-minute run of the crowded corners would put into the ratios). The median line gives
the median of the seeds' ratios. The solves run BLAS on one thread too; with the threads of
``--threads`` (default ``VISCOCONTACT_THREADS`` or the cores) their influence loop splits its
rows, the finite-δX borders' solves split their columns, and the borders' rows and columns are
computed while the matrix is factorised (``benchmarks/results`` §13-14; the same bits on any
count). Prints one line per seed and the median; ``--profile FILE`` writes the cProfile
statistics of the first seed to FILE instead of timing the rest.

Before the timed solves a small adhesive sinusoid is solved once and its time printed as the
process's start: the package's imports, numba and its cached machine code (0.6-1 s), which a
study pays once per process and which would otherwise fall on the first seed alone. ``--cold``
leaves it out (the first seed then pays it).
"""
from __future__ import annotations

import argparse
import time

import numpy as np


def dense_solve_seconds(n: int = 2000, repeats: int = 5) -> float:
    """Median seconds of ``np.linalg.solve`` on an ``n × n`` system with one BLAS thread."""
    from viscocontact._blas import single_blas_thread

    rng = np.random.default_rng(0)
    A = rng.standard_normal((n, n)) + n * np.eye(n)
    b = rng.standard_normal(n)
    times = []
    with single_blas_thread():
        for _ in range(repeats):
            t = time.perf_counter()
            np.linalg.solve(A, b)
            times.append(time.perf_counter() - t)
    return float(np.median(times))


def warm_up() -> float:
    """Seconds of one small adhesive solve in a new process (imports, compiled code loaded)."""
    t = time.perf_counter()
    from viscocontact.adhesion import EnergyBalance
    from viscocontact.problem import ContactProblem, Discretization
    from viscocontact.methods.bem import BEM
    from viscocontact.profiles import Sinusoid
    from viscocontact.rheology import StandardLinearSolid
    from viscocontact.solvers import Broyden

    ContactProblem(method=BEM(),
                   profile=Sinusoid(amplitude=0.1), rheology=StandardLinearSolid(beta=10.0),
                   adhesion=EnergyBalance(gamma=1e-4), solver=Broyden(), mean_pressure=0.1,
                   zeta=1e-3,
                   discretization=Discretization(elements=32)).solve()
    return time.perf_counter() - t


def problem(seed: int, crowded: bool, solver=None, elastic: bool = False):
    from viscocontact.adhesion import EnergyBalance
    from viscocontact.problem import ContactProblem
    from viscocontact.methods.bem import BEM
    from viscocontact.profiles import SelfAffineProfile
    from viscocontact.rheology import Elastic, StandardLinearSolid
    from viscocontact.solvers import Broyden

    zeta, load = (1e-6, 0.6) if crowded else (1e-2, 0.1)
    return ContactProblem(method=BEM(),
                          profile=SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=seed),
                          rheology=Elastic() if elastic else StandardLinearSolid(beta=10.0),
                          adhesion=EnergyBalance(gamma=2.387e-7), solver=solver or Broyden(),
                          mean_pressure=load, zeta=zeta)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", default=None, help="comma-separated (default 11,12,13; 0,1,2 "
                                                  "with --crowded)")
    ap.add_argument("--crowded", action="store_true", help="ζ = 1e-6, p̃∞ = 0.6")
    ap.add_argument("--elastic", action="store_true", help="on the relaxed elastic solid")
    ap.add_argument("--solver", default="broyden", choices=("broyden", "newton"))
    ap.add_argument("--profile", default=None, help="write cProfile statistics of the first seed")
    ap.add_argument("--cold", action="store_true",
                    help="no warm-up solve: the first seed pays the process's start")
    ap.add_argument("--threads", type=int, default=None,
                    help="threads of a solve (default: VISCOCONTACT_THREADS or the cores; the "
                         "dense solve always has one BLAS thread)")
    args = ap.parse_args(argv)
    from viscocontact._threads import set_threads, threads
    from viscocontact.solvers import Broyden, Newton

    set_threads(args.threads)

    solver = {"broyden": Broyden, "newton": Newton}[args.solver]()
    seeds = ([int(s) for s in args.seeds.split(",")] if args.seeds
             else ([0, 1, 2] if args.crowded else [11, 12, 13]))
    ref = dense_solve_seconds()
    print(f"numpy 2000x2000 solve, one BLAS thread: {ref:.3f} s; the solves' influence loop "
          f"on {threads()} thread(s), BLAS on one", flush=True)
    if not args.cold:
        print(f"start of the process (a small adhesive sinusoid, untimed below): "
              f"{warm_up():.2f} s", flush=True)
    print(f"{'seed':>4s} {'s':>8s} {'x solve':>8s} {'ev':>6s} {'it':>6s} {'area':>10s} {'n':>3s} "
          "converged")
    times: list[float] = []
    ratios: list[float] = []
    for seed in seeds:
        prob = problem(seed, args.crowded, solver, args.elastic)
        if args.profile:
            import cProfile

            cProfile.runctx("r = prob.solve()", globals(), locals_ := {"prob": prob},
                            args.profile)
            r = locals_["r"]
            print(f"profile of seed {seed} written to {args.profile}: Ã = {r.area:.7f}, "
                  f"{r.function_evaluations} evaluations, converged {r.converged}")
            return
        before = dense_solve_seconds(repeats=3)
        t = time.perf_counter()
        r = prob.solve()
        s = time.perf_counter() - t
        unit = 0.5 * (before + dense_solve_seconds(repeats=3))
        times.append(s)
        ratios.append(s / unit)
        print(f"{seed:4d} {s:8.2f} {s / unit:8.1f} {r.function_evaluations:6d} "
              f"{r.iterations:6d} {r.area:10.7f} {r.n_contacts:3d} {r.converged} "
              f"(dense solve {unit:.3f} s)", flush=True)
    med = float(np.median(times))
    target = "60 s" if args.crowded else "2 s, about 16 dense solves"
    print(f"median {med:.2f} s, {float(np.median(ratios)):.1f} dense solves (target: {target})")


if __name__ == "__main__":
    main()
