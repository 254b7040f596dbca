"""Shared pieces of the thesis-figure scripts (``fig_4_7.py`` ... ``fig_pressure_gap.py``).

The two cases of thesis §4.6, read from ``examples/scenes``:

* ``rough``: ``thesis_rough.toml``, the self-affine profile (H = 0.8, N_q = 50, r_rms = 10 µm,
  λ0 = 6.28 mm) on a standard linear solid (E0 = 10 MPa, β = 10), Δγ = 0.01 J/m²;
* ``wavy``: ``thesis_wavy.toml``, the sinusoid of §4.6.2 (λ0 = 1 mm, Λ = 8 µm) with the same
  material and adhesion, about the same m2 and Γ̃.

Each study is written with :func:`viscocontact.studies.run` and ``resume=True``: a script run
again (or another script asking for the same study, e.g. Figs. 4.7a and 4.10 share their sweeps)
computes only the points its file lacks. ``--force`` replaces a file that holds another study.
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

SCENES = Path(__file__).resolve().parent / "scenes"
FILES = {"rough": SCENES / "thesis_rough.toml", "wavy": SCENES / "thesis_wavy.toml"}


def floats(text: str) -> list[float]:
    """``"0,1e-4,1e-3"`` or ``"1e-5:1e3:9"`` (log-spaced START:STOP:N) as a list of floats."""
    from viscocontact.studies import log_zetas

    if ":" in text:
        start, stop, n = text.split(":")
        return [float(z) for z in log_zetas(float(start), float(stop), int(n))]
    return [float(v) for v in text.split(",") if v.strip()]


def ints(text: str) -> list[int]:
    """``"0,1,2"`` or ``"0:20"`` (range) as a list of ints."""
    if ":" in text:
        start, stop = text.split(":")
        return list(range(int(start), int(stop)))
    return [int(v) for v in text.split(",") if v.strip()]


def profiles(args) -> list[str]:
    """The profiles named by ``--profiles`` ("rough", "wavy" or both, comma separated)."""
    return [p.strip() for p in args.profiles.split(",") if p.strip()]


def common_arguments(parser: argparse.ArgumentParser) -> None:
    """``--out``, ``--full``, ``--workers``, ``--force``, ``--quiet`` and the hidden ``--tiny``."""
    parser.add_argument("--out", default=".", help="folder for the .h5 study files and PNGs")
    parser.add_argument("--full", action="store_true", help="the thesis's full size "
                        "(20 realizations, 30 ζ, 3 loads: days on one core)")
    parser.add_argument("--workers", type=int, default=1, help="worker processes")
    parser.add_argument("--force", action="store_true",
                        help="replace study files that hold a different study")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    parser.add_argument("--tiny", action="store_true", help=argparse.SUPPRESS)  # tests


def scene(case: str, *, edge_perturbation: float | None = None, solver: str | None = None):
    """The base scene of ``case`` (``"rough"`` or ``"wavy"``), optionally with another δX."""
    from viscocontact.scene import Scene

    data = Scene.from_toml(FILES[case].read_text()).to_dict()
    if edge_perturbation is not None:
        data["adhesion"] = {**data["adhesion"], "edge_perturbation": float(edge_perturbation)}
    if solver is not None:
        data["solver"] = {"kind": solver}
    return Scene.from_dict(data)


def compute(study, path: Path, args) -> "object":
    """Run (or complete) ``study`` into ``path``; print the time taken; return the StudyData."""
    from viscocontact.errors import ValidationError
    from viscocontact.studies import StudyFileError, run

    path.parent.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    progress = None if args.quiet else sys.stderr
    try:
        data = run(study, path, workers=args.workers, resume=True, progress=progress)
    except (StudyFileError, ValidationError):   # the file holds another study
        if not args.force:
            raise
        data = run(study, path, workers=args.workers, overwrite=True, progress=progress)
    failed = len(data.failed)
    print(f"{path}: {len(data)} points, {failed} not converged, "
          f"{time.perf_counter() - t0:.0f} s", flush=True)
    return data


def dx_tag(dx: float) -> str:
    """File-name tag of an edge perturbation: ``dx0``, ``dx1e-04``."""
    return "dx0" if dx == 0 else f"dx{dx:.0e}"


#: ζ-sweep sizes of Figs. 4.7 and 4.10 (which share their load-controlled sweeps): rough ζ run
#: downwards from the stiff end (cheap, few contacts) and each point continues from its neighbour.
SWEEPS = {
    "small": {"rough": {"zetas": "1e3,1,1e-1,1e-2,1e-5", "seeds": "0", "pressures": "0.3",
                        "penetrations": "0.5", "elements": 32},
              "wavy": {"zetas": "1e-5:1e3:9", "seeds": "", "pressures": "0.3",
                       "penetrations": "0.5", "elements": 64}},
    "full": {"rough": {"zetas": "1e4:1e-6:30", "seeds": "0:20", "pressures": "0.1,0.3,0.6",
                       "penetrations": "0.25,0.5,1", "elements": 32},
             "wavy": {"zetas": "1e-6:1e4:30", "seeds": "", "pressures": "0.1,0.3,0.6",
                      "penetrations": "0.25,0.5,1", "elements": 64}},
    "tiny": {"rough": {"zetas": "1e3", "seeds": "0", "pressures": "0.3", "penetrations": "0.2",
                       "elements": 16},
             "wavy": {"zetas": "1e3", "seeds": "", "pressures": "0.3", "penetrations": "0.5",
                      "elements": 32}},
}


def size_name(args) -> str:
    return "tiny" if args.tiny else "full" if args.full else "small"


def sweep_arguments(parser: argparse.ArgumentParser, default_dx: str = "0,1e-4,1e-3") -> None:
    """The options of the ζ-sweep figures (4.7, 4.10)."""
    parser.add_argument("--edge-perturbations", default=default_dx,
                        help="δX values (q0·δX) of the wavy adhesive curves; 0 is the limit")
    parser.add_argument("--rough-edge-perturbations", default="1e-4",
                        help="δX values of the rough adhesive curves")
    parser.add_argument("--rough-cohesive-ranges", default="",
                        help="Maugis-Dugdale ranges h0 in nm of extra rough adhesive curves "
                             "(docs/cohesive.md), e.g. 1,10; default none")
    parser.add_argument("--profiles", default="rough,wavy", help="rough, wavy or both")
    parser.add_argument("--zetas", default=None,
                        help="override the ζ list: 1e-3,1 or START:STOP:N (log-spaced)")
    parser.add_argument("--seeds", default=None, help="override the seeds (0,1 or 0:20)")
    parser.add_argument("--pressures", default=None, help="override the p̃∞ list")
    parser.add_argument("--penetrations", default=None, help="override the Δ̃ list")
    parser.add_argument("--history", choices=("approach", "speed-ramp"), default="approach",
                        help="how the adhesive points are reached: 'approach' (default: "
                             "loading from first touch at each ζ) or 'speed-ramp' (a slow "
                             "change of ζ at constant load); the ramp's files get a _ramp tag")


def sweep_family(profile: str, control: str, args) -> list:
    """The sweeps of one profile and control, one per δX and (rough) one per Maugis-Dugdale
    range of ``--rough-cohesive-ranges``: ``[(label, StudyData), ...]``, the label
    ``"δX = 1e-4"`` or ``"h0 = 1 nm"``. The adhesionless curve is the twin of the first δX's
    sweep, or for the profiles in :data:`SEPARATE_ADHESIONLESS` a sweep of its own, listed first
    with the label None."""
    from viscocontact.problem import Discretization
    from viscocontact.studies import Sweep

    size = SWEEPS[size_name(args)][profile]
    dxs = floats(args.edge_perturbations if profile == "wavy" else args.rough_edge_perturbations)
    loads = (args.pressures or size["pressures"] if control == "mean_pressure"
             else args.penetrations or size["penetrations"])
    seeds = ints(args.seeds if args.seeds is not None else size["seeds"]) or None
    if profile == "wavy":
        seeds = None
    common = dict(zetas=floats(args.zetas or size["zetas"]), loads=floats(loads), control=control,
                  seeds=seeds, discretization=Discretization(elements=size["elements"]))
    out = []
    if profile in SEPARATE_ADHESIONLESS:
        sweep = Sweep(scene=adhesionless_scene(profile), **common)
        path = Path(args.out) / f"sweep_{profile}_{control}_none.h5"
        out.append((None, compute(sweep, path, args)))
    history = getattr(args, "history", "approach")
    ramp = "" if history == "approach" else "_ramp"
    for i, dx in enumerate(dxs):
        sweep = Sweep(scene=scene(profile, edge_perturbation=dx), history=history,
                      pair=(i == 0 and profile not in SEPARATE_ADHESIONLESS), **common)
        tag = dx_tag(dx) + ramp
        path = Path(args.out) / f"sweep_{profile}_{control}_{tag}.h5"
        out.append((f"δX = {dx:g}", compute(sweep, path, args)))
    ranges = floats(getattr(args, "rough_cohesive_ranges", "") or "") if profile == "rough" else []
    for h0 in ranges:
        sweep = Sweep(scene=cohesive_scene(profile, h0), history=history, pair=False, **common)
        tag = f"md{h0:g}nm" + ramp
        path = Path(args.out) / f"sweep_{profile}_{control}_{tag}.h5"
        out.append((f"h0 = {h0:g} nm", compute(sweep, path, args)))
    return out


def cohesive_scene(profile: str, h0_nm: float):
    """The case with a Maugis-Dugdale zone of range ``h0_nm`` nanometres instead of the energy
    balance (the same work of adhesion; ``docs/cohesive.md``)."""
    from viscocontact.scene import Scene

    data = scene(profile).to_dict()
    data["adhesion"] = {"kind": "maugis-dugdale"}
    physical = {k: v for k, v in data.get("physical", {}).items()
                if k != "equilibrium_distance"}
    data["physical"] = {**physical, "cohesive_range": h0_nm * 1e-9}
    return Scene.from_dict(data)


#: Profiles whose adhesionless curves are a sweep of their own instead of the adhesive sweep's
#: twin. Both go through the planned method (``[method] kind = "auto"``: the spectral method for
#: an adhesionless scene, whatever its solver); the separate sweep dates from when the twin kept
#: the adhesive scene's Broyden solver in the BEM, where the rough adhesionless point at
#: ζ = 1e-2 ran 19 minutes and failed, and it keeps the study files' names.
SEPARATE_ADHESIONLESS = ("rough",)


def adhesionless_scene(profile: str):
    """The case without adhesion, with the package's adhesionless default solver."""
    from viscocontact.scene import Scene

    data = scene(profile).to_dict()
    data["adhesion"] = {"kind": "none"}
    data["solver"] = {"kind": "bisection"}
    data.get("physical", {}).pop("work_of_adhesion", None)
    return Scene.from_dict(data)


