r"""The validation report: the BEM against closed forms and the classical theories.

``viscocontact validate [--quick] [--out docs] [--workers N]`` solves every case,
writes ``<out>/validation.md`` and ``<out>/figures/validation_*.png`` (each file atomically:
a temporary file, then :func:`os.replace`). Every number in the markdown is computed here; the
only quoted number is the thesis's "factor 1/2" (§3.4), which the report checks.

The report has six sections:

1. the BEM in its elastic limits against Westergaard and Johnson (errors at the default mesh);
2. mesh convergence against elements per contact, with the observed order;
3. the elastic rough contact area against load for the thesis's profile family
   (``SelfAffineProfile(hurst=0.8, scales=50, rms=0.01, seed=s)``), against Persson's area for line
   roughness, Greenwood-Williamson, simplified BGT and the height-dependent curvature model;
4. adhesionless viscoelastic friction against speed ζ (standard linear solid, β = 10), sinusoid and
   rough, against Persson's mean-field friction;
5. the elastic limits of the viscoelastic solver (ζ → 0 with E0, ζ → ∞ with E∞ = β E0);
6. a comparison of the models' assumptions after the thesis's Table 4.1, with the disagreement
   measured in sections 1-5.

The solves are independent tasks on a process pool (``--workers``, default 2), each with
single-threaded BLAS and a wall-time limit (a solve that reaches it is reported as failed). The
rough viscoelastic solves follow ζ downwards from the fast, stiff end and the rough elastic ones
follow the load upwards, each continued from the previous contact set.
"""
from __future__ import annotations

import argparse
import collections
import math
import multiprocessing
import os
import sys
import tempfile
import time
from concurrent.futures import Future, ProcessPoolExecutor
from pathlib import Path

import attrs
import numpy as np

from .._files import publish

#: Thesis §3.4 (after Carbone et al. 2009): for 1D roughness Persson's theory gives about half the
#: BEM contact area. The report measures ``A_Persson/A_BEM`` and sets it beside this.
THESIS_PERSSON_RATIO = 0.5

SINUSOID_AMPLITUDE = 0.1          # Λ̃ of the wavy cases (results in p̃ units do not depend on it)
BETA = 10.0                       # E∞/E0 of the standard linear solid
HURST, SCALES, RMS = 0.8, 50, 0.01


# ---------------------------------------------------------------------------------------------
# What to solve
# ---------------------------------------------------------------------------------------------
@attrs.frozen(kw_only=True)
class Plan:
    """The cases of one report (:data:`FULL` or :data:`QUICK`)."""

    name: str
    elements: int = 64
    westergaard_loads: tuple = (0.05, 0.3, 0.7, 0.95)
    johnson_cases: tuple = ((0.01, 0.1), (0.01, 0.0), (0.05, -0.02), (0.05, 0.1))
    johnson_limit_cases: tuple = ((0.01, 0.1), (0.01, 0.0), (0.05, -0.02), (0.05, 0.1))
    mesh_elements: tuple = (16, 32, 64, 128, 256)
    mesh_finite_advance: bool = True
    rough_seeds: tuple = tuple(range(20))
    rough_loads: tuple = (0.01, 0.02, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4)
    rough_elements: int = 32
    #: relative accuracy asked of the planned method (``[method] kind = "auto"``) on the rough
    #: adhesionless solves; the accuracy check solves seeds ``mesh_check_seeds`` again at a tenth
    rough_tolerance: float = 1e-3
    mesh_check_seeds: tuple = (0, 1)
    small_load: float = 0.1
    friction_loads: tuple = (0.1, 0.3)
    friction_zetas: tuple = tuple(float(z) for z in 10.0 ** np.arange(-3.0, 3.01, 0.25))
    rough_friction_seeds: tuple = (0, 1)
    rough_friction_zetas: tuple = (100.0, 10.0, 1.0, 0.3, 0.1, 0.01)
    rough_friction_load: float = 0.3
    limit_zetas: tuple = (1e-8, 1e-6, 1e6, 1e8)
    limit_gamma: float = 0.005
    limit_load: float = 0.1
    rough_limit_zetas: tuple = (1e-6, 1e6)
    rough_limit_load: float = 0.1
    time_limit: float = 180.0          # seconds per solve; a slower one is reported as failed


FULL = Plan(name="full")
QUICK = Plan(
    name="quick", johnson_cases=((0.01, 0.1),), mesh_elements=(16, 32, 64, 128),
    mesh_finite_advance=False, rough_seeds=(0, 1), rough_loads=(0.02, 0.05, 0.1),
    mesh_check_seeds=(), friction_loads=(0.1,),
    friction_zetas=(0.01, 0.1, 0.3, 1.0, 3.0, 10.0, 100.0),
    rough_friction_seeds=(0,), rough_friction_zetas=(100.0, 10.0), limit_zetas=(1e-8, 1e8),
    rough_limit_zetas=(1e6,), time_limit=30.0)


# ---------------------------------------------------------------------------------------------
# Tasks (top level, so that a process pool can run them); each returns plain dictionaries
# ---------------------------------------------------------------------------------------------
def time_limit(seconds):
    """The cooperative :func:`~viscocontact.deadline.deadline` of ``seconds`` (0 or None: no
    limit): a solve that runs past it raises :class:`~viscocontact.errors.TimeLimitExceeded`
    at its next residual evaluation, in any thread or worker, and is reported as failed."""
    from ..deadline import deadline

    return deadline(seconds or None)


def _profile(seed):
    from ..profiles import SelfAffineProfile

    return SelfAffineProfile(hurst=HURST, scales=SCALES, rms=RMS, seed=seed)


def _row(result, started) -> dict:
    return dict(area=result.area, mean_pressure=result.mean_pressure,
                penetration=result.penetration, friction=result.friction,
                reduced_friction=result.reduced_friction, n_contacts=result.n_contacts,
                converged=bool(result.converged), min_gap=result.min_gap,
                seconds=time.perf_counter() - started, error=None, method=result.method)


def _failure(error, started) -> dict:
    return dict(area=np.nan, mean_pressure=np.nan, penetration=np.nan, friction=np.nan,
                reduced_friction=np.nan, n_contacts=0, converged=False, min_gap=np.nan,
                seconds=time.perf_counter() - started,
                error=f"{type(error).__name__}: {error}".splitlines()[0][:200], method="")


def _guarded(problem, limit, initial=None):
    """``(result or None, row)``: one solve with single-threaded BLAS under the time limit;
    errors become failed rows (reported in the markdown, never hidden)."""
    from .._blas import single_blas_thread

    started = time.perf_counter()
    try:
        with time_limit(limit), single_blas_thread():
            result = problem.solve(initial=initial)
    except Exception as error:    # TimeLimitExceeded included
        return None, _failure(error, started)
    return result, _row(result, started)


def _problem(profile, *, rheology=None, solver=None, gamma=None, edge_perturbation=None,
             discretization=None, tolerance=None, **kw):
    """A problem of the report; ``tolerance``: solved by the planned method (``auto``) at that
    accuracy, as a scene without ``[method]`` is; otherwise by the BEM."""
    from ..adhesion import EnergyBalance
    from ..problem import ContactProblem, Discretization
    from ..rheology import Elastic
    from ..solvers import Newton

    extra = {}
    if gamma is not None:
        adh = {"gamma": gamma}
        if edge_perturbation is not None:
            adh["edge_perturbation"] = edge_perturbation
        extra["adhesion"] = EnergyBalance(**adh)
    if tolerance is not None:
        from ..methods.auto import Auto

        extra["method"] = Auto(tolerance=tolerance)
    else:
        from ..methods.bem import BEM

        extra["method"] = BEM()
    return ContactProblem(profile=profile, rheology=rheology or Elastic(),
                          solver=solver or Newton(),
                          discretization=discretization or Discretization(), **extra, **kw)


def task_sinusoid(*, mean_pressure, limit, elements=64, zeta=0.0, viscoelastic=False,
                  gamma=None, edge_perturbation=None, edge_zones=True) -> dict:
    """One wavy contact (Newton): elastic, or the standard linear solid at speed ζ."""
    from ..problem import Discretization
    from ..profiles import Sinusoid
    from ..rheology import StandardLinearSolid

    disc = Discretization(elements=elements) if edge_zones else Discretization(
        elements=elements, edge_resolution=None)
    rheology = StandardLinearSolid(beta=BETA) if viscoelastic else None
    return _guarded(_problem(Sinusoid(amplitude=SINUSOID_AMPLITUDE), rheology=rheology,
                             mean_pressure=mean_pressure, zeta=zeta, gamma=gamma,
                             edge_perturbation=edge_perturbation, discretization=disc),
                    limit)[1]


