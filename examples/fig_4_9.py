"""Thesis Fig. 4.9: contact toughness T̃ (eq. 4.57) against ζ, from quasi-static
approach-retraction cycles (the external work per period to pull the sliding profile off).

Small default: the rough profile (seed 0) at ζ = 1e-2 and 1, Δ̃ from 0 to 0.5 in steps of 0.1
(the cycles of ``fig_4_8.py``'s panel (a): when ``--out`` holds them for the same ζ they are read,
not recomputed), and the sinusoid at 9 ζ from 1e-5 to 1e3, Δ̃ from 0 to 0.2 in steps of 0.01.
``--full``: 20 realizations × 30 ζ from 1e-6 to 1e4, steps of 0.05 (days on one core). The
thesis's γ̃ = 2.3885e-7 (Δγ = 0.01 J/m²) throughout.

Writes ``toughness_<profile>.h5`` (or reuses ``cycles_rough_zeta.h5``) and ``fig_4_9.png``.

Usage: ``python examples/fig_4_9.py [--out DIR] [--full] [--workers N] [--profiles rough,wavy]``
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _thesis_cases as cases  # noqa: E402


def reusable(path: Path, zetas, seeds) -> bool:
    """Whether ``path`` (Fig. 4.8 (a)'s cycles) holds the cycles at exactly these ζ and seeds."""
    from viscocontact.studies import StudyFileError, load_study

    if not path.exists():
        return False
    try:
        params = load_study(path).params
    except StudyFileError:
        return False
    return params["zetas"] == list(zetas) and params["seeds"] == (None if seeds is None
                                                                   else list(seeds))


def main(argv=None) -> list[Path]:
    from viscocontact.plots import plot_toughness

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    cases.common_arguments(parser)
    parser.add_argument("--profiles", default="rough,wavy", help="rough, wavy or both")
    parser.add_argument("--zetas", default=None, help="override the ζ list (every profile)")
    parser.add_argument("--rough-zetas", default=None, help="override the rough profile's ζ")
    parser.add_argument("--seeds", default=None, help="override the rough seeds (0 or 0:20)")
    args = parser.parse_args(argv)
    written, curves = [], []
    for profile in cases.profiles(args):
        size = cases.CYCLES[cases.size_name(args)][profile]
        zetas = cases.floats((args.rough_zetas if profile == "rough" else None) or args.zetas
                             or size["toughness_zetas"])
        seeds = None
        if profile == "rough":
            seeds = cases.ints(args.seeds or ("0:20" if args.full else "0"))
        name = f"toughness_{profile}"
        if reusable(Path(args.out) / f"cycles_{profile}_zeta.h5", zetas, seeds):
            name = f"cycles_{profile}_zeta"   # the same study as Fig. 4.8 (a): read, not rerun
        data = cases.cycle(profile, name, args, zetas=zetas, seeds=seeds)
        written.append(data.path)
        curves.append({"data": data, "label": profile})
    written.append(plot_toughness(curves, Path(args.out) / "fig_4_9.png",
                                  title="Fig. 4.9: contact toughness in quasi-static unloading"))
    print(written[-1], flush=True)
    return written


if __name__ == "__main__":
    main()
