"""Thesis Fig. 4.7: contact area Ã against ζ, (a) at given mean pressure p̃∞, (b) at given
penetration Δ̃; adhesive solid, adhesionless dashed; rough and wavy profiles.

The adhesive curves depend on the virtual edge advance δX (``edge_perturbation``, see
``docs/edges.md``), which the thesis does not state. So the figure is drawn for a family of δX
(``--edge-perturbations``, default 0, 1e-4, 1e-3; 0 is the δX → 0 limit) on the wavy profile, and
for ``--rough-edge-perturbations`` (default only the package default 1e-4: adhesive rough solves
take minutes each) on the rough one. Every δX is its own study file; the adhesionless curve is
the twin of the first δX's sweep (wavy) or, for the rough profile, a sweep of its own with the
bisection solver (``sweep_rough_<control>_none.h5``).

Small default: rough profile one seed, p̃∞ = 0.3 and Δ̃ = 0.5, ζ = 1e3, 1, 0.1, 1e-2, 1e-5 (swept
downwards, each point from its neighbour), 32 elements per contact; sinusoid 9 ζ from 1e-5 to 1e3,
64 elements. Measured on a loaded 2-core machine (2026-11-24): wavy 29 s, rough 95 s (a single
adhesive rough point can take minutes, and studies have no per-point time limit). ``--full``: 20
realizations, 30 ζ from 1e-6 to 1e4, p̃∞ = 0.1, 0.3, 0.6 and Δ̃ = 0.25, 0.5, 1 (the thesis's size;
days on one core). The thesis does not state the loads of
its Fig. 4.7; these are our choice.

Writes ``sweep_<profile>_<control>_dx<δX>.h5`` (shared with ``fig_4_10.py``: a study already in
``--out`` is completed, not recomputed) and ``fig_4_7_rough.png``, ``fig_4_7_wavy.png``.

Usage: ``python examples/fig_4_7.py [--out DIR] [--full] [--workers N]
[--edge-perturbations 0,1e-4,1e-3] [--profiles rough,wavy] [--zetas 1e-3,1]
[--history speed-ramp] [--rough-cohesive-ranges 1]`` (``--history``: how the adhesive points
are reached, the approach by default or a slow change of speed, see ``docs/figures.md``;
``--rough-cohesive-ranges``: rough curves with Maugis–Dugdale zones of those ranges in nm,
``docs/cohesive.md``)
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
    written = []
    for profile in cases.profiles(args):
        panels = []
        for control, title in (("mean_pressure", "(a) load control"),
                               ("penetration", "(b) penetration control")):
            family = cases.sweep_family(profile, control, args)
            written += [data.path for _, data in family]
            panels.append({"title": title, "quantity": "area", "ylabel": "contact area Ã",
                           "curves": cases.family_curves(family)})
        written.append(plot_panels(
            panels, Path(args.out) / f"fig_4_7_{profile}.png",
            title=f"Fig. 4.7, {profile} profile: adhesive solid, adhesionless dashed"))
        print(written[-1], flush=True)
    return written


if __name__ == "__main__":
    main()