def _path(base, field, values, limit) -> list:
    """Solve ``base`` with ``field`` set to each value in turn, each solve continued from the
    last converged contact set; one that fails to converge (within the time limit) is retried
    once from first touch (``row["retried"]``)."""
    rows, previous = [], None
    for v in values:
        problem = attrs.evolve(base, **{field: v})
        result, row = _guarded(problem, limit, initial=previous)
        retried = (previous is not None and not row["converged"]
                   and not (row["error"] or "").startswith("TimeLimitExceeded"))
        if retried:
            spent = row["seconds"]
            result, row = _guarded(problem, limit)
            row["seconds"] += spent
        row["retried"] = retried
        rows.append(row)
        if result is not None and result.converged:
            previous = result
    return rows


def task_rough_load_path(*, seed, loads, elements, limit, tolerance=None) -> list:
    """Elastic adhesionless rough contact along increasing load (the planned method at
    ``tolerance``; the BEM with bisection when it runs)."""
    from ..problem import Discretization
    from ..solvers import Bisection

    base = _problem(_profile(seed), solver=Bisection(), mean_pressure=loads[0],
                    discretization=Discretization(elements=elements), tolerance=tolerance)
    return _path(base, "mean_pressure", loads, limit)


def task_rough_zeta_path(*, seed, zetas, mean_pressure, elements, limit, tolerance=None) -> list:
    """Adhesionless rough contact on the standard linear solid along ζ (the planned method)."""
    from ..problem import Discretization
    from ..rheology import StandardLinearSolid
    from ..solvers import Bisection

    base = _problem(_profile(seed), rheology=StandardLinearSolid(beta=BETA), solver=Bisection(),
                    mean_pressure=mean_pressure, discretization=Discretization(elements=elements),
                    tolerance=tolerance)
    return _path(base, "zeta", zetas, limit)


def task_rough(*, seed, mean_pressure, elements, limit, zeta=0.0, viscoelastic=False,
               tolerance=None) -> dict:
    """One rough adhesionless solve (the planned method; the BEM from first touch with the mesh
    of eq. 4.22 alone when it runs), for the limit cases."""
    from ..problem import Discretization
    from ..rheology import StandardLinearSolid
    from ..solvers import Bisection

    rheology = StandardLinearSolid(beta=BETA) if viscoelastic else None
    return _guarded(_problem(_profile(seed), rheology=rheology, solver=Bisection(),
                             mean_pressure=mean_pressure, zeta=zeta,
                             discretization=Discretization(elements=elements,
                                                           edge_resolution=None),
                             tolerance=tolerance), limit)[1]


class _Serial:
    """An executor that runs each task when it is submitted (``--workers 1``)."""

    def submit(self, fn, *args, **kw):
        future = Future()
        try:
            future.set_result(fn(*args, **kw))
        except Exception as error:
            future.set_exception(error)
        return future

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False


_LIMIT_KINDS = (("adhesionless", None, None), ("adhesive, default δX", 1.0, None),
                ("adhesive, δX = 0", 1.0, 0.0))


def _submit_all(plan: Plan, pool) -> dict:
    """Every task of the plan, longest first (the pool starts them in this order)."""
    f = {}

    def submit(key, fn, **kw):
        f[key] = pool.submit(fn, limit=plan.time_limit, **kw)

    wavy = dict(elements=plan.elements)
    lam2 = SINUSOID_AMPLITUDE**2
    for s in plan.rough_friction_seeds:
        submit(("rough_zeta", s), task_rough_zeta_path, seed=s, zetas=plan.rough_friction_zetas,
               mean_pressure=plan.rough_friction_load, elements=plan.rough_elements,
               tolerance=plan.rough_tolerance)
    for s in plan.mesh_check_seeds:
        submit(("rough_fine", s), task_rough_load_path, seed=s, loads=plan.rough_loads,
               elements=2 * plan.rough_elements, tolerance=plan.rough_tolerance / 10)
    for s in plan.rough_seeds:
        submit(("rough", s), task_rough_load_path, seed=s, loads=plan.rough_loads,
               elements=plan.rough_elements, tolerance=plan.rough_tolerance)
    if plan.mesh_finite_advance:
        for n in plan.mesh_elements[::-1]:
            submit(("mesh_johnson_dx", n), task_sinusoid, mean_pressure=0.0, elements=n,
                   gamma=0.05 * lam2)
    for g, p in plan.johnson_cases:
        submit(("johnson", g, p), task_sinusoid, mean_pressure=p, gamma=g * lam2, **wavy)
    for z in plan.rough_limit_zetas:
        submit(("rough_limit", z), task_rough, seed=0, mean_pressure=plan.rough_limit_load,
               elements=plan.rough_elements, zeta=z, viscoelastic=True,
               tolerance=plan.rough_tolerance)
        submit(("rough_limit_ref", z), task_rough, seed=0, elements=plan.rough_elements,
               mean_pressure=plan.rough_limit_load / (BETA if z > 1 else 1.0),
               tolerance=plan.rough_tolerance)
    for n in plan.mesh_elements[::-1]:
        submit(("mesh_westergaard", n), task_sinusoid, mean_pressure=0.3, elements=n)
        submit(("mesh_johnson", n), task_sinusoid, mean_pressure=0.0, elements=n,
               gamma=0.05 * lam2, edge_perturbation=0.0)
    for p in plan.westergaard_loads:
        submit(("westergaard", p), task_sinusoid, mean_pressure=p, **wavy)
    for g, p in plan.johnson_limit_cases:
        submit(("johnson0", g, p), task_sinusoid, mean_pressure=p, gamma=g * lam2,
               edge_perturbation=0.0, **wavy)
    for p in plan.friction_loads:
        for z in plan.friction_zetas:
            submit(("friction", p, z), task_sinusoid, mean_pressure=p, zeta=z,
                   viscoelastic=True, **wavy)
    for kind, gamma, dx in _LIMIT_KINDS:
        for z in plan.limit_zetas:
            submit(("limit", kind, z), task_sinusoid, mean_pressure=plan.limit_load, zeta=z,
                   viscoelastic=True, gamma=None if gamma is None else plan.limit_gamma * lam2,
                   edge_perturbation=dx, edge_zones=False, **wavy)
    return f


# ---------------------------------------------------------------------------------------------
# Numbers
# ---------------------------------------------------------------------------------------------
def fmt(x, digits=2, sign=False) -> str:
    """``5.4e-3`` style (no zero-padded exponent); plain for ``1e-2 <= |x| < 1e4``."""
    if x is None or not np.isfinite(x):
        return "—"
    x = float(x)
    if x == 0:
        return "0"
    if 1e-2 <= abs(x) < 1e4:
        s = f"{x:.{digits}g}"
        if "e" in s:                        # 1280 with 2 digits: keep the integer
            s = f"{x:.0f}"
    else:
        m, e = f"{x:.{digits - 1}e}".split("e")
        if "." in m:
            m = m.rstrip("0").rstrip(".")
        s = f"{m}e{int(e)}"
    return ("+" + s) if sign and x > 0 else s


def _rel(a, b):
    return float(a) / float(b) - 1.0


def observed_order(elements, errors):
    """Least-squares slope of ``-log|e|`` against ``log N``, and the pairwise orders."""
    n = np.asarray(elements, dtype=float)
    e = np.abs(np.asarray(errors, dtype=float))
    ok = e > 0
    slope = -np.polyfit(np.log(n[ok]), np.log(e[ok]), 1)[0] if ok.sum() >= 2 else np.nan
    pairs = [math.log(e[i] / e[i + 1]) / math.log(n[i + 1] / n[i]) if e[i] > 0 and e[i + 1] > 0
             else np.nan for i in range(len(e) - 1)]
    return float(slope), pairs


def _compare(value, quoted, tol=0.1) -> str:
    """How a measured ratio stands against a quoted one (absolute tolerance ``tol``)."""
    if abs(value - quoted) <= tol:
        return f"within {fmt(tol)} of"
    return "above" if value > quoted else "below"


def _stats(values):
    v = np.asarray([x for x in values if np.isfinite(x)], dtype=float)
    if v.size == 0:
        return dict(mean=np.nan, sd=np.nan, lo=np.nan, hi=np.nan, n=0)
    return dict(mean=float(v.mean()), sd=float(v.std(ddof=1)) if v.size > 1 else 0.0,
                lo=float(v.min()), hi=float(v.max()), n=int(v.size))


def _spread(s, digits=3) -> str:
    if s["n"] == 0:
        return "—"
    return (f"{fmt(s['mean'], digits)} ± {fmt(s['sd'], 2)} "
            f"({fmt(s['lo'], digits)}–{fmt(s['hi'], digits)})")


