"""The spectral method against the FFT peer on the thesis's rough profile, side by side.

    python benchmarks/spectral.py [--seeds 0,1,2,3,4] [--repeats 3] [--reference]
    python benchmarks/spectral.py --orders          # observed convergence orders of Ã and μ
    python benchmarks/spectral.py --profile         # where a solve spends its time (cProfile)
    python benchmarks/spectral.py --betas           # robustness of the active set against β
    python benchmarks/spectral.py --near-elastic    # ζ -> 0 against the elastic solid's solve

The acceptance case: ``SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=s)`` on a
half-plane at ``p̃∞ = 0.25``, elastic and standard linear solid β = 10 at ζ = 1e-2.
``Spectral()`` (default tolerance, from scratch: ``problem.prepare()`` included) and
``peer_fft.solve(profile, 0.25, 8192, ...)`` (its operator and nested grids included) run in
turn in this process, ``--repeats`` times each per seed; the times are the medians. Printed: both
times and their ratio per seed, the ratio of the medians over the seeds, and the differences of
``Ã`` (relative) and ``μ`` (relative to ``max(|μ|, 1e-2·√m2)``). ``--reference`` adds the errors
of both against ``Spectral(points=131072)``.
"""
from __future__ import annotations

import argparse
import cProfile
import math
import os
import pstats
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import peer_fft  # noqa: E402

from viscocontact.methods.spectral import Spectral  # noqa: E402
from viscocontact.problem import ContactProblem  # noqa: E402
from viscocontact.profiles import SelfAffineProfile, Sinusoid  # noqa: E402
from viscocontact.reference import westergaard_area  # noqa: E402
from viscocontact.rheology import Elastic, StandardLinearSolid  # noqa: E402
from viscocontact.solvers import Bisection  # noqa: E402
from viscocontact.methods.bem import BEM

LOAD = 0.25
PEER_POINTS = 8192
REFERENCE_POINTS = 1 << 17
RHEOLOGIES = (("elastic", Elastic(), 0.0), ("SLS β=10, ζ=1e-2", StandardLinearSolid(beta=10.0),
                                            1e-2))


def rough(seed: int, scales: int = 50):
    return SelfAffineProfile(hurst=0.8, scales=scales, rms=0.01, seed=seed)


def problem(profile, rheology, zeta, load=LOAD):
    return ContactProblem(method=BEM(), profile=profile, rheology=rheology, solver=Bisection(),
                          mean_pressure=load, zeta=zeta)


def friction_scale(mu, profile):
    return max(abs(mu), 1e-2 * math.sqrt(profile.m2))


def side_by_side(seeds, repeats, reference):
    print(f"p̃∞ = {LOAD}, peer at {PEER_POINTS} cells, spectral at its default tolerance; "
          f"median of {repeats} runs each, alternating")
    for label, rheology, zeta in RHEOLOGIES:
        print(f"\n{label}")
        print("seed  peer ms  spectral ms  ratio  cells  estimate   ΔÃ/Ã      Δμ/μs" +
              ("     errÃ spec  errÃ peer  errμ spec  errμ peer" if reference else ""))
        t_peer, t_spec = [], []
        for seed in seeds:
            profile = rough(seed)
            prob = problem(profile, rheology, zeta)
            tp, ts = [], []
            for _ in range(repeats):
                start = time.perf_counter()
                peer = peer_fft.solve(profile, LOAD, PEER_POINTS, rheology=rheology, zeta=zeta)
                tp.append(time.perf_counter() - start)
                start = time.perf_counter()
                spec = Spectral().solve(prob)
                ts.append(time.perf_counter() - start)
            tp, ts = float(np.median(tp)), float(np.median(ts))
            t_peer.append(tp)
            t_spec.append(ts)
            scale = friction_scale(peer.friction, profile)
            line = (f"{seed:4d} {tp * 1e3:8.1f} {ts * 1e3:12.1f} {ts / tp:6.2f} "
                    f"{spec.extras['points']:6d} {spec.extras['error_estimate']:9.1e} "
                    f"{(spec.area - peer.area) / peer.area:+9.1e} "
                    f"{(spec.friction - peer.friction) / scale:+9.1e}")
            if reference:
                ref = Spectral(points=REFERENCE_POINTS).solve(prob)
                if not ref.converged:
                    print(f"   reference not converged: {ref.message}")
                scale = friction_scale(ref.friction, profile)
                line += (f"  {(spec.area - ref.area) / ref.area:+9.1e}  "
                         f"{(peer.area - ref.area) / ref.area:+9.1e}  "
                         f"{(spec.friction - ref.friction) / scale:+9.1e}  "
                         f"{(peer.friction - ref.friction) / scale:+9.1e}")
            print(line)
        print(f"median over seeds: peer {np.median(t_peer) * 1e3:.1f} ms, spectral "
              f"{np.median(t_spec) * 1e3:.1f} ms, ratio {np.median(t_spec) / np.median(t_peer):.2f}"
              f" (median of the per-seed ratios "
              f"{np.median(np.array(t_spec) / np.array(t_peer)):.2f})")


def _order(points, errors):
    ok = np.abs(errors) > 0
    if ok.sum() < 2:
        return float("nan")
    slope = np.polyfit(np.log(np.asarray(points)[ok]), np.log(np.abs(errors)[ok]), 1)[0]
    return -float(slope)


