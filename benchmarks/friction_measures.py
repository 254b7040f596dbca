"""The two friction measures of the spectral methods under grid refinement.

    python benchmarks/friction_measures.py [--sizes 64,128,256,512] [--points 256,...,8192]
                                           [--out benchmarks/results/raw/friction_measures.json]

``result.friction`` is eq. 4.16 on the grid, ``-<p ∂h/∂s>/<p>`` with the rise of the rigid
profile across each loaded cell; ``extras["friction_dissipation"]`` is the power fed into the
solid by the same piecewise-constant pressure (the loss part of the kernel) over the load, i.e.
``-<p ∂u/∂s>/<p>`` with the displacement ``u`` the kernel gives. In the continuum ``u = h + c``
on the contact and the two are equal; on a grid ``u = h + c`` holds at the loaded centres only.
For every scene and grid this prints and writes both, their relative gap, the method's own
friction estimate, the errors of both against the 1D reference, and from the three finest grids
the observed order of each measure's grid-to-grid change and its Richardson limit (on the 1D
scenes the finest grids are at the solver's resolution, the reference is the check). 1D scenes:
a sinusoid and two self-affine profiles on a standard linear solid (β = 10) with a reference on
65536 cells; areal scenes: the acceptance surface of ``benchmarks/areal.py`` (wavenumbers 1 to
32, about 14 % contact) and a smoother one (1 to 8), each sampled on every grid.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
BETA = 10.0


def _limit(values: list[float]) -> dict:
    """Observed order and Richardson limit from the last three values of a doubling ladder."""
    if len(values) < 3:
        return {"order": math.nan, "limit": math.nan}
    a, b, c = values[-3:]
    ratio = (b - a) / (c - b) if c != b else math.inf
    if not ratio > 1.0:
        return {"order": math.nan, "limit": c}
    return {"order": math.log2(ratio), "limit": c + (c - b) / (ratio - 1.0)}


def _row(n, r) -> dict:
    fd = r.extras["friction_dissipation"]
    return {"points": n, "friction": r.friction, "friction_dissipation": fd,
            "gap": abs(r.friction / fd - 1.0),
            "friction_estimate": r.extras["estimates"]["friction"],
            "area": r.area, "converged": bool(r.converged)}


def line_scenes(points: list[int]) -> list[dict]:
    from viscocontact.methods.spectral import Spectral
    from viscocontact.problem import ContactProblem
    from viscocontact.profiles import SelfAffineProfile, Sinusoid
    from viscocontact.rheology import StandardLinearSolid
    from viscocontact.solvers import Broyden

    scenes = [("1D sinusoid, ζ = 1, p̃∞ = 0.3", Sinusoid(amplitude=0.1), 1.0, 0.3),
              ("1D self-affine seed 1, ζ = 1, p̃∞ = 0.3",
               SelfAffineProfile(hurst=0.8, scales=8, rms=0.01, seed=1), 1.0, 0.3),
              ("1D self-affine seed 2, ζ = 0.1, p̃∞ = 0.1",
               SelfAffineProfile(hurst=0.8, scales=8, rms=0.01, seed=2), 0.1, 0.1)]
    out = []
    for name, profile, zeta, load in scenes:
        prob = ContactProblem(profile=profile, rheology=StandardLinearSolid(beta=BETA),
                              solver=Broyden(), zeta=zeta, mean_pressure=load)
        rows = [_row(n, Spectral(points=n, residual=1e-12).solve(prob)) for n in points]
        ref = Spectral(points=65536, residual=1e-12).solve(prob)
        mu_ref = 0.5 * (ref.friction + ref.extras["friction_dissipation"])
        for r in rows:
            r["friction_error"] = abs(r["friction"] / mu_ref - 1.0)
            r["dissipation_error"] = abs(r["friction_dissipation"] / mu_ref - 1.0)
        out.append({"scene": name, "rows": rows, "reference_points": 65536,
                    "reference": {"friction": ref.friction,
                                  "friction_dissipation": ref.extras["friction_dissipation"]}})
    return out


def areal_scenes(sizes: list[int]) -> list[dict]:
    sys.path.insert(0, str(HERE))
    from areal import self_affine

    from viscocontact.areal.method import ArealSpectral
    from viscocontact.areal.problem import ArealProblem
    from viscocontact.rheology import StandardLinearSolid

    out = []
    for name, q_max, zeta in (("areal acceptance surface (q ≤ 32), ζ = 1", 32.0, 1.0),
                              ("areal smooth surface (q ≤ 8), ζ = 1", 8.0, 1.0),
                              ("areal smooth surface (q ≤ 8), ζ = 0.1", 8.0, 0.1)):
        rows = []
        for n in sizes:
            prob = ArealProblem(surface=self_affine(n, q_max=q_max),
                                rheology=StandardLinearSolid(beta=BETA), zeta=zeta,
                                mean_pressure=1.0)
            rows.append(_row(n, ArealSpectral(residual=1e-11).solve(prob)))
        out.append({"scene": name, "rows": rows})
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="64,128,256,512")
    ap.add_argument("--points", default="256,512,1024,2048,4096,8192")
    ap.add_argument("--out", default=str(HERE / "results" / "raw" / "friction_measures.json"))
    args = ap.parse_args(argv)
    scenes = line_scenes([int(v) for v in args.points.split(",")]) \
        + areal_scenes([int(v) for v in args.sizes.split(",")])
    for s in scenes:
        s["friction_limit"] = _limit([r["friction"] for r in s["rows"]])
        s["dissipation_limit"] = _limit([r["friction_dissipation"] for r in s["rows"]])
        print(s["scene"])
        for r in s["rows"]:
            print(f"  {r['points']:6d}  μ {r['friction']:.10f}  μ_diss "
                  f"{r['friction_dissipation']:.10f}  gap {r['gap']:.2e}  "
                  f"estimate {r['friction_estimate']:.2e}" + (
                      f"  errors {r['friction_error']:.2e} {r['dissipation_error']:.2e}"
                      if "friction_error" in r else ""))
        for key in ("friction_limit", "dissipation_limit"):
            print(f"  {key}: order {s[key]['order']:.2f}, limit {s[key]['limit']:.10f}")
        if "reference" in s:
            print(f"  65536 cells: μ {s['reference']['friction']:.10f}, μ_diss "
                  f"{s['reference']['friction_dissipation']:.10f}")
    Path(args.out).write_text(json.dumps({"beta": BETA, "scenes": scenes}, indent=1,
                                         default=float))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