def _peak(zetas, values):
    """ζ and value of the maximum, refined by a parabola in log ζ through the three best points."""
    z = np.log10(np.asarray(zetas, dtype=float))
    v = np.asarray(values, dtype=float)
    i = int(np.nanargmax(v))
    if 0 < i < len(v) - 1:
        a, b, c = np.polyfit(z[i - 1:i + 2], v[i - 1:i + 2], 2)
        if a < 0:
            zp = -b / (2 * a)
            return float(10**zp), float(np.polyval([a, b, c], zp))
    return float(10 ** z[i]), float(v[i])


# ---------------------------------------------------------------------------------------------
# Sections: results (dictionaries of numbers) from the finished tasks
# ---------------------------------------------------------------------------------------------
def closed_forms(plan, r):
    from ..reference import JohnsonWavy, westergaard_area, westergaard_penetration

    west = []
    for p in plan.westergaard_loads:
        x = r["westergaard", p]
        ref = float(westergaard_area(p))
        west.append(dict(p=p, area=x["area"], ref=ref, error=_rel(x["area"], ref),
                         pen_error=_rel(x["penetration"], westergaard_penetration(ref)),
                         converged=x["converged"], seconds=x["seconds"]))
    john = []
    for key, table in (("johnson", plan.johnson_cases), ("johnson0", plan.johnson_limit_cases)):
        for g, p in table:
            x = r[key, g, p]
            ref = JohnsonWavy(Gamma=g).area_at_pressure(p)
            john.append(dict(kind=key, Gamma=g, p=p, area=x["area"], ref=ref,
                             error=_rel(x["area"], ref), converged=x["converged"],
                             seconds=x["seconds"]))
    return dict(westergaard=west, johnson=john)


def mesh_convergence(plan, r):
    from ..reference import JohnsonWavy, westergaard_area

    ns = list(plan.mesh_elements)
    out = {}
    ref_w = float(westergaard_area(0.3))
    ref_j = JohnsonWavy(Gamma=0.05).area_at_pressure(0.0)
    series = [("westergaard", "Westergaard, p̃∞ = 0.3", ref_w),
              ("johnson", "Johnson, Γ̃ = 0.05, p̃∞ = 0, δX = 0", ref_j)]
    for key, label, ref in series:
        errs = [_rel(r[f"mesh_{key}", n]["area"], ref) for n in ns]
        order, pairs = observed_order(ns, errs)
        out[key] = dict(label=label, elements=ns, errors=errs, order=order, pairs=pairs,
                        seconds=sum(r[f"mesh_{key}", n]["seconds"] for n in ns))
    if plan.mesh_finite_advance:
        areas = [r["mesh_johnson_dx", n]["area"] for n in ns]
        errs = [_rel(a, ref_j) for a in areas]
        self_errs = [_rel(a, areas[-1]) for a in areas[:-1]]
        order, pairs = observed_order(ns[:-1], self_errs)
        out["johnson_dx"] = dict(label="Johnson, Γ̃ = 0.05, p̃∞ = 0, default δX", elements=ns,
                                 errors=errs, self_errors=self_errs, order=order, pairs=pairs,
                                 seconds=sum(r["mesh_johnson_dx", n]["seconds"] for n in ns))
    return out


def rough_area(plan, r):
    from ..theories import (GreenwoodWilliamson, HeightCurvatureModel, PerssonContact,
                           SimplifiedBGT)

    theories = {"persson": "Persson, line form", "persson_iso": "eq. 3.45 as printed",
                "gw": "GW", "bgt": "simplified BGT", "hc": "height-curvature"}
    rows = []
    for s in plan.rough_seeds:
        prof = _profile(s)
        st = prof.statistics()
        lam, m2 = prof.amplitude, st.m2
        pc = PerssonContact.from_profile(prof)
        models = dict(gw=GreenwoodWilliamson.from_profile(prof),
                      bgt=SimplifiedBGT.from_profile(prof),
                      hc=HeightCurvatureModel.from_profile(prof))
        fine = r.get(("rough_fine", s))
        for i, (p, x) in enumerate(zip(plan.rough_loads, r["rough", s])):
            fine_ok = fine is not None and fine[i]["converged"]
            row = dict(seed=s, p=p, load=p * lam / (2 * math.sqrt(m2)),
                       bem=x["area"] / (2 * math.pi), n_contacts=x["n_contacts"],
                       converged=x["converged"] and x["min_gap"] >= 0, seconds=x["seconds"],
                       error=x["error"], retried=x.get("retried", False),
                       persson=float(pc.area_fraction(p)),
                       persson_iso=float(pc.area_fraction_isotropic(p)),
                       fine=fine[i]["area"] / (2 * math.pi) if fine_ok else None)
            for k, m in models.items():
                row[k] = m.area_fraction_at_pressure(p)
            rows.append(row)
    good = [w for w in rows if w["converged"]]
    for w in good:
        for k in theories:
            w[k + "_ratio"] = w[k] / w["bem"]
    per_load = []
    for p in plan.rough_loads:
        sel = [w for w in good if w["p"] == p]
        per_load.append(dict(p=p, n=len(sel), bem=_stats([w["bem"] for w in sel]),
                             contacts=_stats([w["n_contacts"] for w in sel]),
                             **{k: _stats([w[k + "_ratio"] for w in sel]) for k in theories}))
    small = [w for w in good if w["p"] <= plan.small_load]
    pooled = {k: _stats([w[k + "_ratio"] for w in small]) for k in theories}
    pooled_all = {k: _stats([w[k + "_ratio"] for w in good]) for k in theories}
    seed_means = [np.mean([w["persson_ratio"] for w in small if w["seed"] == s])
                  for s in plan.rough_seeds if any(w["seed"] == s for w in small)]
    # small-load slope: A/A0 = κ p̄/(E*√m2), least squares through the origin, loads p̃ <= 0.05
    lo = [w for w in good if w["p"] <= 0.05]
    kappa = (sum(w["bem"] * w["load"] for w in lo) / sum(w["load"] ** 2 for w in lo)
             if lo else np.nan)
    fine = [w for w in good if w["fine"] is not None]
    mesh = [abs(w["fine"] / w["bem"] - 1) for w in fine]
    mesh_ratio = [abs(w["bem"] / w["fine"] - 1) for w in fine]   # Persson/BEM changes by this
    n_fine = sum(len(r["rough_fine", s]) for s in plan.mesh_check_seeds)
    methods = collections.Counter(x.get("method") or "failed" for s in plan.rough_seeds
                                  for x in r["rough", s])
    return dict(rows=rows, methods=methods, per_load=per_load, pooled=pooled, pooled_all=pooled_all,
                seed_means=_stats(seed_means), kappa=kappa,
                kappa_persson=math.sqrt(8 / math.pi), kappa_bgt=math.sqrt(math.pi),
                failed=[w for w in rows if not w["converged"]], theories=theories,
                mesh_change=max(mesh) if mesh else None,
                mesh_ratio_change=max(mesh_ratio) if mesh_ratio else None,
                mesh_points=len(fine), mesh_total=n_fine,
                seconds=sum(w["seconds"] for w in rows),
                fine_seconds=sum(x["seconds"] for s in plan.mesh_check_seeds
                                 for x in r["rough_fine", s]))


def friction(plan, r):
    from ..profiles import Sinusoid
    from ..rheology import StandardLinearSolid
    from ..theories import PerssonFriction

    sls = StandardLinearSolid(beta=BETA)
    dense = 10.0 ** np.linspace(-4, 4, 801)
    sin = Sinusoid(amplitude=SINUSOID_AMPLITUDE)
    wavy = []
    for p in plan.friction_loads:
        pf = PerssonFriction.from_profile(sin, sls)
        pf2 = PerssonFriction.from_profile(sin, sls, contact_correction=0.5)
        pts = []
        for z in plan.friction_zetas:
            x = r["friction", p, z]
            pts.append(dict(zeta=z, area=x["area"], bem=x["reduced_friction"],
                            converged=x["converged"], seconds=x["seconds"], error=x["error"],
                            persson=float(pf.reduced_coefficient(z, p)),
                            persson_area=2 * math.pi * float(pf.area_fraction(z, p))))
        ok = [q for q in pts if q["converged"]]
        curve = pf.reduced_coefficient(dense, p)
        i = int(np.argmax(curve))
        wavy.append(dict(p=p, points=pts,
                         bem_peak=_peak([q["zeta"] for q in ok], [q["bem"] for q in ok]),
                         persson_peak=(float(dense[i]), float(curve[i])), dense=dense,
                         curve=curve, curve_corrected=pf2.reduced_coefficient(dense, p),
                         ratio=_stats([q["persson"] / q["bem"] for q in ok if q["bem"] > 0])))
    rough = []
    for s in plan.rough_friction_seeds:
        pf = PerssonFriction.from_profile(_profile(s), sls)
        pts = []
        for z, x in zip(plan.rough_friction_zetas, r["rough_zeta", s]):
            pts.append(dict(seed=s, zeta=z, area=x["area"], n_contacts=x["n_contacts"],
                            bem=x["reduced_friction"], converged=x["converged"],
                            min_gap=x["min_gap"], seconds=x["seconds"], error=x["error"],
                            retried=x.get("retried", False), method=x.get("method", ""),
                            persson=float(pf.reduced_coefficient(z, plan.rough_friction_load)),
                            persson_area=2 * math.pi * float(
                                pf.area_fraction(z, plan.rough_friction_load))))
        rough.append(dict(seed=s, points=pts, dense=dense,
                          curve=pf.reduced_coefficient(dense, plan.rough_friction_load)))
    ok = [q for w in rough for q in w["points"] if q["converged"] and q["bem"] > 0]
    return dict(wavy=wavy, rough=rough,
                rough_ratio=_stats([q["persson"] / q["bem"] for q in ok]),
                rough_area_ratio=_stats([q["persson_area"] / q["area"] for q in ok]),
                seconds=sum(q["seconds"] for w in wavy for q in w["points"]),
                rough_seconds=sum(q["seconds"] for w in rough for q in w["points"]))


