"""A randomised campaign over the whole scene space: a seeded sampler and the checks of a result.

:func:`draw` turns an integer seed into a scene table (``Scene.from_dict`` input) over the ranges
that a user can enter and that the model claims to cover (:data:`RANGES`): profiles (sinusoid,
self-affine), rheologies (elastic, standard linear solid with β up to 1e4, Prony series of 2-3
arms), kernels (half-plane, confined and free layers), adhesion (none, energy balance,
Maugis-Dugdale), both load controls, ζ over ten decades and the four edge solvers.

:func:`run_scene` builds and solves one drawn scene under a time limit and :func:`check` lists
the identities its outcome violates:

* the solve converged, or it ends with a reason that is a property of the scene (no equilibrium
  under this load, an unstable equilibrium, outside the model's validity, refused at build) —
  never of the solver's path (budget exhausted, contact set still changing, a residual that is
  not finite, a time limit) (:func:`classify`);
* a converged result meets its load (:data:`LOAD_TOLERANCE`) and has no interpenetration
  (:data:`GAP_TOLERANCE`); unless it says that it lies outside the model (where the friction is
  that of a process zone, not the model's), its friction force opposes the sliding on a lossy
  solid (``μ·p̃∞ >= 0``: μ is the force over the load, negative under a tensile load) and its
  friction equals the dissipated power (``friction_dissipation + friction_edges``,
  ``docs/edges.md``) within the errors the two sides have: the estimates of μ and of the
  dissipated power's μ that the result carries (``extras["estimates"]``, both relative to
  ``friction_scale``, :func:`_power_check`) — or :data:`POWER_FALLBACK` of the larger side
  where the method gives no estimate — plus the accuracy of the tips' release
  (``EDGE_RELEASE_ACCURACY`` of the energy through them) and, on a lossless solid, a friction
  of :data:`FRICTION_ZERO` √m2 taken as zero. Which tolerance served is counted
  (:attr:`Outcome.power_tolerance`: ``"estimate"``, ``"fallback"``, or ``"unavailable"`` where
  the method reports no dissipation).

``benchmarks/campaign.py`` runs hundreds of seeds in worker processes and tabulates the outcomes
by component; ``tests/integration/test_campaign.py`` runs a fixed short sample.

>>> from viscocontact.testing.campaign import draw
>>> table = draw(3)
>>> sorted(table) == ['adhesion', 'kernel', 'load', 'profile', 'rheology', 'sliding', 'solver']
True
>>> draw(3) == table
True
"""
from __future__ import annotations

import math
import time
import warnings
from typing import Any

import attrs
import numpy as np

__all__ = ["RANGES", "draw", "describe", "run_scene", "check", "classify", "Outcome",
           "LOAD_TOLERANCE", "GAP_TOLERANCE", "POWER_FALLBACK", "FRICTION_ZERO", "SCENE_REASONS",
           "PATH_REASONS"]

#: The drawn ranges (dimensionless groups of eq. 4.17; ``docs/scene.md``). Log-uniform where
#: the range spans decades.
RANGES: dict[str, Any] = {
    "profile": ("sinusoid", "self-affine"),
    "amplitude": (0.01, 0.1),          # Λ̃ = q0·Λ of a sinusoid
    "hurst": (0.5, 0.95),
    "scales": (10, 100),               # N_q
    "rms": (0.003, 0.03),              # q0·r_rms
    "rheology": ("elastic", "standard-linear-solid", "prony"),
    "beta": (2.0, 1e4),                # E∞/E0 of the SLS and of the Prony series
    "arms": (2, 3),                    # Maxwell arms of a Prony series
    "arm_times": (1e-2, 1e2),          # τ_i in units of the reference time
    "kernel": ("half-plane", "confined-layer", "free-layer"),
    "thickness": (0.1, 30.0),          # q0·d
    "adhesion": ("none", "energy-balance", "maugis-dugdale"),
    "gamma": (1e-7, 1e-5),             # γ̃
    "range": (1e-4, 3e-3),             # h̃0 = q0·h0 of the Dugdale law
    "control": ("mean_pressure", "penetration"),
    "mean_pressure": (0.05, 0.8),      # p̃∞
    "penetration": (0.05, 0.8),        # Δ̃ = Δ/Λ
    "zeta": (1e-6, 1e4),
    "solver": ("broyden", "newton", "nonlinear-cg", "bisection"),
}

