"""The adhesionless curves of the thesis figures and of the validation report, point by point:
what a source tree computes for them, and how far that is from a refined reference.

Three sets, each a ζ-sweep run as the figure scripts and the report run it (each point continued
from its neighbour, ``viscocontact.studies.Sweep``):

* ``fig-rough``: ``examples/fig_4_7.py`` / ``fig_4_10.py``, small size, rough profile: seed 0,
  p̃∞ = 0.3 and Δ̃ = 0.5, ζ = 1e3, 1, 0.1, 1e-2, 1e-5, 32 elements per contact;
* ``fig-wavy``: the same scripts' sinusoid, p̃∞ = 0.3 and Δ̃ = 0.5, 9 ζ from 1e-5 to 1e3;
* ``report-rough``: ``docs/validation.md``'s rough friction table, seeds 0 and 1, p̃∞ = 0.3,
  ζ = 100 … 0.01, 32 elements per contact.

The scenes carry no ``[method]`` section, so each tree uses its own default: before solution
methods existed, the BEM; since, the planned method (the spectral method for these scenes).

    PYTHONPATH=TREE python benchmarks/adhesionless_curves.py run > tree.jsonl
    python benchmarks/adhesionless_curves.py reference > reference.jsonl   # this tree
    python benchmarks/adhesionless_curves.py compare before.jsonl after.jsonl reference.jsonl

``reference`` solves every point from scratch with the spectral method at tolerance 1e-6 (a
point whose two-grid estimate stays above 1e-4, a tenth of the default tolerance, is flagged). ``compare`` prints one Markdown row
per point: both trees' Ã and μ/√m2, the relative change of Ã, and each tree's distance from the
reference (Ã relative; μ/√m2 relative to ``max(|μ/√m2|, 0.01)``, as the spectral method states
its tolerance).
"""
from __future__ import annotations

import argparse
import json
import sys
import tempfile
import time
from pathlib import Path

SCENES = Path(__file__).resolve().parents[1] / "examples" / "scenes"

#: (set, scene file, control, loads, ζ in sweep order, seeds, elements per contact)
SETS = [
    ("fig-rough", "thesis_rough.toml", "mean_pressure", [0.3], [1e3, 1, 0.1, 1e-2, 1e-5], [0], 32),
    ("fig-rough", "thesis_rough.toml", "penetration", [0.5], [1e3, 1, 0.1, 1e-2, 1e-5], [0], 32),
    ("fig-wavy", "thesis_wavy.toml", "mean_pressure", [0.3], None, None, 64),
    ("fig-wavy", "thesis_wavy.toml", "penetration", [0.5], None, None, 64),
    ("report-rough", "thesis_rough.toml", "mean_pressure", [0.3],
     [100, 10, 1, 0.3, 0.1, 0.01], [0, 1], 32),
]


#: μ/√m2 below this is compared in absolute terms (the spectral method's ``friction_floor``)
FRICTION_FLOOR = 1e-2


def adhesionless(name: str, solver: str):
    """The example scene ``name`` without adhesion and without a ``[method]`` section."""
    import tomllib

    from viscocontact.scene import Scene

    data = tomllib.loads((SCENES / name).read_text())
    data["adhesion"] = {"kind": "none"}
    data["solver"] = {"kind": solver}
    data.get("physical", {}).pop("work_of_adhesion", None)
    data.pop("method", None)
    return Scene.from_dict(data)


def wavy_zetas() -> list[float]:
    from viscocontact.studies import log_zetas

    return [float(z) for z in log_zetas(1e-5, 1e3, 9)]


def rows(set_name, name, control, loads, zetas, seeds, elements):
    """The sweep's records: one dict per point."""
    from viscocontact.problem import Discretization
    from viscocontact.studies import Sweep, run

    # the report's rough sweep used the scene's own (Broyden) solver, the figures bisection
    scene = adhesionless(name, "broyden" if set_name == "report-rough" else "bisection")
    sweep = Sweep(scene=scene, zetas=zetas or wavy_zetas(), loads=loads, control=control,
                  seeds=seeds, discretization=Discretization(elements=elements))
    with tempfile.TemporaryDirectory() as folder:
        t0 = time.perf_counter()
        data = run(sweep, Path(folder) / "sweep.h5", progress=None)
        seconds = time.perf_counter() - t0
        points = data.points
        for i in range(len(data)):
            yield {"set": set_name, "control": control, "seed": int(points["seed"][i]),
                   "load": float(points["load"][i]), "zeta": float(points["zeta"][i]),
                   "converged": bool(points["converged"][i]),
                   "area": float(points["area"][i]),
                   "reduced_friction": float(points["reduced_friction"][i]),
                   "method": str(points["method"][i]) if "method" in points else "",
                   "sweep_seconds": seconds}


