r"""The benchmark harness behind ``viscocontact bench``.

A fixed list of scenes — the sinusoid ``Sinusoid(amplitude=0.1)`` and the thesis's rough profile
``SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=0)``, adhesionless and adhesive
(``EnergyBalance(gamma=0.05 Λ̃²)``), on ``StandardLinearSolid(beta=10)`` at ζ from 0 (elastic) to
1e2 — is solved by every nonlinear solver (Newton, Broyden, nonlinear CG, and bisection on the
adhesionless scenes) at several mesh resolutions ``Discretization(elements=n)``, and, on the
adhesionless scenes, by the uniform-grid FFT peer of the suite folder (``peer_fft.py``:
Polonsky-Keer CG on the symmetric elastic operator, and the primal-dual active set with
preconditioned GMRES on every operator) at several grid sizes, side by side in one run.

For each run: wall time (median of ``repeats``; a run past the time budget is reported as a
timeout, not repeated) and the errors of ``Ã`` and ``μ`` against the reference of its scene. The
reference is the converged BEM result on the finest mesh (the first converged solver in the order
Newton, Bisection, Broyden, nonlinear CG), replaced by the Richardson extrapolation of the two finest
meshes when the three finest give an observed order ``p = log2(|a1 - a2|/|a2 - a3|)`` in [0.5, 4];
the table says which. ``Ã`` errors are relative; ``μ`` errors are relative to
``max(|μ_ref|, 1e-3 √m2)`` (μ vanishes on an elastic solid).

Outputs (each written to a temporary file, then moved in place): ``bench.csv`` (one row per run),
``bench.md`` (the same as a table, with references) and ``bench.png`` (time against error, the
Pareto front of each solver drawn as a line).
"""
from __future__ import annotations

import argparse
import csv
import importlib.util
import io
import math
import statistics
import sys
import time
from pathlib import Path
from typing import Any

import attrs
import numpy as np

from .._files import write_atomic
from .._outputs import check_folder
from ..data import bench_suite
from ..errors import TimeLimitExceeded, ValidationError
from ..methods.bem import BEM

BETA = 10.0
PEER_FILE = "peer_fft.py"
SOLVER_NAMES = ("newton", "broyden", "ncg", "bisection")
FIELDS = ("case", "method", "resolution", "status", "seconds", "area", "friction",
          "penetration", "err_area", "err_friction", "iterations", "n_contacts", "note")


@attrs.frozen(kw_only=True)
class Case:
    """One benchmark scene (dimensionless, load control)."""

    name: str
    profile: str            # "sinusoid" or "rough"
    zeta: float
    mean_pressure: float
    adhesive: bool = False

    def components(self):
        """``(profile, rheology, adhesion)`` of the scene."""
        from ..adhesion import EnergyBalance, NoAdhesion
        from ..contact.fields import NormalizedProfile
        from ..profiles import SelfAffineProfile, Sinusoid
        from ..rheology import Elastic, StandardLinearSolid

        prof = (Sinusoid(amplitude=0.1) if self.profile == "sinusoid"
                else SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=0))
        rheology = StandardLinearSolid(beta=BETA) if self.zeta > 0 else Elastic()
        if self.adhesive:
            lam = NormalizedProfile.of(prof).amplitude
            adhesion = EnergyBalance(gamma=0.05 * lam ** 2)
        else:
            adhesion = NoAdhesion()
        return prof, rheology, adhesion


def _cases() -> tuple[Case, ...]:
    out = []
    for profile, load in (("sinusoid", 0.3), ("rough", 0.1)):
        for adhesive in (False, True):
            for zeta in (0.0, 1e-2, 1.0, 1e2):
                tag = "adh" if adhesive else "noadh"
                out.append(Case(name=f"{profile}-{tag}-z{zeta:g}", profile=profile, zeta=zeta,
                                mean_pressure=load, adhesive=adhesive))
    return tuple(out)


CASES = _cases()


