"""Snaps of the spectral method's cohesive zones: one grid solve just past first touch.

    python benchmarks/spectral_snaps.py [--out FILE.json]

Just past first touch (Δ̃ = -η + d) a strong, short-range law pulls the peak into contact: the
zones' tips move by many cells within one grid solve (:func:`~viscocontact.methods.spectral.
cohesive.cohesive_solve`, from the unloaded solid). Two sets, each solve's convergence, inner
solves, contact cells and area printed:

* elastic sinusoids (Λ̃ = 0.1) with Γ̃ = γ̃/Λ̃² and η = h̃0/Λ̃ of (0.05, 0.05), (0.2, 0.02),
  (0.05, 0.01) on 1024 and 4096 cells, d = 1e-4, 1e-3, 1e-2, beside the area of Maugis's wavy
  solution (``MaugisDugdaleWavy``) at that penetration;
* campaign seed 33 (a self-affine profile, N_q = 50, SLS β = 7781 at ζ = 1.7e-5,
  Maugis-Dugdale γ̃ = 3.9e-6, h̃0 = 1.9e-4) on 8192 to 131072 cells, d = 2e-4: where the
  snap lands on each grid (the contact's share of the period).

``--out`` writes the records (JSON list).
"""
from __future__ import annotations

import argparse
import json
import time

import numpy as np

import viscocontact as vc
from viscocontact.adhesion import MaugisDugdale
from viscocontact.methods.spectral import Spectral
from viscocontact.methods.spectral.cohesive import cohesive_solve
from viscocontact.methods.spectral.grid import UniformGrid
from viscocontact.methods.spectral.ladder import grid_options
from viscocontact.profiles import Sinusoid
from viscocontact.reference import MaugisDugdaleWavy
from viscocontact.rheology import Elastic
from viscocontact.testing.campaign import draw

AMPLITUDE = 0.1
SINUSOIDS = [(0.05, 0.05), (0.2, 0.02), (0.05, 0.01)]


def first_step(problem, points: int, past: float) -> dict:
    """One cohesive grid solve at ``Δ̃ = -η + past`` from the unloaded solid."""
    method = Spectral()
    prep = method.prepare(problem)
    law = method.law(problem, prep.shape.amplitude)
    grid = UniformGrid.of(prep.shape, points)
    op = prep.operators.circulant(prep.kernel, points)
    t0 = time.perf_counter()
    out = cohesive_solve(op, grid.heights, law, penetration=-law.opening + past,
                         start=np.zeros(points), start_penetration=-law.opening,
                         **grid_options(method))
    cells = int(out.contact.sum())
    return {"points": points, "past": past, "converged": bool(out.solution.converged),
            "sets": int(out.sets), "contact_cells": cells,
            "area": 2.0 * np.pi * cells / points, "seconds": time.perf_counter() - t0,
            "opening": float(law.opening)}


def wavy_area(Gamma: float, eta: float, penetration: float) -> float:
    """The area of Maugis's wavy solution at ``penetration`` (its contact branch)."""
    ref = MaugisDugdaleWavy(Gamma=Gamma, h0=eta)
    areas = np.linspace(0.05, 6.2, 247)
    pens = np.array([ref.state(a).penetration for a in areas])
    i = np.flatnonzero(np.diff(np.sign(pens - penetration)))
    if not i.size:
        return float("nan")
    k = int(i[-1])
    return float(areas[k] + (penetration - pens[k]) * (areas[k + 1] - areas[k])
                 / (pens[k + 1] - pens[k]))


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=None)
    args = ap.parse_args(argv)
    records = []
    for Gamma, eta in SINUSOIDS:
        problem = vc.ContactProblem(
            profile=Sinusoid(amplitude=AMPLITUDE), rheology=Elastic(),
            adhesion=MaugisDugdale(gamma=Gamma * AMPLITUDE**2, range=eta * AMPLITUDE),
            penetration=0.0, zeta=1.0)
        for points in (1024, 4096):
            for past in (1e-4, 1e-3, 1e-2):
                rec = first_step(problem, points, past)
                rec.update(case="sinusoid", Gamma=Gamma, eta=eta,
                           closed_form_area=wavy_area(Gamma, eta, past - eta))
                records.append(rec)
                print(f"sinusoid Γ̃ {Gamma:<5g} η {eta:<5g} {points:6d} cells d {past:<6g} "
                      f"{'converged' if rec['converged'] else 'NOT converged':14s} "
                      f"{rec['sets']:3d} solves  Ã {rec['area']:.4f} "
                      f"(Maugis {rec['closed_form_area']:.4f})")
    settled = sum(r["converged"] for r in records)
    print(f"{settled} of {len(records)} sinusoid snaps converge")
    problem = vc.ContactProblem.from_scene(vc.Scene.from_dict(draw(33)))
    for points in (8192, 16384, 32768, 65536, 131072):
        rec = first_step(problem, points, 2e-4)
        rec.update(case="campaign seed 33")
        records.append(rec)
        print(f"seed 33 {points:6d} cells: {'converged' if rec['converged'] else 'NOT':9s} "
              f"{rec['sets']:3d} solves, contact {rec['area'] / (2 * np.pi):.3f} of the period "
              f"({rec['seconds']:.1f} s)")
    if args.out:
        with open(args.out, "w") as fh:
            json.dump(records, fh, indent=1)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