#: Relative misfit of the reached load (p̃∞ or Δ̃) allowed to a converged result.
LOAD_TOLERANCE = 1e-6
#: Smallest gap allowed outside the contacts, in units of the profile's amplitude Λ̃ (the
#: check grid samples the gap; round-off of the displacement sums is ~1e-12 of Λ̃).
GAP_TOLERANCE = 1e-6
#: Relative power-balance misfit allowed where the result has no finite ``error_estimate``:
#: the tolerance at which the energy balance itself calls a result outside the model
#: (``viscocontact.adhesion.energy_balance.POWER_BALANCE_TOLERANCE``).
POWER_FALLBACK = 0.02
#: Friction of a lossless solid, in units of the profile's rms slope √m2 (the reduced friction
#: of eq. 4.59), taken as zero: an elastic solid's adhesionless friction is zero, and the
#: methods give up to 6e-6 √m2 on rough profiles (their grids are not symmetric about the
#: contacts). A lossy solid gets no such floor.
FRICTION_ZERO = 1e-5

#: Words of a not-converged message that name a property of the scene (lower case).
SCENE_REASONS = ("no equilibrium", "unstable under load control", "outside the model",
                 "pulls off", "pull-off", "detaches", "refused", "no steady state")
#: Words that name the solver's path: these are failures of the campaign.
PATH_REASONS = ("still changing", "budget", "evaluations", "stalled", "not finite",
                "time limit", "iterations", "did not converge", "no progress", "cycles",
                "did not stop", "without a valid field", "do not represent")


def _log_uniform(rng, lo: float, hi: float) -> float:
    return float(math.exp(rng.uniform(math.log(lo), math.log(hi))))


def _profile(rng) -> dict[str, Any]:
    if rng.random() < 0.5:
        return {"kind": "sinusoid", "amplitude": _log_uniform(rng, *RANGES["amplitude"])}
    return {"kind": "self-affine", "hurst": float(rng.uniform(*RANGES["hurst"])),
            "scales": int(rng.integers(RANGES["scales"][0], RANGES["scales"][1] + 1)),
            "rms": _log_uniform(rng, *RANGES["rms"]), "seed": int(rng.integers(0, 10_000))}


def _rheology(rng) -> dict[str, Any]:
    u = rng.random()
    if u < 0.2:
        return {"kind": "elastic"}
    beta = _log_uniform(rng, *RANGES["beta"])
    if u < 0.65:
        return {"kind": "standard-linear-solid", "beta": beta}
    arms = int(rng.integers(RANGES["arms"][0], RANGES["arms"][1] + 1))
    shares = rng.dirichlet(np.ones(arms))
    times = np.sort([_log_uniform(rng, *RANGES["arm_times"]) for _ in range(arms)])
    return {"kind": "prony", "moduli": [float(v) for v in (beta - 1.0) * shares],
            "times": [float(t) for t in times]}


def _kernel(rng) -> dict[str, Any]:
    u = rng.random()
    if u < 0.4:
        return {"kind": "half-plane"}
    kind = "confined-layer" if u < 0.7 else "free-layer"
    return {"kind": kind, "thickness": _log_uniform(rng, *RANGES["thickness"])}


def _adhesion(rng) -> dict[str, Any]:
    u = rng.random()
    if u < 0.4:
        return {"kind": "none"}
    gamma = _log_uniform(rng, *RANGES["gamma"])
    if u < 0.7:
        return {"kind": "energy-balance", "gamma": gamma}
    return {"kind": "maugis-dugdale", "gamma": gamma, "range": _log_uniform(rng, *RANGES["range"])}


def draw(seed: int) -> dict[str, Any]:
    """The scene table of ``seed`` (deterministic: the same seed gives the same table on every
    machine). Pass it to :meth:`~viscocontact.scene.Scene.from_dict`."""
    rng = np.random.default_rng([0x5CE4E, int(seed)])
    table = {"profile": _profile(rng), "rheology": _rheology(rng), "kernel": _kernel(rng),
             "adhesion": _adhesion(rng)}
    control = RANGES["control"][int(rng.integers(2))]
    table["load"] = {control: float(rng.uniform(*RANGES[control]))}
    table["sliding"] = {"zeta": _log_uniform(rng, *RANGES["zeta"])}
    table["solver"] = {"kind": RANGES["solver"][int(rng.integers(4))]}
    return table


def describe(table: dict[str, Any]) -> dict[str, str]:
    """The component labels a campaign table groups by (adhesion, rheology, kernel, control,
    solver, profile)."""
    return {"adhesion": table["adhesion"]["kind"], "rheology": table["rheology"]["kind"],
            "kernel": table["kernel"]["kind"], "control": next(iter(table["load"])),
            "solver": table["solver"]["kind"], "profile": table["profile"]["kind"]}