@attrs.frozen(kw_only=True)
class Plan:
    """What one benchmark run does."""

    cases: tuple
    solvers: tuple
    elements: tuple
    points: tuple
    repeats: int
    budget: float


QUICK = Plan(cases=("sinusoid-noadh-z1", "rough-noadh-z0", "rough-noadh-z1"),
             solvers=("newton", "bisection"), elements=(32, 64, 128),
             points=(1024, 4096, 16384), repeats=1, budget=20.0)
FULL = Plan(cases=tuple(c.name for c in CASES), solvers=SOLVER_NAMES,
            elements=(16, 32, 64, 128), points=(512, 2048, 8192, 32768), repeats=3, budget=60.0)


# ---- running one solve under a time budget ----------------------------------------------------
def time_limit(seconds):
    """The cooperative :func:`~viscocontact.deadline.deadline` of ``seconds``: a solve past it
    raises :class:`~viscocontact.errors.TimeLimitExceeded` at its next residual evaluation."""
    from ..deadline import deadline

    return deadline(seconds or None)


def _solver(name: str):
    from ..solvers import Bisection, Broyden, Newton, NonlinearCG

    return {"newton": Newton, "broyden": Broyden, "ncg": NonlinearCG, "bisection": Bisection}[name]()


def _timed(fn, repeats: int, budget: float) -> dict:
    """Median wall time of ``fn()`` over ``repeats`` (stops repeating after a failure)."""
    times: list[float] = []
    out: Any = None
    for _ in range(repeats):
        started = time.perf_counter()
        try:
            with time_limit(budget):
                out = fn()
        except TimeLimitExceeded:
            return {"status": "timeout", "seconds": time.perf_counter() - started,
                    "note": f"over the {budget:g} s budget"}
        except Exception as exc:  # a solver error is a benchmark outcome, not a crash
            return {"status": "error", "seconds": time.perf_counter() - started,
                    "note": " ".join(f"{type(exc).__name__}: {exc}".split())[:120]}
        times.append(time.perf_counter() - started)
        if not out["converged"]:
            break
    out = dict(out)
    out["seconds"] = statistics.median(times)
    out["status"] = "converged" if out.pop("converged") else "not_converged"
    return out


def bem_run(case: Case, solver: str, elements: int, repeats: int, budget: float) -> dict:
    """One BEM solve of ``case`` (viscocontact.problem.ContactProblem)."""
    from .._blas import single_blas_thread
    from ..problem import ContactProblem, Discretization

    prof, rheology, adhesion = case.components()
    problem = ContactProblem(method=BEM(), profile=prof, rheology=rheology, adhesion=adhesion,
                             solver=_solver(solver), mean_pressure=case.mean_pressure,
                             zeta=case.zeta, discretization=Discretization(elements=elements))

    def once():
        with single_blas_thread():
            r = problem.solve()
        return {"converged": bool(r.converged), "area": r.area, "friction": r.friction,
                "penetration": r.penetration, "iterations": r.iterations,
                "n_contacts": r.n_contacts, "note": "" if r.converged else r.message[:120]}

    return _timed(once, repeats, budget)


def load_peer(suite: Path):
    """The ``peer_fft`` module of the suite folder."""
    path = Path(suite) / PEER_FILE
    if not path.is_file():
        raise ValidationError("--suite", str(suite), f"a folder that contains {PEER_FILE} "
                              "(the benchmarks/ folder of the source tree)")
    spec = importlib.util.spec_from_file_location("viscocontact_bench_peer_fft", path)
    if spec is None or spec.loader is None:
        raise ImportError(f"cannot load {path} as a module")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def peer_run(peer, case: Case, points: int, repeats: int, budget: float,
             method: str = "auto") -> dict:
    """One FFT-peer solve of ``case`` on ``points`` uniform cells (``method`` of peer.solve)."""
    prof, rheology, _ = case.components()

    def once():
        r = peer.solve(prof, case.mean_pressure, points, rheology=rheology, zeta=case.zeta,
                       method=method)
        return {"converged": r.converged, "area": r.area, "friction": r.friction,
                "penetration": r.penetration, "iterations": r.iterations,
                "n_contacts": r.n_contacts, "method": f"fft-{r.method}",
                "note": "" if r.converged else r.message}

    return _timed(once, repeats, budget)


