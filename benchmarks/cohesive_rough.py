"""The thesis rough scene with Maugis-Dugdale zones over a grid of ζ and loads: result, checks,
seconds and evaluations per point, next to a dense solve timed in the same run.

    python benchmarks/cohesive_rough.py [--zeta 1e-6,1e-2,1,1e4] [--pressure 0.05,0.3,0.6]
                                        [--range 1e-9] [--seed 0] [--json FILE]

The scene is ``examples/scenes/thesis_rough.toml`` (H = 0.8, N_q = 50, q0·r_rms = 0.01, SLS
β = 10, Δγ = 0.01 J/m²) with ``[adhesion] kind = "maugis-dugdale"`` and
``physical.cohesive_range`` (default 1 nm: h̃0 = 1.0e-6, λ = 523), from first touch, the scene's
solver (Broyden) and the default mesh.

Checks of a converged point (``ok``): the target load to 1e-12; a positive gap outside the
contacts; the largest tension at most σ̃0 (the law's strength), in the contacts and the zones;
friction by eq. 4.16 within 3 % of the dissipated power (``docs/cohesive.md``: they differ by the
discretisation of ``u' = r'`` between collocation points, most at ζ = 1e-6). The tip condition
``g̃(c) = η`` is the residual the solve converged on.

The yardstick is ``numpy.linalg.solve`` of a 2000 × 2000 dense system with one BLAS thread
(:func:`adhesive_point.dense_solve_seconds`), so that times can be compared between runs on a
loaded machine.
"""
from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "examples"))         # _thesis_cases
sys.path.insert(0, str(Path(__file__).resolve().parent))   # adhesive_point


def problem(zeta: float, pressure: float, cohesive_range: float, seed: int):
    """The thesis rough scene with zones of ``cohesive_range`` metres
    (:func:`_thesis_cases.cohesive_scene` of the examples), realization ``seed``."""
    import attrs

    from viscocontact.problem import ContactProblem
    from viscocontact.scene import Scene

    import _thesis_cases as cases

    data = cases.cohesive_scene("rough", cohesive_range / 1e-9).to_dict()
    data["profile"]["seed"] = seed
    prob = ContactProblem.from_scene(Scene.from_dict(data))
    return attrs.evolve(prob, zeta=zeta, mean_pressure=pressure)


def checks(r, prob) -> dict:
    """The independent checks of a converged point (see the module docstring)."""
    strength = prob.adhesion.strength(prob.prepare().shape.amplitude)
    # the cohesive law holds every traction at or below its strength, inside the contacts and
    # in the zones (a grid's contact cells keep a gap of round-off, not exactly zero)
    tension = float(np.max(-np.asarray(r.fields["pressure"])))
    mu, mu_d = r.friction, r.extras["friction_dissipation"]
    out = {"load": abs(r.mean_pressure - prob.mean_pressure) <= 1e-12,
           "gap": bool(r.min_gap > 0),
           "tension": bool(tension <= strength * (1 + 1e-9)),
           "friction": bool(abs(mu - mu_d) <= 0.03 * abs(mu_d))}
    out["largest_tension"] = tension
    out["strength"] = strength
    return out


def main(argv=None) -> None:
    from adhesive_point import dense_solve_seconds

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--zeta", default="1e-6,1e-2,1,1e4")
    ap.add_argument("--pressure", default="0.05,0.3,0.6")
    ap.add_argument("--range", type=float, default=1e-9, help="h0 in metres (default 1 nm)")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--json", default=None, help="append one JSON line per point to FILE")
    args = ap.parse_args(argv)
    ref = dense_solve_seconds()
    print(f"numpy 2000x2000 solve, one BLAS thread: {ref:.3f} s", flush=True)
    print(f"{'zeta':>6s} {'p':>5s} {'result':>10s} {'area':>9s} {'n':>3s} {'mu':>11s} "
          f"{'mu_diss':>11s} {'checks':>6s} {'s':>7s} {'x solve':>8s} {'ev':>5s}", flush=True)
    for zeta in (float(z) for z in args.zeta.split(",")):
        for p in (float(v) for v in args.pressure.split(",")):
            prob = problem(zeta, p, args.range, args.seed)
            t = time.perf_counter()
            r = prob.solve(fields=True)
            dt = time.perf_counter() - t
            row = {"zeta": zeta, "pressure": p, "range": args.range, "seed": args.seed,
                   "converged": bool(r.converged), "full_contact": bool(r.full_contact),
                   "message": r.message, "area": r.area, "contacts": r.n_contacts,
                   "friction": r.friction, "friction_dissipation":
                   r.extras["friction_dissipation"], "seconds": dt, "dense_solve": ref,
                   "evaluations": r.function_evaluations, "iterations": r.iterations}
            ok = ""
            if r.converged and not r.full_contact:
                c = checks(r, prob)
                row["checks"] = c
                ok = "ok" if all(c[k] for k in ("load", "gap", "tension", "friction")) else "FAIL"
            result = ("full" if r.full_contact else "converged") if r.converged else "failed"
            print(f"{zeta:6.0e} {p:5.2f} {result:>10s} {r.area:9.5f} {r.n_contacts:3d} "
                  f"{r.friction:11.5g} {row['friction_dissipation']:11.5g} {ok:>6s} {dt:7.1f} "
                  f"{dt / ref:8.0f} {r.function_evaluations:5d}", flush=True)
            if not r.converged:
                print(f"       {r.message}", flush=True)
            if args.json:
                with open(args.json, "a") as fh:
                    fh.write(json.dumps(row, default=float) + "\n")


if __name__ == "__main__":
    main()