def limits(plan, r):
    from ..reference import JohnsonWavy

    rows = []
    for kind, gamma, dx in _LIMIT_KINDS:
        G = 0.0 if gamma is None else plan.limit_gamma
        for z in plan.limit_zetas:
            slow = z < 1
            if dx == 0.0 and slow:        # glassy edge: Γ̃ enhanced β-fold on a relaxed bulk
                ref = JohnsonWavy(Gamma=BETA * G)
                label = f"Johnson, Γ̃ = β·{fmt(G)}, E0"
            else:
                ref = JohnsonWavy(Gamma=G, modulus_ratio=1.0 if slow else BETA)
                name = "Westergaard" if G == 0 else f"Johnson, Γ̃ = {fmt(G)}"
                label = f"{name}, {'E0' if slow else 'E∞ = βE0'}"
            x = r["limit", kind, z]
            a_ref = ref.area_at_pressure(plan.limit_load)
            rows.append(dict(case=f"sinusoid, {kind}", zeta=z, reference=label, area=x["area"],
                             ref=a_ref, error=_rel(x["area"], a_ref), friction=x["friction"],
                             converged=x["converged"], seconds=x["seconds"]))
    for z in plan.rough_limit_zetas:
        x, y = r["rough_limit", z], r["rough_limit_ref", z]
        slow = z < 1
        label = (f"elastic BEM at p̃ = {fmt(plan.rough_limit_load)} (E0)" if slow else
                 f"elastic BEM at p̃/β = {fmt(plan.rough_limit_load / BETA)} (E∞)")
        rows.append(dict(case="rough seed 0, adhesionless", zeta=z, reference=label,
                         area=x["area"], ref=y["area"], error=_rel(x["area"], y["area"]),
                         friction=x["friction"], converged=x["converged"] and y["converged"],
                         seconds=x["seconds"] + y["seconds"]))
    return dict(rows=rows)


def fuller_tabor_note(gamma=2.387e-7, p=0.05):
    """FT (loading) over GW area at the thesis's γ̃ for seed 0, and the adhesion parameter θ."""
    from scipy.optimize import brentq

    from ..theories import FullerTabor, GreenwoodWilliamson

    prof = _profile(0)
    ft = FullerTabor.from_profile(prof, gamma=gamma)
    gw = GreenwoodWilliamson.from_profile(prof)
    d = brentq(lambda t: float(ft.mean_pressure(t)) - p, -10.0, 10.0, xtol=1e-13)
    return dict(gamma=gamma, p=p, theta=float(ft.adhesion_parameter),
                ratio=float(ft.area_fraction(d)) / gw.area_fraction_at_pressure(p))


# ---------------------------------------------------------------------------------------------
# Markdown
# ---------------------------------------------------------------------------------------------
SECTIONS = ("## 1. Closed forms: Westergaard and Johnson",
            "## 2. Mesh convergence",
            "## 3. Elastic rough contact area against load",
            "## 4. Viscoelastic friction against speed",
            "## 5. Elastic limits of the viscoelastic solver",
            "## 6. The models side by side (after thesis Table 4.1)",
            "## Run time")


def _table(header, rows) -> list[str]:
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return out + [""]


def _failures(rows) -> str:
    bad = [w for w in rows if not w["converged"]]
    return "all converged" if not bad else f"{len(bad)} of {len(rows)} failed"


def _md_closed(cf, plan) -> list[str]:
    L = [SECTIONS[0], "",
         f"Rigid sinusoid on an elastic half-plane, {plan.elements} elements per contact (the "
         "default mesh), Newton. Relative errors of the contact area Ã against the closed forms of "
         "`viscocontact.reference` (Westergaard: `p̃∞ = sin²(Ã/4)`; Johnson: "
         "`p̃∞ = s² - 2√(Γ̃ tan(Ã/4))`, `s = sin(Ã/4)`), and of the penetration Δ̃ for "
         "Westergaard. Johnson's form is the limit δX → 0 of the edge advance; the default "
         "`EnergyBalance.edge_perturbation` is a finite δX (`docs/edges.md`), so its error "
         "includes the δX bias.", "", "<!-- table: closed-form-errors -->"]
    rows = [(f"Westergaard, p̃∞ = {fmt(w['p'])}", f"{w['area']:.6f}", f"{w['ref']:.6f}",
             fmt(w["error"], 2, True), fmt(w["pen_error"], 2, True)) for w in cf["westergaard"]]
    rows += [(f"Johnson, Γ̃ = {fmt(j['Gamma'])}, p̃∞ = {fmt(j['p'])}, default δX",
              f"{j['area']:.6f}", f"{j['ref']:.6f}", fmt(j["error"], 2, True), "—")
             for j in cf["johnson"] if j["kind"] == "johnson"]
    L += _table(("case", "Ã (BEM)", "Ã (closed form)", "error of Ã", "error of Δ̃"), rows)
    zero = [j for j in cf["johnson"] if j["kind"] == "johnson0"]
    L += ["With the closed-form edge limit `edge_perturbation = 0` (the model Johnson's formula "
          "describes), same mesh:", "", "<!-- table: johnson-dx0 -->"]
    L += _table(("case", "Ã (BEM)", "Ã (closed form)", "error of Ã"),
                [(f"Johnson, Γ̃ = {fmt(j['Gamma'])}, p̃∞ = {fmt(j['p'])}, δX = 0",
                  f"{j['area']:.6f}", f"{j['ref']:.6f}", fmt(j["error"], 2, True)) for j in zero])
    allw = [abs(w["error"]) for w in cf["westergaard"]]
    allj = [abs(j["error"]) for j in cf["johnson"] if j["kind"] == "johnson"]
    L += [f"Largest |error|: Westergaard {fmt(max(allw))}, Johnson (default δX) "
          f"{fmt(max(allj))}, Johnson (δX = 0) {fmt(max(abs(j['error']) for j in zero))}. "
          f"Solves: {_failures(cf['westergaard'] + cf['johnson'])}.",
          "", "![closed forms](figures/validation_closed_forms.png)", ""]
    return L


def _md_mesh(mc, plan) -> list[str]:
    L = [SECTIONS[1], "",
         "Relative error of Ã against elements per contact (eq. 4.21's N, clustering n = 1). The "
         "observed order is the least-squares slope of log|error| against log N; the pairwise "
         "orders are log₂ of successive error ratios.", ""]
    ns = mc["westergaard"]["elements"]
    rows = []
    for key in ("westergaard", "johnson"):
        s = mc[key]
        rows.append((s["label"], *[fmt(e, 2, True) for e in s["errors"]], fmt(s["order"], 3)))
    L += ["<!-- table: mesh-convergence -->"]
    L += _table(("case", *[f"N = {n}" for n in ns], "observed order"), rows)
    L += ["Pairwise orders: " + "; ".join(
        f"{mc[k]['label']}: " + ", ".join(fmt(o, 3) for o in mc[k]["pairs"])
        for k in ("westergaard", "johnson")) + ".", ""]
    if "johnson_dx" in mc:
        s = mc["johnson_dx"]
        L += ["With the default finite advance δX the BEM converges to the finite-δX model, not "
              "to Johnson's δX → 0 form: the error against Johnson levels off at the δX bias, "
              "while the difference to the finest mesh (self-convergence) keeps falling.", ""]
        L += _table(("Johnson, Γ̃ = 0.05, p̃∞ = 0, default δX", *[f"N = {n}" for n in ns]),
                    [("error against Johnson", *[fmt(e, 2, True) for e in s["errors"]]),
                     (f"difference to N = {ns[-1]}", *[fmt(e, 2, True) for e in s["self_errors"]],
                      "0")])
        L += [f"Observed self-convergence order {fmt(s['order'], 3)} (pairwise "
              + ", ".join(fmt(o, 3) for o in s["pairs"]) + f"); δX bias at N = {ns[-1]}: "
              f"{fmt(s['errors'][-1], 2, True)}.", ""]
    return L