# ---- references and errors --------------------------------------------------------------------
def reference(rows: list[dict], floors: dict | None = None) -> dict:
    """Reference ``Ã`` and ``μ`` of one case from its BEM rows (see the module docstring).

    ``floors`` gives, per quantity, the size below which differences between meshes are noise
    (no Richardson extrapolation then).
    """
    floors = floors or {}
    order = {name: i for i, name in enumerate(("newton", "bisection", "broyden", "ncg"))}
    by_mesh: dict[Any, dict] = {}
    for row in sorted(rows, key=lambda r: order.get(r["method"], 9)):
        if row["status"] == "converged" and not row["method"].startswith("fft"):
            by_mesh.setdefault(row["resolution"], row)
    if not by_mesh:
        return {"area": math.nan, "friction": math.nan, "kind": "none (no converged BEM run)"}
    meshes = sorted(by_mesh)
    out, kinds = {}, []
    for key in ("area", "friction"):
        values = [by_mesh[m][key] for m in meshes]
        out[key] = values[-1]
        kind = f"{key}: finest mesh ({meshes[-1]} elements)"
        if len(meshes) >= 3 and meshes[-1] == 2 * meshes[-2] == 4 * meshes[-3]:
            a1, a2, a3 = values[-3:]
            noise = 1e-9 * max(abs(a3), floors.get(key, 0.0))
            if abs(a2 - a3) > noise and abs(a1 - a2) > noise:
                p = math.log2(abs(a1 - a2) / abs(a2 - a3))
                if 0.5 <= p <= 4.0:
                    out[key] = a3 + (a3 - a2) / (2.0 ** p - 1.0)
                    kind = (f"{key}: Richardson from {meshes[-2]}/{meshes[-1]} elements "
                            f"(observed order {p:.2g})")
        kinds.append(kind)
    out["kind"] = "; ".join(kinds)
    return out


def add_errors(rows: list[dict], ref: dict, mu_floor: float) -> None:
    """Fill ``err_area`` and ``err_friction`` of ``rows`` in place."""
    for row in rows:
        ok = row["status"] == "converged"
        row["err_area"] = (abs(row["area"] - ref["area"]) / abs(ref["area"])
                           if ok and ref["area"] else math.nan)
        row["err_friction"] = (abs(row["friction"] - ref["friction"])
                               / max(abs(ref["friction"]), mu_floor) if ok else math.nan)


# ---- the whole run ----------------------------------------------------------------------------
def run_plan(plan: Plan, suite: Path, log=lambda message: None) -> tuple[list[dict], dict]:
    """All rows and the reference of every case."""
    peer = load_peer(suite)
    known = {c.name: c for c in CASES}
    rows, refs = [], {}
    for name in plan.cases:
        case = known[name]
        prof, _, _ = case.components()
        case_rows = []
        for solver in plan.solvers:
            if solver == "bisection" and case.adhesive:
                continue
            for n in plan.elements:
                row = bem_run(case, solver, n, plan.repeats, plan.budget)
                row.update(case=name, method=solver, resolution=n)
                log(f"{name} {solver} {n}: {row['status']} {row['seconds']:.2f}s")
                case_rows.append(row)
        # the peer: PK on the symmetric (elastic) operator, and PDAS + GMRES, which also
        # solves it and is the faster of the two on fine grids; PDAS alone when ζ > 0
        methods = ("pk", "pdas") if case.zeta == 0 else ("pdas",)
        for method in methods if not case.adhesive else ():
            for n in plan.points:
                row = peer_run(peer, case, n, plan.repeats, plan.budget, method)
                row["method"] = f"fft-{method}"
                row.update(case=name, resolution=n)
                log(f"{name} {row['method']} {n}: {row['status']} {row['seconds']:.2f}s")
                case_rows.append(row)
        mu_floor = 1e-3 * math.sqrt(float(prof.statistics().m2))
        refs[name] = reference(case_rows, {"friction": mu_floor})
        add_errors(case_rows, refs[name], mu_floor)
        rows += case_rows
    return rows, refs


