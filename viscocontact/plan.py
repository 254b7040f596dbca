"""What a solve computes and what it skips, decided from the scene (``viscocontact solve --explain``).

A :class:`SolvePlan` is a list of :class:`PlanStep`: one decision per stage of the algorithm of
thesis §4.4 (kernel, mean displacement, layer series, mesh, edge conditions, reuse, fields), each
with the reason that the scene gives for it. The plan describes the code paths that
:meth:`~viscocontact.problem.ContactProblem.solve` takes; it does not change them.
"""
from __future__ import annotations

import attrs
import numpy as np


@attrs.frozen(kw_only=True)
class PlanStep:
    """One decision: ``stage`` (what), ``choice`` (what is done) and ``reason`` (why)."""

    stage: str
    choice: str
    reason: str


@attrs.frozen(kw_only=True)
class SolvePlan:
    """The decisions of one solve, in the order of the algorithm."""

    steps: tuple

    def to_dict(self) -> list[dict]:
        return [attrs.asdict(step) for step in self.steps]

    def lines(self) -> list[str]:
        width = max(len(step.stage) for step in self.steps)
        return [f"{step.stage:<{width}}  {step.choice}  ({step.reason})" for step in self.steps]

    def __str__(self) -> str:
        return "\n".join(self.lines())


def _kernel_step(kernel) -> PlanStep:
    from .kernels.prepared import ACTIVE, FROZEN, RELAXED

    lengths = np.asarray(kernel.all_zetas, dtype=float)
    if lengths.size == 0:
        return PlanStep(stage="kernel", choice="elastic: Clausen function only, no memory table",
                        reason="the rheology has no creep branch")
    regime = kernel.regimes                      # as the tables were actually prepared
    n_active = int(np.sum(regime == ACTIVE))
    tol = ("tolerance " + f"{kernel.tolerance:g}" if kernel.tolerance is not None
           else "outside ζ_i ∈ [1e-12, 1e12]")
    parts = []
    for name, label in ((RELAXED, "relaxed (E0 side)"), (FROZEN, "frozen (glassy)")):
        sel = lengths[regime == name]
        if sel.size:
            parts.append(f"{sel.size} branch(es) {label} at ζ_i = "
                         + ", ".join(f"{z:.3g}" for z in sel))
    if n_active == 0:
        modulus = "E0" if np.all(regime == RELAXED) else "E∞" if np.all(regime == FROZEN) else \
            "the partly relaxed modulus"
        return PlanStep(stage="kernel",
                        choice=f"elastic with {modulus}: Clausen function only, no memory table",
                        reason="; ".join(parts) + f" ({tol})")
    active = lengths[regime == ACTIVE]
    reason = (f"memory length(s) ζ_i = {', '.join(f'{z:.3g}' for z in active)} inside the "
              f"dissipative band ({tol})")
    if parts:
        reason += "; " + "; ".join(parts)
    return PlanStep(stage="kernel",
                    choice=f"viscoelastic: Clausen function + {n_active} memory table(s)",
                    reason=reason)


def _geometry_steps(problem, kernel) -> list[PlanStep]:
    c0 = float(kernel.mean)
    if c0 == 0.0:
        name = type(problem.kernel).__name__
        why = ("half-plane: no mean displacement" if problem.kernel.correction_modes() == 0
               else "incompressible layer (ν = 0.5): c0 = 0")
        mean = PlanStep(stage="mean displacement", choice="skipped (c0 = 0)", reason=f"{name}, {why}")
    else:
        mean = PlanStep(stage="mean displacement", choice=f"constant kernel c0 = {c0:.4g}",
                        reason="compressible layer (eq. 2.44)")
    modes = problem.kernel.correction_modes()
    if modes == 0:
        layer = PlanStep(stage="layer series", choice="none", reason="half-plane: S_m = 1")
    else:
        layer = PlanStep(stage="layer series", choice=f"{modes} modes, periodic spline",
                         reason="finite thickness: |1 - S_m| > 1e-16 up to that mode")
    return [mean, layer]


def solve_plan(problem, prepared) -> SolvePlan:
    """The :class:`SolvePlan` of ``problem`` with its prepared tables: the kernel and geometry,
    then what the problem's :class:`~viscocontact.methods.base.SolutionMethod` computes."""
    kernel = prepared.kernel
    method = list(problem.method.plan_steps(problem, prepared))
    if not method or method[0].stage != "method":
        method.insert(0, PlanStep(stage="method", choice=problem.method.name,
                                  reason="as asked (the scene's [method] or the problem's method)"))
    if not any(step.stage == "fields" for step in method):
        method.append(PlanStep(stage="fields", choice="pressure, displacement and gap only when "
                               "asked", reason="fields=True / --fields"))
    steps = [_kernel_step(kernel), *_geometry_steps(problem, kernel), *method]
    return SolvePlan(steps=tuple(steps))