def orders():
    sizes = (512, 1024, 2048, 4096, 8192, 16384)
    print("Westergaard (sinusoid, elastic): relative error of Ã; least-squares order")
    for load in (0.05, 0.3, 0.7, 0.95):
        prob = problem(Sinusoid(amplitude=0.1), Elastic(), 0.0, load)
        exact = float(westergaard_area(load))
        err = [(Spectral(points=n).solve(prob).area - exact) / exact for n in sizes]
        print(f"  p̃∞ = {load:4}: " + " ".join(f"{e:+.1e}" for e in err)
              + f"   order {_order(sizes, err):.2f}")
    print(f"Rough (seed 0, p̃∞ = {LOAD}) against {REFERENCE_POINTS} cells: Ã and μ (μ relative "
          "to max(|μ|, 1e-2·√m2)); least-squares orders")
    for label, rheology, zeta in RHEOLOGIES:
        profile = rough(0)
        prob = problem(profile, rheology, zeta)
        ref = Spectral(points=REFERENCE_POINTS).solve(prob)
        if not ref.converged:
            print(f"   reference not converged: {ref.message}")
        scale = friction_scale(ref.friction, profile)
        res = [Spectral(points=n).solve(prob) for n in sizes]
        ea = [(r.area - ref.area) / ref.area for r in res]
        em = [(r.friction - ref.friction) / scale for r in res]
        print(f"  {label}: Ã " + " ".join(f"{e:+.1e}" for e in ea)
              + f"   order {_order(sizes, ea):.2f}")
        print(f"  {' ' * len(label)}  μ " + " ".join(f"{e:+.1e}" for e in em)
              + f"   order {_order(sizes, em):.2f}")
    print("  cells: " + " ".join(f"{n:>8d}" for n in sizes))


def betas():
    """Convergence of the grid solvers as the operator grows less symmetric: a standard linear
    solid with β from 10 to 1e4 (``tan δ`` up to ``(β - 1)/(2√β)``), seeds 0 and 1, ζ = 0.01,
    0.1, 1, 10 and p̃∞ = 0.05, 0.25, 0.6 at the default tolerance."""
    for beta in (10.0, 100.0, 1e3, 1e4):
        runs = []
        for seed in (0, 1):
            for zeta in (0.01, 0.1, 1.0, 10.0):
                for load in (0.05, 0.25, 0.6):
                    prob = problem(rough(seed), StandardLinearSolid(beta=beta), zeta, load)
                    start = time.perf_counter()
                    res = Spectral().solve(prob)
                    runs.append((res.converged, time.perf_counter() - start))
        print(f"β = {beta:5g} (tan δ max {(beta - 1) / (2 * math.sqrt(beta)):.2f}): converged "
              f"{sum(c for c, _ in runs)} of {len(runs)}, slowest {max(t for _, t in runs):.2f} s")


def near_elastic(seeds, repeats):
    """ζ -> 0 against the relaxed elastic solid: ``Spectral()`` on a standard linear solid β = 10
    at ζ = 1e-8, 1e-5 and 1e-2 and on ``Elastic()`` (its relaxed modulus: Polonsky-Keer
    conjugate gradients on every grid), the same profile and load, alternating, from scratch
    (``problem.prepare()`` included), medians of ``repeats``; printed per ζ: both times, their
    ratio, the finest grid, the operator products of each and the last grid's solver (CPU
    time: the machine may be shared)."""
    print(f"p̃∞ = {LOAD}, default tolerance; median of {repeats} runs each, alternating")
    print("zeta    seed  elastic ms  sls ms  ratio  cells  products e/s  solver   (CPU ms)")
    for zeta in (1e-8, 1e-5, 1e-2):
        ratios = []
        for seed in seeds:
            elastic = problem(rough(seed), Elastic(), 0.0)
            sls = problem(rough(seed), StandardLinearSolid(beta=10.0), zeta)
            te, ts, re, rs = [], [], None, None
            for _ in range(repeats):
                start = time.process_time()
                re = Spectral().solve(elastic)
                te.append(time.process_time() - start)
                start = time.process_time()
                rs = Spectral().solve(sls)
                ts.append(time.process_time() - start)
            assert re is not None and rs is not None
            a, b = float(np.median(te)), float(np.median(ts))
            ratios.append(b / a)
            solver = rs.extras.get("solver", "")
            print(f"{zeta:6.0e} {seed:5d} {a * 1e3:11.1f} {b * 1e3:7.1f} {b / a:6.2f} "
                  f"{rs.extras['points']:6d} {re.function_evaluations:6d}/"
                  f"{rs.function_evaluations:<6d} {solver}")
        print(f"ζ = {zeta:g}: median ratio {np.median(ratios):.2f}")


def profile_solves():
    for label, rheology, zeta in RHEOLOGIES:
        prob = problem(rough(0), rheology, zeta)
        Spectral().solve(prob)
        prof = cProfile.Profile()
        prof.enable()
        for _ in range(5):
            Spectral().solve(prob)
        prof.disable()
        print(f"\n{label}: 5 solves from scratch")
        pstats.Stats(prof).sort_stats("tottime").print_stats(12)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", default="0,1,2,3,4")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--reference", action="store_true")
    ap.add_argument("--orders", action="store_true")
    ap.add_argument("--profile", action="store_true")
    ap.add_argument("--betas", action="store_true")
    ap.add_argument("--near-elastic", action="store_true")
    args = ap.parse_args(argv)
    if args.repeats < 1:
        print(f"--repeats = {args.repeats} is not allowed: expected an integer >= 1",
              file=sys.stderr)
        return 2
    if args.orders:
        orders()
    elif args.profile:
        profile_solves()
    elif args.betas:
        betas()
    elif args.near_elastic:
        near_elastic([int(s) for s in args.seeds.split(",")], args.repeats)
    else:
        side_by_side([int(s) for s in args.seeds.split(",")], args.repeats, args.reference)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