def _fmt(value) -> str:
    if isinstance(value, float):
        return "nan" if math.isnan(value) else f"{value:.4g}"
    return str(value)


def table_csv(rows: list[dict]) -> str:
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=FIELDS, extrasaction="ignore", lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow({k: _fmt(row.get(k, "")) for k in FIELDS})
    return buf.getvalue()


def table_markdown(rows: list[dict], refs: dict, plan: Plan) -> str:
    lines = ["# viscocontact bench", "",
             f"Median wall time of {plan.repeats} repeat(s), budget {plan.budget:g} s per solve; "
             "`resolution` is elements per contact (BEM) or grid cells (fft-*). "
             "Errors: Ã relative, μ relative to max(|μ_ref|, 1e-3 √m2). Where the reference is "
             "the finest mesh, the BEM runs on that mesh differ from it only by the solver "
             "tolerance: their error is not measured (the change from the next coarser mesh "
             "bounds it).", ""]
    for name, ref in refs.items():
        lines.append(f"- **{name}**: reference Ã = {_fmt(ref['area'])}, μ = "
                     f"{_fmt(ref['friction'])} — {ref['kind']}")
    cols = [c for c in FIELDS if c != "note"]
    lines += ["", "| " + " | ".join(cols) + " |", "|" + "---|" * len(cols)]
    for row in rows:
        lines.append("| " + " | ".join(_fmt(row.get(c, "")) for c in cols) + " |")
    for key, label in (("err_area", "Ã"), ("err_friction", "μ")):
        lines += ["", f"Fastest run of each method whose error of {label} is within the target, "
                  "and stays within it on every finer resolution (ratio > 1: the FFT peer is "
                  "faster; — : no run of the method reaches it):", ""] + matched(rows, key)
    notes = [f"- {r['case']} {r['method']} {r['resolution']}: {r['note']}" for r in rows
             if r.get("note")]
    if notes:
        lines += ["", "Notes:", ""] + notes
    return "\n".join(lines) + "\n"


def pareto(points: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """The points (time, error) not beaten in both by another, sorted by time."""
    front, best = [], math.inf
    for t, e in sorted(points):
        if e < best:
            front.append((t, e))
            best = e
    return front


def plot(rows: list[dict], path: Path) -> None:
    """Time against error, one row of panels (Ã, μ) per case, Pareto fronts as lines.

    A run whose error is exactly 0 is the reference itself and is left out.
    """
    from ..plots import pyplot_free as plt    # outside pyplot: the caller's backend stays

    cases = list(dict.fromkeys(r["case"] for r in rows))
    methods = sorted({r["method"] for r in rows})
    colours = dict(zip(methods, plt.rcParams["axes.prop_cycle"].by_key()["color"] * 3))
    fig, axes = plt.subplots(len(cases), 2, figsize=(11, 3.6 * len(cases)), squeeze=False,
                             constrained_layout=True)
    for row_axes, case in zip(axes, cases):
        for ax, key, label in ((row_axes[0], "err_area", "relative error of Ã"),
                               (row_axes[1], "err_friction", "error of μ")):
            for m in methods:
                pts = [(r["seconds"], r[key]) for r in rows
                       if r["case"] == case and r["method"] == m and r["status"] == "converged"
                       and np.isfinite(r[key]) and r[key] > 0]
                if not pts:
                    continue
                ax.scatter(*zip(*pts), s=14, color=colours[m], alpha=0.6)
                ax.plot(*zip(*pareto(pts)), "-o", ms=3, color=colours[m], label=m)
            ax.set(xscale="log", yscale="log", xlabel="wall time [s]", ylabel=label, title=case)
            ax.grid(True, which="both", alpha=0.3)
        row_axes[0].legend(fontsize=8)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=100)
    plt.close(fig)
    write_atomic(path, buf.getvalue())