def _md_rough(ra, plan) -> list[str]:
    seeds = plan.rough_seeds
    th = ra["theories"]
    pp = ra["pooled"]["persson"]
    iso = ra["pooled"]["persson_iso"]
    L = [SECTIONS[2], "",
         f"`SelfAffineProfile(hurst={HURST}, scales={SCALES}, rms={RMS}, seed=s)`, seeds "
         f"{seeds[0]}-{seeds[-1]} ({len(seeds)} realisations), elastic, adhesionless, "
         f"{_methods_text(ra['methods'], plan)}; the loads "
         f"p̃∞ = {', '.join(fmt(p) for p in plan.rough_loads)} are followed upwards, each "
         "continued from the previous contact set. The theories are evaluated at the same p̃∞ and "
         "profile (`viscocontact.theories`): Persson's area for line roughness "
         "`erf(p̃Λ̃/√(2m2))`, eq. 3.45 as printed (the isotropic-surface form), and the 3D "
         "multi-asperity models with the profile read as a cross-section of an isotropic surface "
         "(`docs/theories.md`). Ratios are theory/computed per seed and load: mean ± standard "
         "deviation over seeds (min–max); \"computed\" is this package's solution.", ""]
    if ra["failed"]:
        L += [f"**{len(ra['failed'])} of {len(ra['rows'])} solves failed or interpenetrated and "
              "are left out:** "
              + "; ".join(f"seed {w['seed']} p̃ = {fmt(w['p'])} ({w['error'] or 'not converged'})"
                          for w in ra["failed"]) + ".", ""]
    else:
        L += [f"All {len(ra['rows'])} solves converged without interpenetration.", ""]
    retried = [w for w in ra["rows"] if w["retried"]]
    if retried:
        L[-2] += (f" {len(retried)} solves did not converge when continued from the previous "
                  "load and were solved again from first touch ("
                  + ("all converged" if all(w["converged"] for w in retried) else
                     f"{sum(w['converged'] for w in retried)} converged") + ").")
    rows = [(fmt(d["p"]), d["n"], _spread(d["bem"]), fmt(d["contacts"]["mean"], 2),
             *[_spread(d[k]) for k in th]) for d in ra["per_load"]]
    L += ["<!-- table: rough-area -->"]
    L += _table(("p̃∞", "seeds", "A/A0 (computed)", "contacts",
                 *[f"{v} / computed" for v in th.values()]),
                rows)
    small_area = max(d["bem"]["hi"] for d in ra["per_load"] if d["p"] <= plan.small_load)
    L += [f"**Thesis §3.4 check.** The thesis quotes A_Persson/A_BEM ≈ {THESIS_PERSSON_RATIO} "
          f"for 1D roughness (Carbone et al. 2009). Measured at p̃∞ ≤ {fmt(plan.small_load)} "
          f"(A/A0 ≤ {fmt(small_area, 2)}), {pp['n']} solves: A_Persson/A_computed = {_spread(pp)}, "
          f"i.e. computed/Persson = {fmt(1 / pp['mean'], 3)}; the per-seed mean ratios spread as "
          f"{_spread(ra['seed_means'])}. Over all loads: {_spread(ra['pooled_all']['persson'])}. "
          f"Eq. 3.45 applied literally to the profile gives {_spread(iso)} at "
          f"p̃∞ ≤ {fmt(plan.small_load)}. So Persson's line form gives {fmt(pp['mean'], 3)} of "
          f"the computed area, {_compare(pp['mean'], THESIS_PERSSON_RATIO)} the thesis's "
          f"{THESIS_PERSSON_RATIO}, and eq. 3.45 as printed {fmt(iso['mean'], 3)}, "
          f"{_compare(iso['mean'], THESIS_PERSSON_RATIO)} it.", "",
          f"**Small-load slope.** Fitting A/A0 = κ·p̄/(E*√m2) through the origin at p̃∞ ≤ 0.05 "
          f"gives κ_computed = {fmt(ra['kappa'], 3)}, against Persson's √(8/π) = "
          f"{fmt(ra['kappa_persson'], 4)} (line form) and the asperity models' asymptotic "
          f"√π = {fmt(ra['kappa_bgt'], 4)} (BGT, height-curvature).", ""]
    if ra["mesh_change"] is not None:
        L += [f"**Accuracy.** Seeds {', '.join(str(s) for s in plan.mesh_check_seeds)} solved "
              f"again at tolerance {fmt(plan.rough_tolerance / 10)} ({ra['mesh_points']} of "
              f"{ra['mesh_total']} solves converged): the largest relative change of A/A0 is "
              f"{fmt(ra['mesh_change'])}, and of the Persson/computed ratio "
              f"{fmt(ra['mesh_ratio_change'])}, against a spread between realisations of "
              f"{fmt(pp['sd'] / pp['mean'])} (relative standard deviation).", ""]
    L += ["![rough area](figures/validation_rough_area.png)", ""]
    return L


def _methods_text(methods, plan) -> str:
    """Which method computed the rough solves: the planned one and the counts of each."""
    counts = ", ".join(f"{n} by {m}" for m, n in sorted(methods.items()))
    return (f"solved by the planned method (`[method] kind = \"auto\"`, tolerance "
            f"{fmt(plan.rough_tolerance)}: the spectral method for adhesionless scenes, the BEM "
            f"with {plan.rough_elements} elements per contact and bisection where it takes over; "
            f"{counts})")


def _md_friction(fr, plan) -> list[str]:
    L = [SECTIONS[3], "",
         f"Adhesionless, `StandardLinearSolid(beta={fmt(BETA)})`. The BEM (default mesh, Newton) "
         "for the sinusoid, the planned method (`auto`: the spectral method) for the rough "
         "profile, against Persson's mean-field friction for "
         "the same profile and rheology (`PerssonFriction`, contact correction S = 1; the "
         "figure also shows S = γ + (1-γ)P² with γ = ½). Friction is the reduced coefficient "
         "μ/√m2 (eq. 4.59).", "",
         f"**Sinusoid** `Sinusoid(amplitude={SINUSOID_AMPLITUDE})`, "
         f"{len(plan.friction_zetas)} speeds ζ from {fmt(min(plan.friction_zetas))} to "
         f"{fmt(max(plan.friction_zetas))}.", ""]
    rows: list[tuple] = []
    for w in fr["wavy"]:
        (zb, vb), (zp, vp) = w["bem_peak"], w["persson_peak"]
        rows.append((fmt(w["p"]), fmt(zb, 3), fmt(vb, 3), fmt(zp, 3), fmt(vp, 3),
                     fmt(vp / vb, 3), _spread(w["ratio"])))
    L += ["<!-- table: wavy-friction-peaks -->"]
    L += _table(("p̃∞", "ζ at BEM peak", "BEM peak μ/√m2", "ζ at Persson peak",
                 "Persson peak μ/√m2", "peak ratio Persson/BEM", "Persson/BEM over all ζ"), rows)
    decade = [z for z in plan.friction_zetas if abs(math.log10(z) - round(math.log10(z))) < 1e-9]
    rows = []
    for w in fr["wavy"]:
        for q in w["points"]:
            if q["zeta"] in decade:
                rows.append((fmt(w["p"]), fmt(q["zeta"]), f"{q['area']:.4f}",
                             fmt(q["persson_area"], 4), fmt(q["bem"], 3), fmt(q["persson"], 3),
                             fmt(q["persson"] / q["bem"], 3) if q["bem"] > 0 else "—"))
    L += _table(("p̃∞", "ζ", "Ã (BEM)", "Ã (Persson)", "μ/√m2 (BEM)", "μ/√m2 (Persson)",
                 "Persson/BEM"), rows)
    points = [q for w in fr["wavy"] for q in w["points"]]
    L += [f"Sinusoid solves: {_failures(points)}"
          + "".join(f"; ζ = {fmt(q['zeta'])}: {q['error'] or 'not converged'}"
                    for q in points if not q["converged"]) + ".", "",
          f"**Rough profile**, seeds {', '.join(str(w['seed']) for w in fr['rough'])}, "
          f"p̃∞ = {fmt(plan.rough_friction_load)}, the planned method at tolerance "
          f"{fmt(plan.rough_tolerance)} (methods: "
          + ", ".join(f"{n} {m}" for m, n in sorted(collections.Counter(
              q.get("method") or "failed" for w in fr["rough"] for q in w["points"]).items()))
          + "), ζ followed downwards from the stiff end, each continued from the last converged "
          "contact set. Times are per solve.", ""]
    rows = []
    for w in fr["rough"]:
        for q in w["points"]:
            ok = q["converged"]
            rows.append((q["seed"], fmt(q["zeta"]),
                         ("yes" if ok else f"no ({q['error'] or 'not converged'})")
                         + (", retried from first touch" if q["retried"] else ""),
                         f"{q['area']:.4f}" if ok else "—", q["n_contacts"] if ok else "—",
                         fmt(q["bem"], 3) if ok else "—", fmt(q["persson"], 3),
                         fmt(q["persson"] / q["bem"], 3) if ok and q["bem"] > 0 else "—",
                         fmt(q["persson_area"] / q["area"], 3) if ok else "—",
                         f"{q['seconds']:.1f} s"))
    L += ["<!-- table: rough-friction -->"]
    L += _table(("seed", "ζ", "converged", "Ã (computed)", "contacts", "μ/√m2 (computed)",
                 "μ/√m2 (Persson)", "Persson/computed", "area Persson/computed", "time"), rows)
    wv = fr["wavy"][0]
    ok = [q for q in wv["points"] if q["converged"] and q["bem"] > 0]
    lo, hi = ok[0], ok[-1]
    L += [f"Persson/computed friction on the rough profile: {_spread(fr['rough_ratio'])}; "
          f"contact area Persson/computed {_spread(fr['rough_area_ratio'])}. On the sinusoid at "
          f"p̃∞ = {fmt(wv['p'])} the friction ratio runs from {fmt(wv['ratio']['lo'], 3)} to "
          f"{fmt(wv['ratio']['hi'], 3)}: {fmt(lo['persson'] / lo['bem'], 3)} at "
          f"ζ = {fmt(lo['zeta'])}, {fmt(hi['persson'] / hi['bem'], 3)} at ζ = {fmt(hi['zeta'])}, "
          f"and the mean-field peak lies at {fmt(wv['persson_peak'][0] / wv['bem_peak'][0], 3)} "
          "times the BEM's ζ. The mean-field theory excites each mode at the frequency of its "
          "wavelength, while in the BEM the stress varies over the shorter contact length, so "
          "the BEM's loss peak sits at lower ζ.", "",
          "![friction](figures/validation_friction.png)", ""]
    return L


