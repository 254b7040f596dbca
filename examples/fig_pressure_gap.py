"""Pressure and gap of single solutions against x̃, adhesive (solid) and adhesionless (dashed).

One ζ-sweep point with its fields stored (``Sweep(..., zetas=[ζ], fields=True)``), for the rough
profile of thesis §4.6 (seed 0) and for the sinusoid of §4.6.2, at ``--zeta`` (default 1, where
both profiles solve in seconds to a minute; adhesive rough solves at ζ ≈ 1e-3-1e-1 take minutes)
and ``--pressure`` p̃∞ (default 0.3). Pressure is compressive-positive; the material moves
towards −x, so each contact's leading edge is its right one (``docs/thesis-notes.md`` §4).

Writes ``fields_<profile>.h5`` and ``fig_pressure_gap_<profile>.png``.

Usage: ``python examples/fig_pressure_gap.py [--out DIR] [--zeta 1] [--pressure 0.3]
[--profiles rough,wavy] [--edge-perturbation 1e-4]``
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _thesis_cases as cases  # noqa: E402


def main(argv=None) -> list[Path]:
    from viscocontact.plots import plot_solution_fields
    from viscocontact.problem import Discretization
    from viscocontact.studies import Sweep

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    cases.common_arguments(parser)
    parser.add_argument("--profiles", default="rough,wavy", help="rough, wavy or both")
    parser.add_argument("--zeta", type=float, default=1.0, help="ζ = q0 V τ")
    parser.add_argument("--pressure", type=float, default=0.3, help="p̃∞")
    parser.add_argument("--edge-perturbation", type=float, default=None,
                        help="δX of the adhesive solution (default the package's 1e-4)")
    args = parser.parse_args(argv)
    written = []
    for profile in cases.profiles(args):
        elements = {"rough": 16 if args.tiny else 32, "wavy": 32 if args.tiny else 64}[profile]
        study = Sweep(scene=cases.scene(profile, edge_perturbation=args.edge_perturbation),
                      zetas=[args.zeta], loads=[args.pressure], fields=True,
                      seeds=[0] if profile == "rough" else None,
                      discretization=Discretization(elements=elements))
        data = cases.compute(study, Path(args.out) / f"fields_{profile}.h5", args)
        solutions = []
        for row in range(len(data)):
            fields = data.fields(row)
            if fields is None or not data.points["converged"][row]:
                continue
            variant = str(data.points["variant"][row])
            solutions.append({
                "fields": fields, "style": "-" if variant == "adhesive" else "--",
                "label": (f"{variant}: Ã = {data.points['area'][row]:.3f}, "
                          f"μ/√m2 = {data.points['reduced_friction'][row]:.3f}")})
        written += [data.path, plot_solution_fields(
            solutions, Path(args.out) / f"fig_pressure_gap_{profile}.png",
            title=f"{profile} profile, ζ = {args.zeta:g}, p̃∞ = {args.pressure:g}")]
        print(written[-1], flush=True)
    return written


if __name__ == "__main__":
    main()