def matched(rows: list[dict], key: str, targets=(1e-2, 1e-3, 1e-4)) -> list[str]:
    """Markdown lines: per case and target, the fastest run of each method that meets the target
    reliably — it and every finer run of the same method do (the uniform grid's sub-cell area
    error is not monotone in N, and a lucky coarse grid is not an accuracy one can count on)."""
    lines = []
    cases = list(dict.fromkeys(r["case"] for r in rows))
    methods = list(dict.fromkeys(r["method"] for r in rows))
    head = "| case | target | " + " | ".join(methods) + " | fastest BEM / fastest FFT |"
    lines += [head, "|" + "---|" * (len(methods) + 3)]
    for case in cases:
        for target in targets:
            best = {}
            for m in methods:
                runs = sorted((r for r in rows if r["case"] == case and r["method"] == m),
                              key=lambda r: r["resolution"])
                good = [r["status"] == "converged" and np.isfinite(r[key]) and r[key] <= target
                        for r in runs]
                ok = [r["seconds"] for i, r in enumerate(runs) if all(good[i:])]
                best[m] = min(ok) if ok else math.nan
            bem = [v for m, v in best.items() if not m.startswith("fft") and np.isfinite(v)]
            fft = [v for m, v in best.items() if m.startswith("fft") and np.isfinite(v)]
            ratio = f"{min(bem) / min(fft):.3g}" if bem and fft else "—"
            cells = " | ".join("—" if math.isnan(best[m]) else f"{best[m]:.3g} s" for m in methods)
            lines.append(f"| {case} | {target:g} | {cells} | {ratio} |")
    return lines


# ---- command line -----------------------------------------------------------------------------
def _int_list(option):
    def parse(text):
        try:
            values = tuple(int(v) for v in text.split(","))
        except ValueError:
            raise argparse.ArgumentTypeError(f"{option} = {text!r} is not allowed: expected "
                                              "comma-separated integers") from None
        return values
    return parse


def configure_parser(parser: argparse.ArgumentParser) -> None:
    """The options of ``viscocontact bench``."""
    parser.add_argument("--quick", action="store_true",
                        help="three adhesionless scenes, Newton and bisection (about a minute)")
    parser.add_argument("--out", default="bench-results", help="output folder (default: %(default)s)")
    parser.add_argument("--suite", default=None,
                        help="folder holding peer_fft.py (default: ./benchmarks in a source "
                             "tree, else the copy shipped with the package)")
    parser.add_argument("--repeats", type=int, default=None,
                        help="timed repeats per run, median reported (default 1 quick, 3 full)")
    parser.add_argument("--budget", type=float, default=None,
                        help="seconds allowed per solve (default 20 quick, 60 full)")
    parser.add_argument("--cases", default=None,
                        help="comma-separated case names (default: the plan's); see --list")
    parser.add_argument("--solvers", default=None,
                        help=f"comma-separated subset of {','.join(SOLVER_NAMES)}")
    parser.add_argument("--elements", type=_int_list("--elements"), default=None,
                        help="BEM elements per contact, e.g. 16,32,64")
    parser.add_argument("--points", type=_int_list("--points"), default=None,
                        help="FFT peer grid sizes, e.g. 1024,4096")
    parser.add_argument("--list", action="store_true", help="print the case names and exit")
    parser.add_argument("--spectral", action="store_true",
                        help="only the spectral method at its default tolerance against the peer "
                             f"at {PEER_CELLS} cells on the thesis's rough profiles, side by side "
                             "(ratio of times, differences of Ã and μ; writes spectral.md)")
    parser.add_argument("--seeds", type=_int_list("--seeds"), default=None,
                        help="profile seeds of --spectral (default 0,1,2,3,4)")