def _md_limits(li, plan) -> list[str]:
    L = [SECTIONS[4], "",
         f"`StandardLinearSolid(beta={fmt(BETA)})` at very small and very large ζ against the "
         f"elastic solutions with E0 and with E∞ = βE0: the sinusoid at p̃∞ = "
         f"{fmt(plan.limit_load)} (adhesionless and Γ̃ = {fmt(plan.limit_gamma)}, "
         f"{plan.elements} elements) against the closed forms, the rough profile (seed 0, "
         f"p̃∞ = {fmt(plan.rough_limit_load)}, {plan.rough_elements} elements) against the elastic "
         "BEM (at E∞ the elastic solution at p̃∞/β, by linearity). These cases use "
         "`Discretization(edge_resolution=None)`: the memory length ζ is far below any scale of "
         "the contact, and eq. 4.22's mesh alone is the elastic mesh.", ""]
    rows = [(w["case"], fmt(w["zeta"]), w["reference"], f"{w['area']:.6f}", f"{w['ref']:.6f}",
             fmt(w["error"], 2, True), fmt(w["friction"], 2), "yes" if w["converged"] else "no")
            for w in li["rows"]]
    L += ["<!-- table: elastic-limits -->"]
    L += _table(("case", "ζ", "reference", "Ã", "Ã (reference)", "error of Ã", "μ",
                 "converged"), rows)
    adh = [w for w in li["rows"] if "δX = 0" not in w["case"]]
    glassy = [w for w in li["rows"] if "δX = 0" in w["case"] and w["zeta"] < 1]
    L += [f"Largest |error| (all but the δX = 0 rows): {fmt(max(abs(w['error']) for w in adh))}; "
          f"largest |μ|: {fmt(max(abs(w['friction']) for w in li['rows']))}. "
          "With `edge_perturbation = 0` the limits do not commute (`docs/edges.md`): for any "
          "ζ > 0 the δX → 0 edge is glassy, so as ζ → 0 the bulk relaxes while the adhesion stays "
          "enhanced β-fold; those rows are compared with Johnson for βΓ̃ on E0 (largest |error| "
          f"{fmt(max([abs(w['error']) for w in glassy] or [np.nan]))}).", "",
          "![limits](figures/validation_limits.png)", ""]
    return L


def _md_models(cf, mc, ra, fr, li, ft, plan) -> list[str]:
    th = ra["pooled_all"]
    west = max(abs(w["error"]) for w in cf["westergaard"])
    john = max(abs(j["error"]) for j in cf["johnson"] if j["kind"] == "johnson")
    over = (f"over {len(plan.rough_seeds)} seeds and p̃∞ = {fmt(min(plan.rough_loads))}–"
            f"{fmt(max(plan.rough_loads))}")
    mesh = (f"; rough A/A0 changes by at most {fmt(ra['mesh_change'])} from "
            f"{plan.rough_elements} to {2 * plan.rough_elements} elements"
            if ra["mesh_change"] is not None else "")
    lim = max(abs(w["error"]) for w in li["rows"] if "δX = 0" not in w["case"])
    wv = fr["wavy"][0]
    rows = [
        ("Westergaard (1939), Johnson (1995)",
         "single sinusoid on an elastic half-plane; Johnson adds JKR-type adhesion",
         "one wavelength, elastic", "exact references of the BEM's elastic limits",
         f"largest error of Ã {fmt(west)} (Westergaard), {fmt(john)} (Johnson, default δX) at "
         f"{plan.elements} elements; order {fmt(mc['westergaard']['order'], 3)}"),
        ("Greenwood & Williamson (1966)",
         "Gaussian summit heights, identical spherical summits, independent Hertz contacts",
         "no interaction or coalescence; mono-scale; small loads only", "`GreenwoodWilliamson`",
         f"A_GW/A_BEM = {_spread(th['gw'])} {over}"),
        ("Fuller & Tabor (1975)", "GW with JKR summits (short-range adhesion, large Tabor "
         "parameter)", "simplified topography; JKR regime only", "`FullerTabor`",
         f"not compared (no adhesive rough BEM here; see `docs/verification.md`); at the "
         f"thesis's γ̃ = {fmt(ft['gamma'], 4)} (θ = {fmt(ft['theta'], 4)}) FT/GW area = "
         f"{fmt(ft['ratio'], 3)} at p̃∞ = {fmt(ft['p'])}, so it inherits GW's disagreement"),
        ("Bush, Gibson & Thomas (1975)", "elliptic Hertz summits; curvatures from the spectral "
         "moments (Nayak); isotropic Gaussian surface", "no interaction; non-adhesive; "
         "asperity-based", "not implemented (only Greenwood's simplification)", "—"),
        ("Greenwood (2006)", "BGT with equivalent spheres of radius 1/√(K1K2)",
         "no interaction; single scale; non-adhesive", "`SimplifiedBGT`",
         f"A_BGT/A_BEM = {_spread(th['bgt'])} {over}"),
        ("Carbone et al. (2009)", "GW with summit curvature depending on summit height",
         "no coalescence; independent asperities; non-adhesive", "`HeightCurvatureModel`",
         f"A/A_BEM = {_spread(th['hc'])} {over}"),
        ("Afferrante et al. (2012)", "Hertz asperities with elastic interaction and "
         "coalescence", "equivalent circular asperities; non-adhesive", "not implemented", "—"),
        ("Persson (2001), area", "diffusion of the pressure distribution in magnification; "
         "PSD-based; Gaussian self-affine surfaces", "inaccurate far from full contact; no "
         "adhesion, no discrete contacts", "`PerssonContact` (line form)",
         f"A_P/A_BEM = {_spread(th['persson'])} {over} (thesis §3.4: ≈ "
         f"{THESIS_PERSSON_RATIO}); eq. 3.45 literally: {_spread(th['persson_iso'])}"),
        ("Persson (2001), viscoelastic friction", "mean-field: each mode dissipates on the "
         "contact fraction at its magnification", "no edge physics, no adhesion",
         "`PerssonFriction`",
         f"μ_P/μ_BEM {fmt(wv['ratio']['lo'], 3)}–{fmt(wv['ratio']['hi'], 3)} (sinusoid, "
         f"p̃∞ = {fmt(wv['p'])}), peak at {fmt(wv['persson_peak'][0] / wv['bem_peak'][0], 3)}× "
         f"the BEM's ζ; rough {_spread(fr['rough_ratio'])}"),
        ("Proposed model (BEM, this package)", "rigid periodic profile sliding on a linear "
         "viscoelastic half-plane; steady state; energy balance at each edge; no interfacial "
         "shear", "1D + 1D; cost of the multi-edge balance", "`ContactProblem`",
         f"closed forms above{mesh}; elastic limits within {fmt(lim)}"),
    ]
    L = [SECTIONS[5], "",
         "Assumptions and limitations are those of thesis Table 4.1, abridged; the last column "
         "is measured in this report (theory/BEM, mean ± sd over seeds (min–max)).", "",
         "<!-- table: models -->"]
    L += _table(("model", "main assumptions", "main limitations (thesis)", "in viscocontact",
                 "measured disagreement with the BEM"), rows)
    return L


