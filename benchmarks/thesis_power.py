"""The power balance on the thesis's scenes, point by point.

Every point of ``examples/scenes/thesis_rough.toml`` (seeds 0-4) and ``thesis_wavy.toml`` at
p̃∞ = 0.1, 0.3 and 0.6 and ζ = 1e-6 … 1e3 (one a decade) is solved under the default history
(the approach from first touch) and checked as the campaign checks its scenes
(``viscocontact.testing.campaign.check``): the load met, no interpenetration, friction ≥ 0, and
friction equal to the dissipated power (bulk plus the net flux into the edges) within the two
sides' error estimates — unless the result says that it lies outside the δX model. Prints one
row per scene and load: points that hold the balance, points flagged outside the model (with
their ζ), points that fail it, points that did not converge, and the time.

    PYTHONPATH=. python benchmarks/thesis_power.py --workers 2 --out FILE.json
"""
from __future__ import annotations

import argparse
import json
import multiprocessing as mp
import os
import sys
import time
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SCENES = {"rough": ROOT / "examples" / "scenes" / "thesis_rough.toml",
          "wavy": ROOT / "examples" / "scenes" / "thesis_wavy.toml"}
DEFAULT_OUT = Path(__file__).resolve().parent / "results" / "raw" / "thesis_power.json"


def points(seeds, loads, zetas):
    """``(name, seed, load, zeta)`` of every point (``seed`` None for the wavy scene)."""
    out = [("wavy", None, p, z) for p in loads for z in zetas]
    out += [("rough", s, p, z) for s in seeds for p in loads for z in zetas]
    return out


def table(name: str, seed, load: float, zeta: float) -> dict:
    """The scene table of one point: the example scene with its seed, load and ζ."""
    import viscocontact as vc

    data = vc.Scene.from_toml(SCENES[name].read_text()).to_dict()
    if seed is not None:
        data["profile"]["seed"] = int(seed)
    data["load"] = {"mean_pressure": float(load)}
    data["sliding"] = {"zeta": float(zeta)}
    return data


def solve_point(args) -> dict:
    """Solve and check one point (in a worker)."""
    name, seed, load, zeta, limit = args
    from viscocontact.testing.campaign import run_scene

    out = run_scene(table(name, seed, load, zeta), time_limit=limit).to_dict()
    return {"scene": name, "seed": seed, "load": load, "zeta": zeta, **out}


def summarise(records) -> list[str]:
    rows = defaultdict(list)
    for r in records:
        rows[(r["scene"], r["seed"], r["load"])].append(r)
    lines = ["| scene | p̃∞ | balance holds | outside the model (ζ) | balance fails (ζ) | "
             "not converged (ζ) | s |", "|---|---|---|---|---|---|---|"]
    for (name, seed, load), rs in sorted(rows.items(), key=lambda kv: (kv[0][0] != "wavy",
                                                                        kv[0][1] or 0, kv[0][2])):
        rs.sort(key=lambda r: r["zeta"])
        holds = [r for r in rs if r["outcome"] == "converged" and not r["failures"]]
        outside = [r for r in rs if r["outcome"] == "outside-model" and not r["failures"]]
        fails = [r for r in rs if r["outcome"] in ("converged", "outside-model") and r["failures"]]
        other = [r for r in rs if r["outcome"] not in ("converged", "outside-model")]

        def zs(group):
            return ", ".join(f"{r['zeta']:g}" for r in group) or "-"

        label = name if seed is None else f"{name} seed {seed}"
        lines.append(f"| {label} | {load:g} | {len(holds)}/{len(rs)} | {zs(outside)} | "
                     f"{zs(fails)} | {zs(other)} | {sum(r['seconds'] for r in rs):.0f} |")
    return lines


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", default="0,1,2,3,4")
    ap.add_argument("--loads", default="0.1,0.3,0.6")
    ap.add_argument("--zetas", default="1e-6,1e-5,1e-4,1e-3,1e-2,0.1,1,10,100,1000")
    ap.add_argument("--time-limit", type=float, default=300.0)
    ap.add_argument("--workers", type=int, default=max(1, (os.cpu_count() or 2) // 2))
    ap.add_argument("--out", type=Path, default=DEFAULT_OUT)
    ap.add_argument("--table", action="store_true", help="print the table of --out")
    args = ap.parse_args(argv)
    if args.table:
        print("\n".join(summarise(json.loads(args.out.read_text())["records"])))
        return 0
    seeds = [int(s) for s in args.seeds.split(",")]
    loads = [float(p) for p in args.loads.split(",")]
    zetas = [float(z) for z in args.zetas.split(",")]
    jobs = [(*pt, args.time_limit) for pt in points(seeds, loads, zetas)]
    start = time.perf_counter()
    records = []
    with mp.get_context("spawn").Pool(args.workers, maxtasksperchild=8) as pool:
        for rec in pool.imap_unordered(solve_point, jobs):
            records.append(rec)
            print(f"{rec['scene']} {rec['seed']} p {rec['load']:g} ζ {rec['zeta']:g}: "
                  f"{rec['outcome']} {rec['seconds']:.1f} s {'; '.join(rec['failures'])[:160]}",
                  flush=True)
    wall = time.perf_counter() - start
    data = {"benchmark": "benchmarks/thesis_power.py", "time_limit": args.time_limit,
            "workers": args.workers, "wall_seconds": round(wall, 1), "records": records}
    tmp = args.out.with_suffix(".tmp")
    tmp.write_text(json.dumps(data, indent=1))
    tmp.replace(args.out)                    # never half-written
    print("\n".join(summarise(records)))
    print(f"wall {wall:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