def plan_from_args(args: argparse.Namespace) -> Plan:
    """The plan of the command line, every option checked (ValidationError names it)."""
    base = QUICK if args.quick else FULL
    known = [c.name for c in CASES]
    cases = base.cases if args.cases is None else tuple(s.strip() for s in args.cases.split(","))
    for c in cases:
        if c not in known:
            raise ValidationError("--cases", c, f"one of {known}")
    solvers = (base.solvers if args.solvers is None
               else tuple(s.strip() for s in args.solvers.split(",")))
    for s in solvers:
        if s not in SOLVER_NAMES:
            raise ValidationError("--solvers", s, f"one of {list(SOLVER_NAMES)}")
    repeats = base.repeats if args.repeats is None else args.repeats
    if repeats < 1 or repeats > 100:
        raise ValidationError("--repeats", repeats, "an integer in [1, 100]")
    budget = base.budget if args.budget is None else args.budget
    if not (math.isfinite(budget) and 0 < budget <= 3600):
        raise ValidationError("--budget", budget, "a number of seconds in (0, 3600]")
    elements = base.elements if args.elements is None else args.elements
    if any(not 8 <= n <= 4096 for n in elements):
        raise ValidationError("--elements", list(elements), "integers in [8, 4096]")
    points = base.points if args.points is None else args.points
    if any(n < 16 or n % 2 or n > 1 << 22 for n in points):
        raise ValidationError("--points", list(points), "even integers in [16, 4194304]")
    return Plan(cases=cases, solvers=solvers, elements=tuple(sorted(elements)),
                points=tuple(sorted(points)), repeats=repeats, budget=budget)


def run(args: argparse.Namespace) -> int:
    """Benchmark the nonlinear solvers and mesh sizes against the uniform-grid FFT peer."""
    if args.list:
        for c in CASES:
            print(c.name)
        return 0
    if args.spectral:
        return run_spectral(args)
    plan = plan_from_args(args)
    suite = bench_suite(args.suite)
    if not suite.is_dir():
        raise ValidationError("--suite", str(suite), "an existing folder that contains "
                              f"{PEER_FILE}")
    load_peer(suite)                              # fail before any solve
    out = check_folder("--out", args.out, "an output folder")
    out.mkdir(parents=True, exist_ok=True)
    rows, refs = run_plan(plan, suite, log=lambda m: print(m, file=sys.stderr))
    write_atomic(out / "bench.csv", table_csv(rows).encode())
    write_atomic(out / "bench.md", table_markdown(rows, refs, plan).encode())
    plot(rows, out / "bench.png")
    for name in ("bench.md", "bench.csv", "bench.png"):
        print(f"wrote {out / name}")
    return 0


#: Grid of the peer in the spectral comparison, and the scene family of that comparison.
PEER_CELLS = 8192
SPECTRAL_LOAD = 0.25
SPECTRAL_RHEOLOGIES = (("elastic", None, 0.0), ("SLS β = 10, ζ = 1e-2", BETA, 1e-2))


