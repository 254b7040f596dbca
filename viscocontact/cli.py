"""The ``viscocontact`` command line.

Each subcommand is a pair of small functions registered in :data:`SUBCOMMANDS`:
``configure(parser)`` adds its arguments and ``run(args) -> int`` does the work. Errors about user
input (:class:`ValidationError`, :class:`PluginError`, a foreign or damaged study file, missing
files, TOML syntax) print one line to stderr and return exit code 2, never a traceback.
``sweep`` and ``cycle`` return 1 when some point failed (it is stored with its reason).
Ctrl-C prints one line (for a study: what its file keeps and how to resume it) and returns 130;
output piped into a reader that stops early (``| head``) ends quietly with 141.
"""
from __future__ import annotations

import argparse
import json
import sys
import tomllib
import warnings
from typing import Callable, Sequence

from ._cli_stops import Interrupted, kept_on_interrupt, quiet_stdout, verbose
from .errors import ValidationError, ViscoContactError

EXIT_USAGE = 2
EXIT_INTERRUPTED = 130      # 128 + SIGINT, as a shell reports a command stopped by Ctrl-C
EXIT_BROKEN_PIPE = 141      # 128 + SIGPIPE: the reader (``| head``) closed the pipe
_PROG = "viscocontact"


# ---- describe -----------------------------------------------------------------------------------
def _configure_describe(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("scene", metavar="SCENE.toml", help="scene file")
    parser.add_argument("--json", action="store_true", help="print the groups as JSON")


def _format_value(value) -> str:
    if isinstance(value, float):
        return f"{value:.6g}"
    return str(value)


#: SI units of the ``describe`` keys that are not dimensionless (text output only).
_DESCRIBE_UNITS = {"tabor_radius": "m", "adhesion_length": "m", "equilibrium_distance": "m",
                   "cohesive_range": "m", "cohesive_strength": "Pa",
                   "quasi_static_zone_length": "m"}


def _run_describe(args: argparse.Namespace) -> int:
    """Print the dimensionless groups of a scene (and its Tabor parameter)."""
    from ._json import dumps
    from .errors import ModelValidityWarning
    from .groups import dimensionless_groups
    from .read import read_scene
    from .scene import Scene

    with warnings.catch_warnings():     # listed below, with the groups they come from
        warnings.simplefilter("ignore", ModelValidityWarning)
        scene = read_scene(_path(args.scene))
    if isinstance(scene, Scene):
        groups = dimensionless_groups(scene)
    else:
        from .areal.report import areal_groups

        groups = areal_groups(scene)
    for message in groups["warnings"]:
        print(f"{_PROG} describe: warning: {message}", file=sys.stderr)
    if args.json:
        print(dumps(groups, indent=2, ensure_ascii=False))
        return 0
    width = max(len(k) for k in groups)
    for key, value in groups.items():
        if key in ("physical", "warnings"):
            continue
        unit = f" {_DESCRIBE_UNITS[key]}" if key in _DESCRIBE_UNITS and value is not None else ""
        print(f"{key:<{width}}  {_format_value(value)}{unit}")
    if groups["physical"]:
        print("physical:")
        for key, value in groups["physical"].items():
            print(f"  {key:<{width - 2}}  {_format_value(value)}")
    return 0


def _path(name: str):
    """A file named on the command line; the README's ``examples/scenes/NAME.toml`` is the copy
    shipped with the package when no such file exists here
    (:func:`viscocontact.data.scene_path`)."""
    from .data import scene_path

    return scene_path(name)


# ---- plugins ------------------------------------------------------------------------------------
def _configure_plugins(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--json", action="store_true", help="print the registry as JSON")


def _run_plugins(args: argparse.Namespace) -> int:
    """List the registered components and the distributions that provide them."""
    from ._registry import REGISTRIES

    table = {group: [{"name": d["name"], "distribution": d["distribution"]}
                     for d in registry.describe()]
             for group, registry in REGISTRIES.items()}
    if args.json:
        from ._json import dumps

        print(dumps(table, indent=2))
        return 0
    for group, entries in table.items():
        print(f"{group}:")
        if not entries:
            print("  (none)")
        width = max((len(e["name"]) for e in entries), default=0)
        for entry in entries:
            dist = entry["distribution"] or "unknown distribution"
            print(f"  {entry['name']:<{width}}  ({dist})")
    return 0


# ---- solve --------------------------------------------------------------------------------------
def _add_interior_resolution(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--interior-resolution", metavar="R", default=None,
        help="a contact's largest element is at most λ_min/R, λ_min the profile's shortest "
             "wavelength (1 <= R <= 64, or 'none'; default 8). It does not scale with "
             "--elements: for a mesh-convergence study scale both (e.g. 32 and 8, 64 and 16)")


def _interior_resolution(text: str) -> float | None:
    """``--interior-resolution``: a number in [1, 64], or ``None`` for 'none'."""
    if text.strip().lower() == "none":
        return None
    try:
        value = float(text)
    except ValueError:
        value = float("nan")
    if not 1.0 <= value <= 64.0:
        raise ValidationError("--interior-resolution", text, "a number in [1, 64], or 'none'")
    return value


def _configure_solve(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("scene", metavar="SCENE.toml", help="scene file")
    parser.add_argument("-v", "--verbose", action="store_true", default=argparse.SUPPRESS,
                        help="log each event of the solve (contacts born, merged, refined; "
                             "grids) to stderr as it happens, with the seconds since it began")
    parser.add_argument("--json", action="store_true", help="print the result as JSON")
    parser.add_argument("--fields", action="store_true",
                        help="include pressure, displacement and gap on the check grid")
    parser.add_argument("--si", action="store_true",
                        help="also the result in SI units (m, Pa), from the scene's [physical] "
                             "table")
    parser.add_argument("--elements", type=int, default=None, help="elements per contact")
    _add_interior_resolution(parser)
    parser.add_argument("--plot", metavar="FILE.png", default=None,
                        help="also draw the solution: pressure and gap against x̃ (a profile), "
                             "the contact map and the pressure field (a surface)")
    parser.add_argument("--explain", action="store_true",
                        help="print the solve plan (what is computed, what is skipped and why) "
                             "and exit without solving")
    parser.add_argument("--kernel-tolerance", metavar="TOL", type=float, default=None,
                        help="take memory branches in their relaxed or frozen limit when that "
                             "changes the kernel by at most TOL (0 < TOL <= 1e-2; default: only "
                             "outside ζ_i in [1e-12, 1e12])")


def _run_solve(args: argparse.Namespace) -> int:
    """Solve one scene; exit status 1 when the solve does not converge."""
    from .problem import ContactProblem, Discretization
    from .read import read_scene
    from .scene import Scene

    scene = read_scene(_path(args.scene))
    if not isinstance(scene, Scene):
        return _solve_areal(args, scene)
    options = {}
    disc = _discretization(args)
    if disc is not None:
        options["discretization"] = Discretization(**disc)
    if args.kernel_tolerance is not None:
        if not 0 < args.kernel_tolerance <= 1e-2:
            raise ValidationError("--kernel-tolerance", args.kernel_tolerance,
                                  "a number in (0, 1e-2]")
        options["kernel_tolerance"] = args.kernel_tolerance
    problem = ContactProblem.from_scene(scene, **options)
    if args.explain:
        from ._json import dumps

        plan = problem.plan()
        print(dumps(plan.to_dict(), ensure_ascii=False, indent=2) if args.json else plan)
        return 0
    if args.si:
        from .units import require_scale

        require_scale(scene)                # a scene without an SI scale: said before solving
    _check_plot(args.plot)
    result = problem.solve(fields=args.fields or args.plot is not None)
    if args.plot is not None:
        from .plots import plot_solution_fields

        print(f"wrote {plot_solution_fields(result, args.plot, scene=scene)}", file=sys.stderr)
    si = _si(result, scene) if args.si else None
    if args.json:
        if si is None:
            print(result.to_json(with_fields=args.fields))
        else:
            from ._json import dumps

            print(dumps({**result.to_dict(with_fields=args.fields), "si": si}))
    else:
        for key, value in result.to_dict().items():
            if key != "edge_terms":
                print(f"{key:<18} {_format_value(value)}")
        for key, value in (si or {}).items():
            print(f"{'si.' + key:<21} {_format_value(value)} {_SI_UNITS[key]}".rstrip())
    if not result.converged:
        print(f"viscocontact solve: not converged: {result.message}", file=sys.stderr)
        return 1
    return 0


def _solve_areal(args: argparse.Namespace, scene) -> int:
    """``solve`` of an areal scene: the plan (``--explain``) or the result with its areal
    quantities (:func:`~viscocontact.areal.report.areal_quantities`)."""
    from ._json import dumps
    from .areal.report import areal_fields, areal_quantities

    for option in ("elements", "interior_resolution", "kernel_tolerance"):
        if getattr(args, option) is not None:
            raise ValidationError(f"--{option.replace('_', '-')}", getattr(args, option),
                                  "no value for an areal scene (its grid is surface.grid, its "
                                  "options [method]'s)")
    if args.si:
        raise ValidationError("--si", True, "no value for an areal scene (its results are "
                                            "given in the dimensionless groups)")
    if args.explain:
        plan = scene.plan()
        print(dumps(plan.to_dict(), ensure_ascii=False, indent=2) if args.json else plan)
        return 0
    _check_plot(args.plot)
    result = scene.solve(fields=True)
    quantities = areal_quantities(result)
    if args.plot is not None:
        from .areal.plots import plot_contact

        print(f"wrote {plot_contact(result, args.plot)}", file=sys.stderr)
    for event in result.extras.get("events", []):
        if "under-resolved" in event:       # said at every solve, as --explain says it
            print(f"viscocontact solve: warning: {event}", file=sys.stderr)
    if args.json:
        out = {**result.to_dict(), **quantities,
               "patch_areas": json.loads(quantities["patch_areas"])}
        if args.fields:
            out["fields"] = {k: v.tolist() for k, v in (areal_fields(result) or {}).items()}
        print(dumps(out, ensure_ascii=False))
    else:
        for key, value in {**result.to_dict(), **quantities}.items():
            if key not in ("edges", "edge_terms", "patch_areas"):
                print(f"{key:<20} {_format_value(value)}")
    if not result.converged:
        print(f"viscocontact solve: not converged: {result.message}", file=sys.stderr)
        return 1
    return 0


def _check_plot(name: str | None) -> None:
    """``--plot FILE.png``: a file name in an existing folder this process can write in (said
    before solving)."""
    from pathlib import Path

    from ._outputs import check_folder

    if name is None:
        return
    path = Path(name)
    what = "a PNG file name in an existing folder"
    if path.is_dir() or not path.parent.is_dir():
        raise ValidationError("--plot", name, what)
    try:
        check_folder("--plot", path.parent, what)
    except ValidationError as exc:
        raise ValidationError("--plot", name, exc.allowed) from None


#: SI units of ``solve --si`` (:class:`~viscocontact.units.PhysicalResult`).
_SI_UNITS = {"contact_length": "m", "contact_fraction": "", "edges": "m", "penetration": "m",
             "mean_pressure": "Pa", "tangential_stress": "Pa", "friction": "",
             "wavelength": "m", "amplitude": "m"}


def _si(result, scene) -> dict:
    """``solve --si``: the result in SI units as plain data."""
    import attrs

    si = attrs.asdict(result.physical(scene))
    si["edges"] = si["edges"].tolist()
    return si


# ---- studies: shared options -------------------------------------------------------------------
def _add_study_options(parser: argparse.ArgumentParser, kind: str) -> None:
    parser.add_argument("scene", metavar="SCENE.toml", nargs="?",
                        help="base scene (optional with --resume: the file's own is used)")
    parser.add_argument("--seeds", metavar="SEEDS", default=None,
                        help="profile seeds, one realization each: 'START:STOP' or 'A,B,C'")
    parser.add_argument("--realizations", metavar="K", type=int, default=None,
                        help="K realizations with seeds 0..K-1 (same as --seeds 0:K)")
    parser.add_argument("--fields", action="store_true",
                        help="also store pressure, displacement and gap of every point")
    parser.add_argument("--elements", type=int, default=None, help="elements per contact")
    _add_interior_resolution(parser)
    parser.add_argument("--out", metavar="FILE.h5", default=None,
                        help=f"study file (default: <scene name>_{kind}.h5 in this folder)")
    parser.add_argument("--resume", action="store_true",
                        help="continue an interrupted study file (same scene and parameters)")
    parser.add_argument("--force", action="store_true", help="replace an existing study file")
    parser.add_argument("--workers", metavar="N", type=int, default=1,
                        help="compute independent chains in N processes (default 1)")
    parser.add_argument("--scheduler", metavar="ADDRESS", default=None,
                        help="send the points to this Dask distributed scheduler, or to the one "
                             "in Dask's configuration with 'config' (scheduler-address, "
                             "DASK_SCHEDULER_ADDRESS); pip install 'viscocontact[distributed]'")
    parser.add_argument("--scheduler-file", metavar="FILE", default=None,
                        help="send the points to the Dask scheduler that wrote FILE "
                             "(dask scheduler --scheduler-file FILE)")
    parser.add_argument("--time-limit", metavar="SECONDS", type=float, default=None,
                        help="seconds allowed to one point; a point past it is stored as an "
                             "error and its chain goes on (default: no limit)")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    parser.add_argument("--plot", action="store_true", help="also draw the PNG figures")


def _seeds(args):
    from .studies.base import parse_seeds

    if args.seeds is not None and args.realizations is not None:
        raise ValidationError("--realizations", args.realizations, "not both --seeds and "
                                                                   "--realizations")
    if args.realizations is not None:
        if args.realizations < 1:
            raise ValidationError("--realizations", args.realizations, "an integer >= 1")
        return tuple(range(args.realizations))
    return None if args.seeds is None else parse_seeds(args.seeds)


def _discretization(args):
    """The ``Discretization`` fields the command line sets (None: the defaults)."""
    disc = {} if args.elements is None else {"elements": args.elements}
    if args.interior_resolution is not None:
        disc["interior_resolution"] = _interior_resolution(args.interior_resolution)
    return disc or None


def _scheduler(args):
    """The Dask scheduler of ``--scheduler`` / ``--scheduler-file`` (None: no Dask)."""
    if args.scheduler is None and args.scheduler_file is None:
        return None
    from .studies.parallel import DaskScheduler

    spec = DaskScheduler(address=None if args.scheduler == "config" else args.scheduler,
                         scheduler_file=args.scheduler_file)
    spec.resolve()  # an unset address or a missing scheduler file: said before any file is made
    return spec


def _run_study_file(args, kind: str, build) -> int:
    """Build the study (or take it from the file with --resume alone), run it, report."""
    from pathlib import Path

    from .studies import resume, run

    if args.time_limit is not None and not 0 < args.time_limit < float("inf"):
        raise ValidationError("--time-limit", args.time_limit, "a finite number of seconds > 0")
    options = dict(workers=args.workers, scheduler=_scheduler(args),
                   progress=None if args.quiet else sys.stderr, time_limit=args.time_limit)
    if args.scene is None:
        if not (args.resume and args.out):
            raise ValidationError("SCENE.toml", None, "a scene file (or --resume --out FILE.h5 "
                                                      "to continue a study file)")
        out = Path(args.out)
        with kept_on_interrupt(kind, out):
            data = resume(out, **options)
    else:
        from .read import read_scene

        scene_path = _path(args.scene)
        study = build(read_scene(scene_path))
        out = Path(args.out) if args.out else Path(f"{scene_path.stem}_{kind}.h5")
        with kept_on_interrupt(kind, out):
            data = run(study, out, resume=args.resume, overwrite=args.force, **options)
    if data.kind != kind:
        raise ValidationError("--out", str(data.path), f"a {kind} study file (it holds a "
                                                       f"{data.kind})")
    failed = _report(data)
    if args.plot:
        from .plots import plot_study

        for f in plot_study(data):
            print(f"wrote {f}")
    return 1 if failed else 0


def _report(data) -> int:
    """Print a summary of a study file; the number of points that failed."""
    p = data.points
    if data.kind == "sweep":
        failed = int((~p["converged"]).sum())
        axes = data.axes()
        control = "p" if data.study.control == "mean_pressure" else "Delta"
        names = ("area_fraction", "friction") if data.areal else ("area", "reduced_friction")
        heads = ("A/A0", "mu") if data.areal else ("area", "mu/sqrt(m2)")
        print(f"{'variant':<13} {control:>8} {'zeta':>10} {heads[0]:>10} {heads[1]:>12} "
              f"{'n':>3}")
        area, fric = data.band(names[0]), data.band(names[1])
        for iv, variant in enumerate(axes["variant"]):
            for il, load in enumerate(axes["load"]):
                for iz, zeta in enumerate(axes["zeta"]):
                    print(f"{variant:<13} {load:>8.4g} {zeta:>10.4g} "
                          f"{area.mean[iv, il, iz]:>10.5g} {fric.mean[iv, il, iz]:>12.5g} "
                          f"{area.count[iv, il, iz]:>3d}")
        if data.params.get("certify"):
            from .studies.certify import failed as uncertified

            rows = [dict(zip(p, values)) for values in zip(*p.values())]
            bad = sum(1 for r in rows if uncertified(r, True))
            print(f"certified with a tenth of the tolerance: {bad} adhesive point(s) not "
                  "(see /points/message)" if bad else
                  "certified with a tenth of the tolerance: every converged adhesive point")
    else:
        from .studies.cycle import is_detached

        rows = [dict(zip(p, values)) for values in zip(*p.values())]
        failed = sum(1 for r in rows if not r["converged"]
                     and not (r["phase"] == "retract" and is_detached(r)))
        print(f"{'zeta':>10} {'gamma':>10} {'seed':>4} {'T':>10} {'Delta0':>9} {'Delta_out':>9} "
              f"{'min p':>9}")
        for cyc in data.cycles():
            m = cyc["metrics"]
            if m is None:
                continue
            print(f"{cyc['zeta']:>10.4g} {cyc['gamma']:>10.4g} {cyc['seed']:>4d} "
                  f"{m.toughness:>10.5g} {m.zero_load_penetration:>9.4g} "
                  f"{m.detachment_penetration:>9.4g} {m.pull_off_pressure:>9.4g}")
    note = f", {failed} failed (see /points/message)" if failed else ""
    print(f"wrote {data.path}: {len(data)} points{note}")
    return failed


def _add_certify(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--certify", action="store_true",
                        help="also solve every adhesive point under its history with a tenth of "
                             "the tolerance and record whether they agree (columns certified, "
                             "certified_area, certified_friction; 2-3 times the cost)")


# ---- sweep --------------------------------------------------------------------------------------
def _configure_sweep(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--zetas", metavar="ZETAS", default=None,
                        help="ζ values: 'START:STOP:N' log-spaced (e.g. 1e-4:1e3:15) or 'A,B,C'")
    parser.add_argument("--loads", metavar="LOADS", default=None,
                        help="values of the controlled load: 'A,B,C' or 'START:STOP:N' "
                             "(default: the scene's)")
    parser.add_argument("--control", choices=("mean_pressure", "penetration"), default=None,
                        help="load control p̃∞ or penetration control Δ̃ (default: the scene's)")
    parser.add_argument("--no-pair", dest="pair", action="store_false",
                        help="only the scene's adhesion (default: an adhesive scene is swept "
                             "with its adhesionless twin)")
    parser.add_argument("--history", choices=("approach", "speed-ramp"), default="approach",
                        help="how each adhesive point is reached: 'approach' (default: "
                             "loading from first touch at its own ζ) or 'speed-ramp' (a slow "
                             "change of ζ at constant load from the first ζ); stored with "
                             "every point")
    parser.add_argument("--ramp-tolerance", metavar="TOL", type=float, default=None,
                        help="the speed ramp's step-control tolerance (default 0.02)")
    _add_certify(parser)
    _add_study_options(parser, "sweep")


def _run_sweep(args: argparse.Namespace) -> int:
    """ζ-sweep of a scene (area and friction; adhesive and adhesionless) into an HDF5 file."""
    from .studies import Sweep
    from .studies.base import parse_numbers

    def build(scene):
        if args.zetas is None:
            raise ValidationError("--zetas", None, "'START:STOP:N' (log-spaced) or a list")
        options = {}
        if args.loads is not None:
            options["loads"] = parse_numbers("--loads", args.loads)
        if args.control is not None:
            options["control"] = args.control
            if args.loads is None and args.control != scene.load.controlled:
                raise ValidationError("--loads", None, f"values of {args.control} (the scene "
                                                       f"is in {scene.load.controlled} control)")
        history: dict = {"name": args.history}
        if args.ramp_tolerance is not None:
            if args.history != "speed-ramp":
                raise ValidationError("--ramp-tolerance", args.ramp_tolerance,
                                      "only with --history speed-ramp")
            history["tolerance"] = args.ramp_tolerance
        return Sweep(scene=scene, zetas=parse_numbers("--zetas", args.zetas, log=True),
                     seeds=_seeds(args), pair=args.pair, history=history,
                     fields=args.fields, discretization=_discretization(args),
                     certify=args.certify, **options)

    return _run_study_file(args, "sweep", build)


# ---- cycle --------------------------------------------------------------------------------------
def _configure_cycle(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--max-penetration", metavar="D", type=float, default=None,
                        help="Δ̃ at the turning point (required)")
    parser.add_argument("--step", metavar="S", type=float, default=None,
                        help="penetration step Δ̃ (required)")
    parser.add_argument("--start", metavar="D", type=float, default=0.0,
                        help="Δ̃ of the first approach point (default 0)")
    parser.add_argument("--min-penetration", metavar="D", type=float, default=None,
                        help="lowest Δ̃ of the retraction (default START - 2)")
    parser.add_argument("--refine", metavar="R", type=int, default=4,
                        help="bisection steps locating detachment (default 4)")
    parser.add_argument("--max-failures", metavar="N", type=int, default=3,
                        help="end a cycle after N failed points in a row (default 3)")
    parser.add_argument("--zetas", metavar="ZETAS", default=None,
                        help="one cycle per ζ: 'START:STOP:N' log-spaced or 'A,B,C' "
                             "(default: the scene's)")
    parser.add_argument("--gammas", metavar="GAMMAS", default=None,
                        help="one cycle per γ̃ ('A,B,C'; 0 = adhesionless)")
    _add_study_options(parser, "cycle")


def _run_cycle(args: argparse.Namespace) -> int:
    """Approach-retraction cycles in penetration control: hysteresis, pull-off, toughness."""
    from .studies import Cycle
    from .studies.base import parse_numbers

    def build(scene):
        from .scene import Scene

        if not isinstance(scene, Scene):
            raise ValidationError("SCENE.toml", args.scene, "a scene with a [profile]: cycles "
                                                            "of areal scenes are not available")
        for name in ("max_penetration", "step"):
            if getattr(args, name) is None:
                raise ValidationError(f"--{name.replace('_', '-')}", None, "a value (required)")
        options = {}
        if args.min_penetration is not None:
            options["min_penetration"] = args.min_penetration
        if args.zetas is not None:
            options["zetas"] = parse_numbers("--zetas", args.zetas, log=True)
        if args.gammas is not None:
            options["gammas"] = parse_numbers("--gammas", args.gammas)
        return Cycle(scene=scene, max_penetration=args.max_penetration, step=args.step,
                     start=args.start, refine=args.refine, max_failures=args.max_failures,
                     seeds=_seeds(args),
                     fields=args.fields, discretization=_discretization(args), **options)

    return _run_study_file(args, "cycle", build)


# ---- validate -----------------------------------------------------------------------------------
def _configure_validate(parser: argparse.ArgumentParser) -> None:
    from .reports.validation import configure_parser

    configure_parser(parser)


def _run_validate(args: argparse.Namespace) -> int:
    """Regenerate the validation report (docs/validation.md and its figures)."""
    from .reports.validation import run

    return run(args)


# ---- plot ---------------------------------------------------------------------------------------
def _configure_plot(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", metavar="FILE.h5", help="study file (sweep, cycle or study)")
    parser.add_argument("--out", metavar="DIR", default=None,
                        help="folder for the PNG files (default: next to FILE.h5)")


def _run_plot(args: argparse.Namespace) -> int:
    """Draw a study file: area and friction against ζ, or the load-penetration loops."""
    from .plots import plot_study

    if args.out is not None:
        _check_folder("--out", args.out, "a folder for the PNG files")
    for f in plot_study(_path(args.file), out=args.out):
        print(f"wrote {f}")
    return 0


def _check_folder(option: str, name: str, what: str) -> None:
    """A folder to write into (made if missing): not a file nor below one, and writable."""
    from ._outputs import check_folder

    check_folder(option, name, what)


# ---- study --------------------------------------------------------------------------------------
def _configure_study(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--out", default=".", help="folder for study.h5 and the PNG plots")
    parser.add_argument("--workers", metavar="N", type=int, default=None,
                        help="compute the points in N processes (default: one per CPU)")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    _add_certify(parser)


def _run_study(args: argparse.Namespace) -> int:
    """Run the default study (wavy contact, area and friction against ζ) and plot it."""
    from .studies import load_study
    from .study import WavyStudy

    import os

    workers = args.workers if args.workers is not None else (os.cpu_count() or 1)
    _check_folder("--out", args.out, "a folder for study.h5 and the plots")
    files = WavyStudy(certify=args.certify).run(args.out, workers=workers,
                            progress=None if args.quiet else sys.stderr)
    for f in files:
        print(f"wrote {f}")
    return 0 if load_study(files[0]).points["converged"].all() else 1


# ---- bench --------------------------------------------------------------------------------------
def _configure_bench(parser: argparse.ArgumentParser) -> None:
    from .reports.bench import configure_parser

    configure_parser(parser)


def _run_bench(args: argparse.Namespace) -> int:
    """Benchmark the nonlinear solvers and mesh sizes against the uniform-grid FFT peer."""
    from .reports.bench import run

    return run(args)


# ---- the parser ---------------------------------------------------------------------------------
Configure = Callable[[argparse.ArgumentParser], None]
Run = Callable[[argparse.Namespace], int]

#: subcommand name -> (configure(parser), run(args) -> exit code); the help text is the first
#: line of ``run``'s docstring. Add a subcommand by adding two small functions and one entry.
SUBCOMMANDS: dict[str, tuple[Configure, Run]] = {
    "describe": (_configure_describe, _run_describe),
    "plugins": (_configure_plugins, _run_plugins),
    "solve": (_configure_solve, _run_solve),
    "sweep": (_configure_sweep, _run_sweep),
    "cycle": (_configure_cycle, _run_cycle),
    "plot": (_configure_plot, _run_plot),
    "study": (_configure_study, _run_study),
    "validate": (_configure_validate, _run_validate),
    "bench": (_configure_bench, _run_bench),
}


def build_parser() -> argparse.ArgumentParser:
    """The argument parser with one sub-parser per entry of :data:`SUBCOMMANDS`."""
    from . import __version__

    parser = argparse.ArgumentParser(
        prog="viscocontact",
        description="Adhesive viscoelastic rough sliding contact "
                    "(dimensionless groups of the thesis's eq. 4.17).")
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    parser.add_argument("-v", "--verbose", action="store_true",
                        help="log what a solve does as it happens (to stderr)")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for name, (configure, run) in SUBCOMMANDS.items():
        help_text = (run.__doc__ or "").strip().splitlines()[0] if run.__doc__ else None
        subparser = sub.add_parser(name, help=help_text, description=help_text)
        configure(subparser)
        subparser.set_defaults(run=run)
    return parser


def _one_line(message: object) -> str:
    return " ".join(str(message).split())


def _one_line_warning(command: str):
    """A :func:`warnings.showwarning` that prints ``viscocontact COMMAND: warning: ...`` (the
    file and line of a library warning mean nothing to a command-line user)."""
    def show(message, category, filename, lineno, file=None, line=None):
        print(f"{_PROG} {command}: warning: {_one_line(message)}", file=file or sys.stderr)

    return show


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit code (0 success, 2 bad input)."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help, --version, usage errors (argparse already printed)
        return int(exc.code or 0) if not isinstance(exc.code, str) else EXIT_USAGE
    try:
        with warnings.catch_warnings(), verbose(args.verbose):
            warnings.showwarning = _one_line_warning(args.command)
            code = args.run(args)
        sys.stdout.flush()      # a closed pipe is found here, not at exit
        return code
    except Interrupted as exc:
        print(f"{_PROG} {args.command}: {exc}", file=sys.stderr)
        return EXIT_INTERRUPTED
    except KeyboardInterrupt:
        print(f"{_PROG} {args.command}: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except BrokenPipeError:
        quiet_stdout()
        return EXIT_BROKEN_PIPE
    except ViscoContactError as exc:  # ValidationError, PluginError, StudyFileError
        print(f"viscocontact {args.command}: error: {_one_line(exc)}", file=sys.stderr)
    except tomllib.TOMLDecodeError as exc:
        print(f"viscocontact {args.command}: error: invalid TOML in "
              f"{getattr(args, 'scene', '?')}: {_one_line(exc)}", file=sys.stderr)
    except FileNotFoundError as exc:
        what = f"no such file: {exc.filename}" if exc.filename else _one_line(exc)
        print(f"viscocontact {args.command}: error: {what}", file=sys.stderr)
    except (IsADirectoryError, PermissionError, UnicodeDecodeError) as exc:
        name = getattr(exc, "filename", None) or getattr(args, "scene", "?")
        print(f"viscocontact {args.command}: error: cannot read {name}: "
              f"{_one_line(getattr(exc, 'strerror', None) or exc)}", file=sys.stderr)
    return EXIT_USAGE


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