def key(row) -> tuple:
    return (row["set"], row["control"], row["seed"], row["load"], round(row["zeta"], 12))


def reference(row) -> dict:
    """``row``'s point solved from scratch by the spectral method at tolerance 1e-6."""
    from viscocontact.methods.spectral import Spectral
    from viscocontact.problem import ContactProblem

    name = "thesis_wavy.toml" if row["set"] == "fig-wavy" else "thesis_rough.toml"
    scene = adhesionless(name, "bisection")
    load = {"mean_pressure": row["load"], "penetration": None} if row["control"] == "mean_pressure" \
        else {"mean_pressure": None, "penetration": row["load"]}
    if row["seed"] >= 0 and hasattr(scene.profile, "seed"):
        import attrs
        scene = attrs.evolve(scene, profile=attrs.evolve(scene.profile, seed=row["seed"]))
    problem = ContactProblem.from_scene(scene, zeta=row["zeta"], method=Spectral(tolerance=1e-6),
                                        **load)
    result = problem.solve()
    estimate = result.extras.get("error_estimate", float("nan"))
    return {**{k: row[k] for k in ("set", "control", "seed", "load", "zeta")},
            "converged": bool(result.converged), "area": float(result.area),
            "reduced_friction": float(result.reduced_friction), "error_estimate": estimate,
            "trusted": bool(result.converged and estimate <= 1e-4)}


def read(path) -> dict:
    with open(path) as f:
        return {key(r): r for r in map(json.loads, f) if r}


def compare(before, after, ref) -> None:
    before, after, ref = read(before), read(after), read(ref)
    print("| set | control | seed | load | ζ | Ã before | Ã after | change | before − ref "
          "| after − ref | μ/√m2 before | μ/√m2 after | μ before − ref | μ after − ref | ref. estimate |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    worst = {"change": 0.0, "before": 0.0, "after": 0.0, "mu_before": 0.0, "mu_after": 0.0}
    for k, a in after.items():
        b, r = before.get(k), ref.get(k)
        if b is None or r is None:
            print(f"| {' | '.join(map(str, k))} | missing |")
            continue

        def rel(x, y):
            return (x - y) / abs(y) if y else float("nan")

        change, eb, ea = rel(a["area"], b["area"]), rel(b["area"], r["area"]), rel(a["area"], r["area"])
        # μ as the spectral method states its tolerance: relative to max(|μ|, 0.01·√m2)
        mu_scale = max(abs(r["reduced_friction"]), FRICTION_FLOOR)
        mu_b = (b["reduced_friction"] - r["reduced_friction"]) / mu_scale
        mu_a = (a["reduced_friction"] - r["reduced_friction"]) / mu_scale
        for name, value in (("change", change), ("before", eb), ("after", ea),
                            ("mu_before", mu_b), ("mu_after", mu_a)):
            if value == value:
                worst[name] = max(worst[name], abs(value))
        flag = "" if r["converged"] and r["error_estimate"] <= 1e-4 else " (reference not trusted)"
        print(f"| {k[0]} | {k[1]} | {k[2]} | {k[3]:g} | {k[4]:g} | {b['area']:.6f} | "
              f"{a['area']:.6f} | {change:+.1e} | {eb:+.1e} | {ea:+.1e} | "
              f"{b['reduced_friction']:.4g} | {a['reduced_friction']:.4g} | {mu_b:+.1e} | {mu_a:+.1e} | "
              f"{r['error_estimate']:.1e}{flag} |")
    print()
    print("largest |relative|: change {change:.1e}, before − reference {before:.1e}, "
          "after − reference {after:.1e}; μ before − reference {mu_before:.1e}, "
          "after − reference {mu_after:.1e}".format(**worst))


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("command", choices=("run", "reference", "compare"))
    parser.add_argument("files", nargs="*")
    parser.add_argument("--sets", default=None, help="comma-separated subset of the sets")
    args = parser.parse_args(argv)
    wanted = set(args.sets.split(",")) if args.sets else None
    if args.command == "compare":
        compare(*args.files)
        return
    for spec in SETS:
        if wanted and spec[0] not in wanted:
            continue
        for row in rows(*spec):
            if args.command == "reference":
                row = reference(row)
            print(json.dumps(row), flush=True)
            print(f"{row['set']} {row['control']} seed {row['seed']} ζ {row['zeta']:g}: "
                  f"Ã {row['area']:.6f}", file=sys.stderr, flush=True)


if __name__ == "__main__":
    main()