def markdown(plan, sections, ft, timing) -> str:
    """The report's text from the computed sections."""
    from .. import __version__

    cf, mc, ra, fr, li = (sections[k] for k in ("closed", "mesh", "rough", "friction", "limits"))
    pp = ra["pooled"]["persson"]
    L = ["# Validation", "",
         "<!-- generated by `viscocontact validate"
         f"{' --quick' if plan.name == 'quick' else ''}`; do not edit by hand -->", "",
         f"The BEM of `viscocontact` {__version__} against closed forms and the classical theories "
         f"of the thesis's Chapters 1 and 3 ({plan.name} run). Every number below is computed by "
         "`viscocontact/reports/validation.py`; regenerate with `viscocontact validate` "
         "(`--quick` for a short smoke run). Units are the dimensionless groups of eq. 4.17 "
         "(`docs/model.md`).", "",
         "**Headlines.**", "",
         f"* Closed forms at {plan.elements} elements per contact: largest |error of Ã| "
         f"{fmt(max(abs(w['error']) for w in cf['westergaard']))} (Westergaard), "
         f"{fmt(max(abs(j['error']) for j in cf['johnson'] if j['kind'] == 'johnson'))} "
         f"(Johnson, default δX); observed mesh orders {fmt(mc['westergaard']['order'], 3)} "
         f"(Westergaard) and {fmt(mc['johnson']['order'], 3)} (Johnson, δX = 0).",
         f"* Rough elastic area, p̃∞ ≤ {fmt(plan.small_load)}, {len(plan.rough_seeds)} seeds: "
         f"A_Persson/A_BEM = {_spread(pp)} (thesis: ≈ {THESIS_PERSSON_RATIO}); GW "
         f"{fmt(ra['pooled']['gw']['mean'], 3)}, simplified BGT "
         f"{fmt(ra['pooled']['bgt']['mean'], 3)}, height-curvature "
         f"{fmt(ra['pooled']['hc']['mean'], 3)} of the BEM area.",
         f"* Viscoelastic friction: Persson/BEM {fmt(fr['wavy'][0]['ratio']['lo'], 3)}–"
         f"{fmt(fr['wavy'][0]['ratio']['hi'], 3)} on the sinusoid, {_spread(fr['rough_ratio'])} "
         "on the rough profile.",
         f"* Elastic limits of the viscoelastic solver: |error of Ã| ≤ "
         f"{fmt(max(abs(w['error']) for w in li['rows'] if 'δX = 0' not in w['case']))}.", ""]
    L += _md_closed(cf, plan) + _md_mesh(mc, plan) + _md_rough(ra, plan)
    L += _md_friction(fr, plan) + _md_limits(li, plan) + _md_models(cf, mc, ra, fr, li, ft, plan)
    L += [SECTIONS[6], "",
          f"{plan.name} run with {timing['workers']} worker process(es): "
          f"{timing['wall']:.0f} s wall clock, {timing['cpu']:.0f} s of solves in total "
          f"(rough elastic {ra['seconds'] + ra['fine_seconds']:.0f} s, rough viscoelastic "
          f"{fr['rough_seconds']:.0f} s, sinusoid friction {fr['seconds']:.0f} s) on "
          f"{timing['cores']} cores; the 1-minute load average before the run was "
          f"{timing['load_before']:.1f} (other work on the machine slows the solves). Each solve "
          f"has a time limit of {plan.time_limit:.0f} s; a solve that reaches it is reported as "
          "failed in its table.", ""]
    return "\n".join(L)


# ---------------------------------------------------------------------------------------------
# Figures
# ---------------------------------------------------------------------------------------------
def _pyplot():
    """Figures outside pyplot's state: the caller's backend is left alone."""
    from ..plots import pyplot_free

    return pyplot_free


def _plain_ticks(axis, ticks=None) -> None:
    """Major ticks at ``ticks`` in plain numbers, no minor labels."""
    from matplotlib import ticker

    if ticks is not None:
        axis.set_major_locator(ticker.FixedLocator(list(ticks)))
        axis.set_major_formatter(ticker.FuncFormatter(lambda v, _: f"{v:g}"))
    axis.set_minor_formatter(ticker.NullFormatter())


def _save(fig, path: Path) -> Path:
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.stem}.", suffix=".png")
    os.close(fd)
    try:
        fig.savefig(tmp, format="png", dpi=120, bbox_inches="tight")
        publish(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)
    return path


def _figure_closed_forms(plt, cf, mc, path):
    from ..reference import JohnsonWavy

    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    A = np.linspace(1e-3, 2 * np.pi - 1e-3, 600)
    for G, c in ((0.0, "k"), (0.01, "C0"), (0.05, "C1")):
        a.plot(A, JohnsonWavy(Gamma=G).mean_pressure(A), c, lw=1,
               label="Westergaard" if G == 0 else f"Johnson Γ̃={G}")
    a.plot([w["area"] for w in cf["westergaard"]], [w["p"] for w in cf["westergaard"]], "ko",
           mfc="none", label="BEM, Westergaard")
    for j in cf["johnson"]:
        a.plot(j["area"], j["p"], "s" if j["kind"] == "johnson" else "^", mfc="none",
               color="C0" if j["Gamma"] == 0.01 else "C1")
    a.plot([], [], "ks", mfc="none", label="BEM, Johnson, default δX")
    a.plot([], [], "k^", mfc="none", label="BEM, Johnson, δX = 0")
    a.set(xlabel="Ã", ylabel="p̃∞", ylim=(-0.3, 1.05), title="BEM (markers) and closed forms")
    a.legend(fontsize=8)
    for key, m in (("westergaard", "o-"), ("johnson", "^-"), ("johnson_dx", "s--")):
        if key in mc:
            s = mc[key]
            b.loglog(s["elements"], np.abs(s["errors"]), m, label=s["label"])
            if key == "johnson_dx":
                b.loglog(s["elements"][:-1], np.abs(s["self_errors"]), "s:", mfc="none",
                         label="same, difference to finest mesh")
    n = np.array(mc["westergaard"]["elements"], dtype=float)
    b.loglog(n, abs(mc["westergaard"]["errors"][0]) * (n / n[0]) ** -2, "k:", lw=0.8,
             label="slope −2")
    b.set(xlabel="elements per contact N", ylabel="|relative error of Ã|",
          title="mesh convergence")
    _plain_ticks(b.xaxis, mc["westergaard"]["elements"])
    b.legend(fontsize=7)
    _save(fig, path)
    plt.close(fig)


