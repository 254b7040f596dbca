"""Thesis Fig. 4.10: reduced friction μ/√m2 against ζ at given mean pressure p̃∞, (a) rough and
(b) wavy profile; adhesive solid, adhesionless dashed.

The rough profile and the sinusoid are those of thesis §4.6.2 (same material and work of adhesion,
about the same m2 and Γ̃; ``examples/scenes/thesis_rough.toml`` and ``thesis_wavy.toml``). The
adhesive curves depend on the edge advance δX (``docs/edges.md``): the wavy panel is drawn for
``--edge-perturbations`` (default 0, 1e-4, 1e-3), the rough one for
``--rough-edge-perturbations`` (default 1e-4).

Small default: rough one seed, p̃∞ = 0.3, ζ = 1e3, 1, 0.1, 1e-2, 1e-5, 32 elements per contact;
sinusoid 9 ζ from 1e-5 to 1e3. ``--full``: 20 realizations × 30 ζ (1e-6 to 1e4) × p̃∞ = 0.1,
0.3, 0.6 (the thesis's size; the thesis names p̃∞ ≈ 0.6 only, the other loads are our choice).

The load-controlled sweeps are the same files as those of ``fig_4_7.py``
(``sweep_<profile>_mean_pressure_dx<δX>.h5``): run into the same ``--out``, the second script
only reads them. Writes ``fig_4_10.png``.

``--rough-cohesive-ranges 1,10`` adds rough adhesive curves with a Maugis–Dugdale zone of
those ranges h0 in nm instead of the energy balance (``sweep_rough_mean_pressure_md1nm.h5``;
``docs/cohesive.md``).

Usage: ``python examples/fig_4_10.py [--out DIR] [--full] [--workers N]
[--edge-perturbations 0,1e-4,1e-3] [--zetas 1e-3,1] [--history speed-ramp]
[--rough-cohesive-ranges 1]`` (``--history``: how the adhesive points are reached, the
approach by default or a slow change of speed; see ``docs/figures.md``)
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _thesis_cases as cases  # noqa: E402


def main(argv=None) -> list[Path]:
    from viscocontact.plots import plot_panels

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    cases.common_arguments(parser)
    cases.sweep_arguments(parser)
    args = parser.parse_args(argv)
    written, panels = [], []
    for tag, profile in zip("ab", cases.profiles(args)):
        family = cases.sweep_family(profile, "mean_pressure", args)
        written += [data.path for _, data in family]
        panels.append({"title": f"({tag}) {profile}", "quantity": "reduced_friction",
                       "ylabel": "reduced friction μ/√m2", "curves": cases.family_curves(family)})
    written.append(plot_panels(panels, Path(args.out) / "fig_4_10.png",
                               title="Fig. 4.10: adhesive solid, adhesionless dashed"))
    print(written[-1], flush=True)
    return written


if __name__ == "__main__":
    main()
