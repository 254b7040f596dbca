"""Sampling independence of adhesive sweeps under each history.

Every scene is swept over the same ζ range recorded at 1, 3 and 8 points per decade, under each
history, and the curves are compared at the common ζ (the whole decades): Ã within 1e-3 of
max(Ã, 0.1) and μ within 1e-2 of max(|μ|, 0.01). Prints one table row per scene, load and
history and writes ``benchmarks/results/raw/histories.json``.

The approach-retraction ``cycle`` is recorded in the penetration, at the scene's ζ (or
``--cycle-zeta``): each
``--loads`` value is then the turning penetration Δ̃ of a cycle from first touch (Δ̃ = 0) and
back to detachment, recorded in steps of Δ̃/4 at one point "per decade", Δ̃/12 at three and
Δ̃/32 at eight; the curves are compared at the common points of both branches (the steps of
Δ̃/4 before the detachment's bisection), in Ã, μ and, beside them, the load p̃∞ (within 1e-3 of
max(|p̃∞|, 0.01)).

Usage::

    python benchmarks/histories.py [--scenes sinusoid,thesis_wavy,thesis_rough] [--seeds 0:5]
        [--loads 0.1,0.3,0.6] [--zetas 1e-4:1e2] [--per 1,3,8]
        [--histories approach,speed-ramp,cycle] [--cycle-zeta Z] [--workers 2] [--elements N]
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import tempfile
import time
from datetime import datetime, timezone
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
SCENES = HERE.parent / "examples" / "scenes"
AREA_TOL, FRICTION_TOL = 1e-3, 1e-2
#: A cycle recorded at one point "per decade" steps a quarter of its turning penetration.
CYCLE_STEPS = 4


def recorded(study, folder, workers) -> tuple[dict, dict]:
    """Run ``study`` in ``folder``: its points and what every recording reports (the failed
    points, among all it solved; the evaluations; the seconds)."""
    import viscocontact as vc

    t0 = time.perf_counter()
    data = vc.run_study(study, folder / "study.h5", overwrite=True, workers=workers,
                        progress=None)
    p = data.points
    return p, {"failed": int((~p["converged"]).sum()),
               "evaluations": int(p["function_evaluations"].sum()),
               "seconds": time.perf_counter() - t0}


def _options(elements) -> dict:
    from viscocontact.problem import Discretization

    return {} if elements is None else {"discretization": Discretization(elements=elements)}


def sweep(scene, zetas, load, history, workers, elements, folder):
    import viscocontact as vc

    study = vc.Sweep(scene=scene, zetas=zetas, loads=[load], pair=False, history=history,
                     **_options(elements))
    p, report = recorded(study, folder, workers)
    order = np.argsort(p["zeta"])
    return {"x": np.log10(p["zeta"][order]), "area": p["area"][order],
            "friction": p["friction"][order], "load": p["mean_pressure"][order],
            "converged": p["converged"][order], **report}


def cycle(scene, turn, per, workers, elements, folder, zeta=None):
    """One approach-retraction cycle to the penetration ``turn`` in steps of
    ``turn / (CYCLE_STEPS·per)``: its regular points (not the detachment's bisection) at
    ``x``, the distance along the cycle (Δ̃ on the approach, ``2·turn - Δ̃`` on the way out);
    its failed points counted among all of them."""
    import viscocontact as vc

    step = turn / (CYCLE_STEPS * per)
    if zeta is not None:
        scene = scene.replace(zeta=zeta, physical=None)
    study = vc.Cycle(scene=scene, max_penetration=turn, step=step, **_options(elements))
    p, report = recorded(study, folder, workers)
    out = np.where(p["phase"] == "approach", p["target"], 2.0 * turn - p["target"])
    regular = np.abs(out / step - np.round(out / step)) < 1e-6
    return {"x": out[regular], "area": p["area"][regular],
            "friction": p["friction"][regular], "load": p["mean_pressure"][regular],
            "converged": p["converged"][regular], **report}


def compare(curves: dict[int, dict]) -> dict:
    """Largest scaled differences at the common points (``x``: log10 ζ, or the distance along
    a cycle) against the finest recording."""
    finest = curves[max(curves)]
    worst = {"area": 0.0, "friction": 0.0, "load": 0.0}
    floors = {"area": 0.1, "friction": 0.01, "load": 0.01}
    for curve in curves.values():
        for j, x in enumerate(curve["x"]):
            i = int(np.argmin(np.abs(finest["x"] - x)))
            if abs(finest["x"][i] - x) > 1e-9:
                continue
            for key, floor in floors.items():
                a, b = float(curve[key][j]), float(finest[key][i])
                if np.isnan(a) or np.isnan(b):
                    # no contact: no friction (in both, they agree)
                    worst[key] = worst[key] if np.isnan(a) and np.isnan(b) else np.inf
                    continue
                worst[key] = max(worst[key], abs(a - b) / max(abs(a), floor))
    return worst


def main(argv=None) -> int:
    import viscocontact as vc
    from viscocontact.studies.base import parse_numbers, parse_seeds

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenes", default="sinusoid,thesis_wavy,thesis_rough")
    parser.add_argument("--seeds", default="0:5", help="seeds of the rough scene")
    parser.add_argument("--loads", default="0.1,0.3,0.6")
    parser.add_argument("--zetas", default="1e-4:1e2", help="START:STOP in whole decades")
    parser.add_argument("--per", default="1,3,8", help="points per decade")
    parser.add_argument("--histories", default="approach,speed-ramp")
    parser.add_argument("--cycle-zeta", type=float, default=None,
                        help="ζ of the cycles (default: the scene's)")
    parser.add_argument("--workers", type=int, default=1)
    parser.add_argument("--elements", type=int, default=None)
    parser.add_argument("--out", default=str(HERE / "results" / "raw" / "histories.json"))
    args = parser.parse_args(argv)

    start, stop = (math.log10(float(v)) for v in args.zetas.split(":"))
    decades = int(round(stop - start))
    pers = [int(v) for v in args.per.split(",")]
    rows = []
    print(f"{'scene':>14} {'load':>5} {'history':>10} {'ΔÃ':>9} {'Δμ':>9} {'Δp̃∞':>9} "
          f"{'failed':>6} {'evaluations per recording':>28} {'s':>7}")
    for name in args.scenes.split(","):
        base = vc.Scene.from_toml(SCENES / f"{name}.toml")
        seeds = parse_seeds(args.seeds) if name == "thesis_rough" else [None]
        for seed in seeds:
            scene = base if seed is None else _seeded(base, seed)
            label = name if seed is None else f"{name}#{seed}"
            for load in parse_numbers("--loads", args.loads):
                for history in args.histories.split(","):
                    curves = {}
                    with tempfile.TemporaryDirectory() as folder:
                        for per in pers:
                            if history == "cycle":
                                curves[per] = cycle(scene, load, per, args.workers,
                                                    args.elements, Path(folder),
                                                    args.cycle_zeta)
                                continue
                            zetas = np.logspace(start, stop, decades * per + 1)
                            curves[per] = sweep(scene, zetas, load, history, args.workers,
                                                args.elements, Path(folder))
                    worst = compare(curves)
                    failed = sum(c["failed"] for c in curves.values())
                    row = {"scene": label, "load": load, "history": history, **worst,
                           "failed": failed,
                           "evaluations": {str(p): c["evaluations"] for p, c in curves.items()},
                           "seconds": {str(p): c["seconds"] for p, c in curves.items()},
                           "passes": bool(worst["area"] <= AREA_TOL
                                          and worst["friction"] <= FRICTION_TOL
                                          and failed == 0),
                           "curves": {str(p): {k: np.asarray(c[k]).tolist() for k in
                                               ("x", "area", "friction", "load", "converged")}
                                      for p, c in curves.items()}}
                    rows.append(row)
                    print(f"{label:>14} {load:>5g} {history:>10} {worst['area']:>9.2e} "
                          f"{worst['friction']:>9.2e} {worst['load']:>9.2e} {failed:>6d} "
                          f"{'/'.join(str(c['evaluations']) for c in curves.values()):>28} "
                          f"{sum(c['seconds'] for c in curves.values()):>7.1f}", flush=True)
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    record = {"benchmark": "histories", "date": datetime.now(timezone.utc).isoformat(),
              "version": vc.__version__ if hasattr(vc, "__version__") else "",
              "args": vars(args), "rows": rows}
    tmp = out.with_suffix(".tmp")
    tmp.write_text(json.dumps(record, indent=1))
    tmp.replace(out)
    passed = sum(r["passes"] for r in rows)
    print(f"{passed} of {len(rows)} curves agree at 1e-3 in Ã and 1e-2 in μ with no failed "
          f"point; wrote {out}")
    return 0 if passed == len(rows) else 1


def _seeded(scene, seed):
    from viscocontact.scene import Scene

    data = scene.to_dict()
    data["profile"] = {**data["profile"], "seed": int(seed)}
    return Scene.from_dict(data)


if __name__ == "__main__":
    sys.exit(main())