def family_curves(family) -> list[dict]:
    """Curves of :func:`viscocontact.plots.plot_panels` for a family of :func:`sweep_family`:
    one colour set and marker per curve."""
    markers = "os^vD<>"
    curves = []
    for i, (label, data) in enumerate(family):
        colors = [f"C{(i + 3 * j) % 10}" for j in range(4)] if len(family) > 1 else None
        curves.append({"data": data, "label": label or "",
                       "colors": colors, "marker": markers[i % len(markers)]})
    return curves


#: Approach-retraction cycle sizes of Figs. 4.8 and 4.9 (rough: one seed, as the thesis's Fig. 4.8).
CYCLES = {
    "small": {"rough": {"zetas": "1e-2,1", "factors": "0,4", "toughness_zetas": "1e-2,1",
                        "max_penetration": 0.5, "step": 0.1, "refine": 2, "elements": 32},
              "wavy": {"zetas": "1e-2,1", "factors": "0,4", "toughness_zetas": "1e-5:1e3:9",
                       "max_penetration": 0.2, "step": 0.01, "refine": 3, "elements": 64}},
    "full": {"rough": {"zetas": "1e-4,1e-3,1e-2,1e-1,1", "factors": "0,0.5,2,4",
                       "toughness_zetas": "1e-6:1e4:30", "max_penetration": 0.6, "step": 0.05,
                       "refine": 4, "elements": 32},
             "wavy": {"zetas": "1e-4,1e-3,1e-2,1e-1,1", "factors": "0,0.5,2,4",
                      "toughness_zetas": "1e-6:1e4:30", "max_penetration": 0.2, "step": 0.005,
                      "refine": 4, "elements": 64}},
    "tiny": {"rough": {"zetas": "1e3", "factors": "0", "toughness_zetas": "1e3",
                       "max_penetration": 0.2, "step": 0.1, "refine": 1, "elements": 16},
             "wavy": {"zetas": "1e3", "factors": "0", "toughness_zetas": "1e2,1e3",
                      "max_penetration": 0.3, "step": 0.15, "refine": 1, "elements": 32}},
}


def cycle(profile: str, name: str, args, *, zetas, gammas=None, seeds=None):
    """Compute one approach-retraction study into ``<out>/<name>.h5``; the StudyData."""
    from viscocontact.problem import Discretization
    from viscocontact.studies import Cycle

    size = CYCLES[size_name(args)][profile]
    study = Cycle(scene=scene(profile), zetas=zetas, gammas=gammas, seeds=seeds,
                  max_penetration=size["max_penetration"], step=size["step"],
                  refine=size["refine"], discretization=Discretization(elements=size["elements"]))
    return compute(study, Path(args.out) / f"{name}.h5", args)