@attrs.frozen(kw_only=True)
class Outcome:
    """What one drawn scene gave.

    ``outcome`` is ``"converged"``, ``"outside-model"`` (converged, and the result says that it
    lies outside the model), ``"scene"`` (not converged for a property of the scene: the
    message names it), ``"refused"`` (the scene was refused when built), ``"path"`` (not
    converged for a reason of the solver's path), ``"time-limit"``, ``"error"`` (an exception)
    or ``"unclassified"`` (a message neither list names). ``power_tolerance`` is ``"estimate"``
    or ``"fallback"`` (which tolerance the power balance was checked against; ``""`` when it
    was not checked).
    """

    outcome: str
    message: str = ""
    failures: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()
    seconds: float = 0.0
    method: str = ""
    power_tolerance: str = ""
    values: dict = attrs.field(factory=dict)

    @property
    def passed(self) -> bool:
        return not self.failures

    def to_dict(self) -> dict[str, Any]:
        """Plain data, compact: texts cut to 160 characters, numbers to 4 digits."""
        return {"outcome": self.outcome, "message": self.message[:160],
                "failures": [f[:160] for f in self.failures],
                "warnings": [w[:100] for w in self.warnings],
                "seconds": round(self.seconds, 2), "method": self.method,
                "power_tolerance": self.power_tolerance,
                **{k: v if v is None else float(f"{v:.4g}") for k, v in self.values.items()}}


def classify(message: str) -> str:
    """``"scene"`` when a not-converged message names a property of the scene, ``"path"`` when
    it names the solver's path, ``"unclassified"`` otherwise. A message naming both is a path
    failure (the scene's reason then comes from where the path stopped)."""
    text = message.lower()
    if any(word in text for word in PATH_REASONS):
        return "path"
    if any(word in text for word in SCENE_REASONS):
        return "scene"
    return "unclassified"


def _lossy(scene) -> bool:
    rheology = scene.rheology
    return scene.zeta > 0 and float(getattr(rheology, "instantaneous_modulus", 1.0)) > float(
        getattr(rheology, "relaxed_modulus", 1.0)) * (1 + 1e-12)


def _through_tips(scene, result) -> float:
    """The energy that flows through the edges' tips in friction units,
    ``|Λ̃/(2πp̃∞)| K_e Σ K̃²/4`` with ``K_e = E0 J(0+) = E0/E∞`` (the kernels' memory is never
    taken in its relaxed limit inside the drawn ranges)."""
    terms = result.edge_terms
    if terms is None or not result.mean_pressure:
        return 0.0
    k = np.asarray(terms.stress_intensity, dtype=float)
    rheology = scene.rheology
    compliance = float(rheology.relaxed_modulus) / float(rheology.instantaneous_modulus)
    scale = abs(float(scene.profile.amplitude) / (2 * np.pi * result.mean_pressure))
    return scale * compliance * float(np.sum(k**2)) / 4


def _power_check(scene, result) -> tuple[list[str], str, dict]:
    """The power balance: μ against the dissipated power's μ, within the sum of their error
    estimates (each side is a discretisation of the same quantity with its own error: on a
    free layer at ζ = 0.38, seed 18 of the campaign, μ on 512 cells was 3.6e-4 from the
    16384-cell value and the dissipation 1.8e-3), each relative to the scale the estimates are
    taken on, ``max(|μ|, floor·√m2)`` (the methods' ``friction_scale``)."""
    from ..adhesion.energy_balance import EDGE_RELEASE_ACCURACY

    mu = float(result.friction)
    bulk = float(result.extras.get("friction_dissipation", math.nan))
    edges = float(result.extras.get("friction_edges", 0.0))
    balance = bulk + edges
    values = {"friction": mu, "friction_dissipation": bulk, "friction_edges": edges}
    if not math.isfinite(mu):
        return [f"friction not finite: μ = {mu!r}"], "", values
    if not math.isfinite(balance):
        return [], "unavailable", values      # the method reports no dissipation: counted
    estimates = result.extras.get("estimates") or {}
    sides = (estimates.get("friction", math.nan), estimates.get("dissipation", math.nan),
             estimates.get("friction_scale", math.nan))
    if all(math.isfinite(v) for v in sides):
        used, error = "estimate", (sides[0] + sides[1]) * sides[2]
    elif math.isfinite(result.error_estimate):
        used = "estimate"
        error = result.error_estimate * max(abs(mu), abs(bulk), abs(edges))
    else:
        used, error = "fallback", POWER_FALLBACK * max(abs(mu), abs(bulk), abs(edges))
    scale = max(abs(mu), abs(bulk), abs(edges))
    through = _through_tips(scene, result)
    misfit = abs(mu - balance)
    zero = (0.0 if _lossy(scene)
            else FRICTION_ZERO * math.sqrt(float(scene.profile.statistics().m2)))
    allowed = error + EDGE_RELEASE_ACCURACY * through + zero
    values["power_misfit"] = misfit / scale if scale > 0 else 0.0
    values["power_allowed"] = allowed
    # (the bound on the two estimates makes them add up to the misfit exactly where they fell
    # short, and both sides come through other sums and products: a round-off of 1e-9)
    if misfit > allowed * (1.0 + 1e-9):
        return [f"power balance: μ = {mu:.4g}, dissipated power {balance:.4g}, misfit "
                f"{misfit:.3g} beyond the {used} tolerance {allowed:.3g}"], used, values
    return [], used, values