def _figure_rough_area(plt, ra, plan, path):
    from scipy import special

    from ..theories import GreenwoodWilliamson, HeightCurvatureModel, SimplifiedBGT

    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    good = [w for w in ra["rows"] if w["converged"]]
    a.loglog([w["load"] for w in good], [w["bem"] for w in good], "k.", ms=4,
             label="computed (each seed)")
    x = np.geomspace(min(w["load"] for w in good) / 1.5, max(w["load"] for w in good) * 1.5, 60)
    a.loglog(x, special.erf(math.sqrt(2) * x), "C0", label="Persson, line form")
    a.loglog(x, special.erf(x), "C0--", label="eq. 3.45 as printed")
    prof = _profile(plan.rough_seeds[0])
    to_p = 2 * math.sqrt(prof.statistics().m2) / prof.amplitude   # p̄/(E*√m2) -> p̃
    for M, c, name in ((GreenwoodWilliamson, "C2", "GW"), (SimplifiedBGT, "C3", "simplified BGT"),
                       (HeightCurvatureModel, "C4", "height-curvature")):
        m = M.from_profile(prof)            # the moments, hence these curves, are the same
        a.loglog(x, [m.area_fraction_at_pressure(v * to_p) for v in x], c, label=name)
    _plain_ticks(a.xaxis)
    a.set(xlabel="p̄/(E*√m2) = p̃∞Λ̃/(2√m2)", ylabel="A/A0",
          title=f"elastic rough contact, {len(plan.rough_seeds)} seeds")
    a.legend(fontsize=8)
    loads = [d["p"] for d in ra["per_load"]]
    for k, c in (("persson", "C0"), ("persson_iso", "C0"), ("gw", "C2"), ("bgt", "C3"),
                 ("hc", "C4")):
        ls = "--" if k == "persson_iso" else "-"
        b.plot(loads, [d[k]["mean"] for d in ra["per_load"]], ls, color=c, marker="o", ms=3,
               label=ra["theories"][k])
        b.fill_between(loads, [d[k]["lo"] for d in ra["per_load"]],
                       [d[k]["hi"] for d in ra["per_load"]], color=c, alpha=0.12)
    b.axhline(THESIS_PERSSON_RATIO, color="k", lw=0.8, ls=":", label="thesis §3.4: ½")
    b.axhline(1.0, color="k", lw=0.5)
    b.set_xscale("log")
    nice = [p for p in loads if round(p / 10 ** math.floor(math.log10(p)), 9) in (1, 2, 5)]
    _plain_ticks(b.xaxis, nice or loads)
    b.set(xlabel="p̃∞", ylabel="A_theory / A_computed",
          title="ratio to the computed area: mean, band min–max over seeds")
    b.legend(fontsize=7)
    _save(fig, path)
    plt.close(fig)


def _figure_friction(plt, fr, plan, path):
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    for i, w in enumerate(fr["wavy"]):
        c = f"C{i}"
        pts = [q for q in w["points"] if q["converged"]]
        a.semilogx([q["zeta"] for q in pts], [q["bem"] for q in pts], "o", color=c, ms=4,
                   label=f"BEM p̃∞={fmt(w['p'])}")
        a.semilogx(w["dense"], w["curve"], "-", color=c, lw=1, label="Persson, S = 1")
        a.semilogx(w["dense"], w["curve_corrected"], ":", color=c, lw=1, label="Persson, γ = ½")
    a.set(xlim=(1e-4, 1e4), xlabel="ζ = q0Vτ", ylabel="μ/√m2", title=f"sinusoid, SLS β = {BETA:g}")
    a.legend(fontsize=7)
    for i, w in enumerate(fr["rough"]):
        c = f"C{i}"
        pts = [q for q in w["points"] if q["converged"]]
        b.semilogx([q["zeta"] for q in pts], [q["bem"] for q in pts], "o", color=c, ms=4,
                   label=f"computed seed {w['seed']}")
        b.semilogx(w["dense"], w["curve"], "-", color=c, lw=1, label=f"Persson seed {w['seed']}")
    b.set(xlim=(1e-4, 1e4), xlabel="ζ = q0Vτ", ylabel="μ/√m2",
          title=f"rough profile, p̃∞ = {fmt(plan.rough_friction_load)}")
    b.legend(fontsize=7)
    _save(fig, path)
    plt.close(fig)


def _figure_limits(plt, fr, li, path):
    from ..reference import westergaard_area

    fig, a = plt.subplots(figsize=(6, 4.2))
    for i, w in enumerate(fr["wavy"]):
        pts = [q for q in w["points"] if q["converged"]]
        a.semilogx([q["zeta"] for q in pts], [q["area"] for q in pts], "o-", color=f"C{i}",
                   ms=4, label=f"BEM p̃∞={fmt(w['p'])}")
        a.axhline(float(westergaard_area(w["p"])), color=f"C{i}", ls="--", lw=0.8)
        a.axhline(float(westergaard_area(w["p"] / BETA)), color=f"C{i}", ls=":", lw=0.8)
    for row in li["rows"]:
        if row["case"] == "sinusoid, adhesionless":
            a.plot(row["zeta"], row["area"], "kx")
    a.set(xscale="log", xlabel="ζ = q0Vτ", ylabel="Ã",
          title="sinusoid: Westergaard with E0 (--) and E∞ (:), limits (×)")
    a.legend(fontsize=8)
    _save(fig, path)
    plt.close(fig)


def figures(plan, sections, folder: Path) -> list[Path]:
    """Draw the four figures into ``folder``; returns their paths."""
    plt = _pyplot()
    folder.mkdir(parents=True, exist_ok=True)
    paths = [folder / f"validation_{n}.png"
             for n in ("closed_forms", "rough_area", "friction", "limits")]
    _figure_closed_forms(plt, sections["closed"], sections["mesh"], paths[0])
    _figure_rough_area(plt, sections["rough"], plan, paths[1])
    _figure_friction(plt, sections["friction"], plan, paths[2])
    _figure_limits(plt, sections["friction"], sections["limits"], paths[3])
    return paths


# ---------------------------------------------------------------------------------------------
# Entry point
# ---------------------------------------------------------------------------------------------
def _write_text(path: Path, text: str) -> None:
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            fh.write(text)
        publish(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def _solve_all(plan: Plan, workers: int, log) -> dict:
    """Run every task; ``{key: row or list of rows}``."""
    pool: _Serial | ProcessPoolExecutor
    if workers <= 1:
        pool = _Serial()
    else:   # spawn: no fork of a process whose BLAS threads may be running
        pool = ProcessPoolExecutor(max_workers=workers,
                                   mp_context=multiprocessing.get_context("spawn"))
    with pool:
        futures = _submit_all(plan, pool)
        log(f"{len(futures)} tasks on {max(workers, 1)} worker(s)")
        return {key: fut.result() for key, fut in futures.items()}


def generate(plan: Plan, out, workers: int = 2, log=print) -> dict:
    """Solve every case of ``plan`` and write ``out/validation.md`` and the figures.

    Returns the computed sections (dictionaries of numbers), the timing and the markdown.
    """
    out = Path(out)
    started = time.perf_counter()
    load_before = os.getloadavg()[0] if hasattr(os, "getloadavg") else np.nan
    results = _solve_all(plan, workers, log)
    sections = dict(closed=closed_forms(plan, results), mesh=mesh_convergence(plan, results),
                    rough=rough_area(plan, results), friction=friction(plan, results),
                    limits=limits(plan, results))
    cpu = sum(row["seconds"] for v in results.values()
              for row in (v if isinstance(v, list) else [v]))
    paths = figures(plan, sections, out / "figures")
    timing = dict(wall=time.perf_counter() - started, cpu=cpu, workers=max(workers, 1),
                  load_before=load_before, cores=os.cpu_count())
    text = markdown(plan, sections, fuller_tabor_note(), timing)
    _write_text(out / "validation.md", text)
    log(f"wrote {out / 'validation.md'} and {len(paths)} figures in {timing['wall']:.0f} s")
    return dict(sections=sections, timing=timing, markdown=text)


def configure_parser(parser: argparse.ArgumentParser) -> None:
    """The options of ``viscocontact validate`` (``python -m viscocontact.reports.validation``)."""
    parser.add_argument("--quick", action="store_true",
                        help="fewer seeds, loads and speeds (under a minute)")
    parser.add_argument("--out", default=None,
                        help="folder for validation.md and figures/ (default: docs, in a "
                             "source tree, i.e. a folder with docs/conf.py; required elsewhere)")
    parser.add_argument("--workers", type=int, default=min(2, os.cpu_count() or 1),
                        help="worker processes (default: 2, or 1 on a single core)")


def output_folder(out: str | None) -> Path:
    """``--out``, checked before any solve: by default ``docs`` of the source tree this runs
    in (a folder with ``docs/conf.py``), never a new ``docs/`` wherever an install runs it."""
    from .._outputs import check_folder
    from ..errors import ValidationError

    if out is None:
        if not Path("docs", "conf.py").is_file():
            raise ValidationError("--out", None, "a folder for validation.md and figures/ "
                                                 "(the default, docs/, is only used in a source "
                                                 "tree: a folder with docs/conf.py)")
        out = "docs"
    return check_folder("--out", out, "a folder for validation.md and figures/")


def run(args: argparse.Namespace) -> int:
    """Regenerate the validation report (docs/validation.md and its figures)."""
    if args.workers < 1:
        from ..errors import ValidationError

        raise ValidationError("--workers", args.workers, "an integer >= 1")
    generate(QUICK if args.quick else FULL, output_folder(args.out), workers=args.workers,
             log=lambda m: print(m, file=sys.stderr))
    return 0


def main(argv=None) -> int:
    """``python -m viscocontact.reports.validation [--quick] [--out docs] [--workers N]``."""
    parser = argparse.ArgumentParser(prog="viscocontact validate",
                                     description="Regenerate the validation report.")
    configure_parser(parser)
    return run(parser.parse_args(argv))


if __name__ == "__main__":
    sys.exit(main())