def spectral_side_by_side(peer, seeds, repeats: int, log=lambda message: None) -> list[dict]:
    """The spectral method (default tolerance, from scratch) and the peer at
    :data:`PEER_CELLS` cells (operator and nested grids included) on
    ``SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=s)`` at p̃∞ = 0.25, elastic and
    on the standard linear solid β = 10 at ζ = 1e-2, run in turn in this process; one row per
    (rheology, seed) with both median times, their ratio and the differences of Ã and μ."""
    from .._blas import single_blas_thread
    from ..methods.spectral import Spectral
    from ..problem import ContactProblem
    from ..profiles import SelfAffineProfile
    from ..rheology import Elastic, StandardLinearSolid
    from ..solvers import Bisection

    rows = []
    for label, beta, zeta in SPECTRAL_RHEOLOGIES:
        rheology = Elastic() if beta is None else StandardLinearSolid(beta=beta)
        for seed in seeds:
            profile = SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=seed)
            problem = ContactProblem(profile=profile, rheology=rheology, solver=Bisection(),
                                     mean_pressure=SPECTRAL_LOAD, zeta=zeta, method=Spectral())
            ours, theirs = [], []
            with single_blas_thread():
                for _ in range(repeats):                 # alternating: the same machine load
                    t = time.perf_counter()
                    mine = problem.solve()
                    ours.append(time.perf_counter() - t)
                    t = time.perf_counter()
                    other = peer.solve(profile, SPECTRAL_LOAD, PEER_CELLS, rheology=rheology,
                                       zeta=zeta)
                    theirs.append(time.perf_counter() - t)
            scale = max(abs(other.friction), 1e-2 * math.sqrt(profile.statistics().m2))
            row = dict(rheology=label, seed=seed, spectral=statistics.median(ours),
                       peer=statistics.median(theirs), points=mine.extras.get("points"),
                       area=mine.area, peer_area=other.area,
                       d_area=mine.area / other.area - 1.0,
                       d_friction=(mine.friction - other.friction) / scale,
                       estimate=mine.error_estimate, converged=mine.converged and other.converged)
            row["ratio"] = row["spectral"] / row["peer"]
            rows.append(row)
            log(f"{label} seed {seed}: spectral {row['spectral']:.3f} s, peer "
                f"{row['peer']:.3f} s, ratio {row['ratio']:.2f}, dÃ {row['d_area']:+.1e}")
    return rows


def spectral_markdown(rows: list[dict], repeats: int) -> str:
    """The side-by-side table and the ratio of the medians per rheology."""
    head = ("| rheology | seed | spectral (s) | grid | peer 8192 (s) | ratio | Ã | "
            "Ã peer | ΔÃ/Ã | Δμ | estimate |")
    lines = [f"Spectral method at its default tolerance against the FFT peer at {PEER_CELLS} "
             f"cells, p̃∞ = {SPECTRAL_LOAD}, median of {repeats} alternating runs per seed.", "",
             head, "|" + "---|" * 11]
    for r in rows:
        lines.append(f"| {r['rheology']} | {r['seed']} | {r['spectral']:.3f} | {r['points']} | "
                     f"{r['peer']:.3f} | {r['ratio']:.2f} | {r['area']:.6f} | "
                     f"{r['peer_area']:.6f} | {r['d_area']:+.1e} | {r['d_friction']:+.1e} | "
                     f"{r['estimate']:.1e} |")
    lines.append("")
    for label, _, _ in SPECTRAL_RHEOLOGIES:
        sel = [r for r in rows if r["rheology"] == label]
        if sel:
            med_s = statistics.median(r["spectral"] for r in sel)
            med_p = statistics.median(r["peer"] for r in sel)
            lines.append(f"* {label}: median spectral {med_s:.3f} s, median peer {med_p:.3f} s, "
                         f"ratio of the medians {med_s / med_p:.2f} (below 1: the spectral method "
                         "is faster).")
    return "\n".join(lines) + "\n"


def run_spectral(args: argparse.Namespace) -> int:
    """``viscocontact bench --spectral``: the spectral method against the peer."""
    suite = bench_suite(args.suite)
    peer = load_peer(suite)
    out = check_folder("--out", args.out, "an output folder")
    repeats = 3 if args.repeats is None else args.repeats
    if repeats < 1 or repeats > 100:
        raise ValidationError("--repeats", repeats, "an integer in [1, 100]")
    seeds = args.seeds or (0, 1, 2, 3, 4)
    rows = spectral_side_by_side(peer, seeds, repeats, log=lambda m: print(m, file=sys.stderr))
    out.mkdir(parents=True, exist_ok=True)
    text = spectral_markdown(rows, repeats)
    write_atomic(out / "spectral.md", text.encode())
    print(text)
    print(f"wrote {out / 'spectral.md'}")
    return 0


def main(argv=None) -> int:
    """``python -m viscocontact.reports.bench [options]`` (same as ``viscocontact bench``)."""
    parser = argparse.ArgumentParser(prog="viscocontact bench", description=__doc__.splitlines()[0])
    configure_parser(parser)
    return run(parser.parse_args(argv))


if __name__ == "__main__":
    sys.exit(main())
