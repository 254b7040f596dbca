"""The ``viscocontact`` command line.

Each subcommand is a pair of small functions registered in :data:`SUBCOMMANDS`:
``configure(parser)`` adds its arguments and ``run(args) -> int`` does the work. Errors about user
input (:class:`ValidationError`, :class:`PluginError`, missing files, TOML syntax) print one line
to stderr and return exit code 2, never a traceback.
"""
from __future__ import annotations

import argparse
import json
import sys
import tomllib
from typing import Callable, Sequence

from .errors import PluginError, ValidationError

EXIT_USAGE = 2


# ---- describe -----------------------------------------------------------------------------------
def _configure_describe(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("scene", metavar="SCENE.toml", help="scene file")
    parser.add_argument("--json", action="store_true", help="print the groups as JSON")


def _format_value(value) -> str:
    if isinstance(value, float):
        return f"{value:.6g}"
    return str(value)


def _run_describe(args: argparse.Namespace) -> int:
    """Print the dimensionless groups of a scene (and its Tabor parameter)."""
    from .groups import dimensionless_groups
    from .scene import Scene

    groups = dimensionless_groups(Scene.from_toml(_path(args.scene)))
    for message in groups["warnings"]:
        print(f"warning: {message}", file=sys.stderr)
    if args.json:
        print(json.dumps(groups, indent=2, ensure_ascii=False))
        return 0
    width = max(len(k) for k in groups)
    for key, value in groups.items():
        if key in ("physical", "warnings"):
            continue
        print(f"{key:<{width}}  {_format_value(value)}")
    if groups["physical"]:
        print("physical:")
        for key, value in groups["physical"].items():
            print(f"  {key:<{width - 2}}  {_format_value(value)}")
    return 0


def _path(name: str):
    from pathlib import Path

    return Path(name)


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
        print(json.dumps(table, indent=2))
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
def _configure_solve(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("scene", metavar="SCENE.toml", help="scene file")
    parser.add_argument("--json", action="store_true", help="print the result as JSON")
    parser.add_argument("--fields", action="store_true",
                        help="include pressure, displacement and gap on the check grid")
    parser.add_argument("--elements", type=int, default=None, help="elements per contact")


def _run_solve(args: argparse.Namespace) -> int:
    """Solve one scene; exit status 1 when the solve does not converge."""
    from .problem import ContactProblem, Discretization
    from .scene import Scene

    scene = Scene.from_toml(_path(args.scene))
    options = {}
    if args.elements is not None:
        options["discretization"] = Discretization(elements=args.elements)
    result = ContactProblem.from_scene(scene, **options).solve(fields=args.fields)
    if args.json:
        print(result.to_json(with_fields=args.fields))
    else:
        for key, value in result.to_dict().items():
            if key != "edge_terms":
                print(f"{key:<18} {_format_value(value)}")
    if not result.converged:
        print(f"viscocontact solve: not converged: {result.message}", file=sys.stderr)
        return 1
    return 0


# ---- study --------------------------------------------------------------------------------------
def _configure_study(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--out", default=".", help="folder for study.h5 and the PNG plots")


def _run_study(args: argparse.Namespace) -> int:
    """Run the default study (wavy contact, area and friction against ζ) and plot it."""
    from pathlib import Path

    from .study import WavyStudy, plot, write_h5

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    study = WavyStudy()
    results = study.run()
    write_h5(out / "study.h5", study, results)
    for f in [out / "study.h5", *plot(out, results)]:
        print(f"wrote {f}")
    ok = all(results[k]["converged"].all() for k in ("adhesive", "adhesionless"))
    return 0 if ok else 1


# ---- the parser ---------------------------------------------------------------------------------
Configure = Callable[[argparse.ArgumentParser], None]
Run = Callable[[argparse.Namespace], int]

#: subcommand name -> (configure(parser), run(args) -> exit code); the help text is the first
#: line of ``run``'s docstring. Add a subcommand by adding two small functions and one entry.
SUBCOMMANDS: dict[str, tuple[Configure, Run]] = {
    "describe": (_configure_describe, _run_describe),
    "plugins": (_configure_plugins, _run_plugins),
    "solve": (_configure_solve, _run_solve),
    "study": (_configure_study, _run_study),
}


def build_parser() -> argparse.ArgumentParser:
    """The argument parser with one sub-parser per entry of :data:`SUBCOMMANDS`."""
    from . import __version__

    parser = argparse.ArgumentParser(
        prog="viscocontact",
        description="Adhesive viscoelastic rough sliding contact "
                    "(dimensionless groups of the thesis's eq. 4.17).")
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for name, (configure, run) in SUBCOMMANDS.items():
        help_text = (run.__doc__ or "").strip().splitlines()[0] if run.__doc__ else None
        subparser = sub.add_parser(name, help=help_text, description=help_text)
        configure(subparser)
        subparser.set_defaults(run=run)
    return parser


def _one_line(message: str) -> str:
    return " ".join(str(message).split())


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit code (0 success, 2 bad input)."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help, --version, usage errors (argparse already printed)
        return int(exc.code or 0) if not isinstance(exc.code, str) else EXIT_USAGE
    try:
        return args.run(args)
    except (ValidationError, PluginError) as exc:
        print(f"viscocontact {args.command}: error: {_one_line(exc)}", file=sys.stderr)
    except tomllib.TOMLDecodeError as exc:
        print(f"viscocontact {args.command}: error: invalid TOML in "
              f"{getattr(args, 'scene', '?')}: {_one_line(exc)}", file=sys.stderr)
    except FileNotFoundError as exc:
        print(f"viscocontact {args.command}: error: no such file: {exc.filename}", file=sys.stderr)
    except (IsADirectoryError, PermissionError, UnicodeDecodeError) as exc:
        print(f"viscocontact {args.command}: error: cannot read "
              f"{getattr(args, 'scene', '?')}: {_one_line(exc)}", file=sys.stderr)
    return EXIT_USAGE


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
