"""Thesis Fig. 4.8: quasi-static approach-retraction cycles, contact area Ã against penetration Δ̃,
(a) for several ζ at the thesis's γ̃, (b) for several γ̃ at ζ = 1e-2; approach solid, retraction
dashed, detachment ×. One roughness realization (seed 0), as in the thesis.

γ̃ values are multiples of the thesis's γ̃ = 2.3885e-7 (Δγ = 0.01 J/m²): ``--gamma-factors``
(0 is adhesionless). Small default: rough profile, ζ = 1e-2, 1 in (a), factors 0 and 4 (plus 1
from (a)) in (b), Δ̃ from 0 to 0.5 in steps of 0.1, detachment bisected twice, 32 elements per
contact. ``--full``: ζ = 1e-4 ... 1, factors 0, 0.5, 1, 2, 4, steps of 0.05, 4 bisections.
``--profiles wavy`` draws the same cycles for the sinusoid (a single, path-independent branch).

Writes ``cycles_<profile>_zeta.h5``, ``cycles_<profile>_gamma.h5`` and ``fig_4_8_<profile>.png``.

Usage: ``python examples/fig_4_8.py [--out DIR] [--full] [--workers N] [--profiles rough,wavy]``
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _thesis_cases as cases  # noqa: E402


def main(argv=None) -> list[Path]:
    from viscocontact.plots import plot_cycles_panels

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    cases.common_arguments(parser)
    parser.add_argument("--profiles", default="rough", help="rough, wavy or both")
    parser.add_argument("--zetas", default=None, help="ζ of panel (a), e.g. 1e-2,1")
    parser.add_argument("--gamma-factors", default=None,
                        help="γ̃/γ̃_thesis of panel (b), e.g. 0,4 (1 is taken from panel a)")
    parser.add_argument("--gamma-zeta", type=float, default=1e-2, help="ζ of panel (b)")
    args = parser.parse_args(argv)
    written = []
    for profile in cases.profiles(args):
        size = cases.CYCLES[cases.size_name(args)][profile]
        seeds = [0] if profile == "rough" else None
        gamma = cases.scene(profile).to_dict()["adhesion"]["gamma"]
        zetas = cases.floats(args.zetas or size["zetas"])
        factors = cases.floats(args.gamma_factors or size["factors"])
        by_zeta = cases.cycle(profile, f"cycles_{profile}_zeta", args, zetas=zetas, seeds=seeds)
        by_gamma = cases.cycle(profile, f"cycles_{profile}_gamma", args, zetas=[args.gamma_zeta],
                               gammas=[f * gamma for f in factors], seeds=seeds)
        written += [by_zeta.path, by_gamma.path]
        panels = [{"title": f"(a) effect of ζ, γ̃ = {gamma:.3g}", "curves": [{"data": by_zeta}]},
                  {"title": f"(b) effect of γ̃, ζ = {args.gamma_zeta:g}",
                   "curves": [{"data": by_gamma},
                              {"data": by_zeta, "zetas": [args.gamma_zeta]}]}]
        written.append(plot_cycles_panels(
            panels, Path(args.out) / f"fig_4_8_{profile}.png",
            title=f"Fig. 4.8, {profile} profile: approach solid, retraction dashed, detachment ×"))
        print(written[-1], flush=True)
    return written


if __name__ == "__main__":
    main()