def check(scene, result) -> tuple[list[str], str, dict]:
    """The identities a converged ``result`` of ``scene`` violates, which power tolerance was
    used (``"estimate"``, ``"fallback"`` or ``""``), and the checked values."""
    failures: list[str] = []
    load = scene.load
    reached = result.mean_pressure if load.controlled == "mean_pressure" else result.penetration
    values: dict[str, Any] = {"reached": float(reached), "min_gap": float(result.min_gap),
                              "error_estimate": result.error_estimate}
    if result.status.value == "no_contact":
        if load.controlled == "mean_pressure" and load.value > 0:
            failures.append(f"no contact under a compressive load p̃∞ = {load.value}")
        if load.controlled == "penetration" and load.value > 0:
            # the profile first touches at Δ̃ = 0: past it, it penetrates the undeformed solid
            failures.append(f"no contact at the penetration Δ̃ = {load.value}, where the "
                            "profile penetrates the undeformed solid")
        return failures, "", values
    if not abs(reached - load.value) <= LOAD_TOLERANCE * max(1.0, abs(load.value)):
        failures.append(f"load not met: {load.controlled} {reached!r} for {load.value!r}")
    amplitude = float(scene.profile.amplitude)
    if not result.min_gap >= -GAP_TOLERANCE * amplitude:
        failures.append(f"interpenetration: min gap {result.min_gap:.3g} "
                        f"(profile amplitude {amplitude:.3g})")
    used = ""
    if result.extras.get("outside_model"):
        return failures, used, values      # the friction there is not the model's: said so
    more, used, power = _power_check(scene, result)
    # μ = F_t/p̃∞: under a tensile load (adhesion) the force that opposes sliding gives μ < 0;
    # μ is known to the power balance's accuracy (the tips' release, at the glassy end)
    if _lossy(scene) and not (result.friction * np.sign(result.mean_pressure)
                              >= -power.get("power_allowed", 0.0)):
        failures.append(f"friction force against the sliding direction on a lossy solid: "
                        f"μ = {result.friction:.4g} at p̃∞ = {result.mean_pressure:.4g}")
    return failures + more, used, {**values, **power}


def run_scene(table: dict[str, Any], *, time_limit: float | None = None) -> Outcome:
    """Build and solve the scene of ``table`` (within ``time_limit`` seconds) and check it."""
    import viscocontact as vc
    from viscocontact.errors import TimeLimitExceeded, ValidationError

    t0 = time.perf_counter()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            scene = vc.Scene.from_dict(table)
        except ValidationError as exc:
            return Outcome(outcome="refused", message=str(exc), seconds=time.perf_counter() - t0)
        try:
            result = vc.solve(scene, time_limit=time_limit)
        except TimeLimitExceeded as exc:
            return Outcome(outcome="time-limit", message=str(exc),
                           failures=(f"time limit {time_limit} s",),
                           warnings=_texts(caught), seconds=time.perf_counter() - t0)
        except Exception as exc:          # noqa: BLE001 - every exception is a finding
            return Outcome(outcome="error", message=f"{type(exc).__name__}: {exc}",
                           failures=(f"{type(exc).__name__}: {exc}"[:300],),
                           warnings=_texts(caught), seconds=time.perf_counter() - t0)
    seconds = time.perf_counter() - t0
    return judge(scene, result, seconds=seconds, warned=_texts(caught))


def _texts(caught) -> tuple[str, ...]:
    return tuple(sorted({f"{w.category.__name__}: {w.message}" for w in caught}))


def judge(scene, result, *, seconds: float = 0.0, warned: tuple[str, ...] = ()) -> Outcome:
    """The :class:`Outcome` of ``result``, a solve of ``scene``."""
    common = dict(message=result.message, warnings=warned, seconds=seconds, method=result.method)
    if not result.converged:
        kind = classify(result.message)
        failed: tuple[str, ...] = (() if kind == "scene"      # (the message says why)
                                   else (f"not converged ({kind})",))
        return Outcome(outcome=kind, failures=failed, **common)
    failures, used, values = check(scene, result)
    outside = bool(result.extras.get("outside_model"))
    return Outcome(outcome="outside-model" if outside else "converged", failures=tuple(failures),
                   power_tolerance=used, values=_finite(values), **common)


def _finite(values: dict) -> dict:
    return {k: (float(v) if isinstance(v, (int, float)) and math.isfinite(v) else None)
            for k, v in values.items()}
