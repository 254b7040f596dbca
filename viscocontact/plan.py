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


def _mesh_step(problem, spec, kernel) -> PlanStep:
    from .methods.bem.meshing import INTERIOR_CAP, SMALLEST_RESOLVED

    disc = problem.discretization
    base = f"{disc.elements} clustered elements per contact (n = {disc.clustering:g})"
    wavelength = getattr(problem.profile, "shortest_wavelength", None)
    if disc.interior_resolution is not None and wavelength is not None:
        finest = wavelength / disc.interior_resolution
        base += (f", doubled (up to {INTERIOR_CAP}) in a contact until its largest element is "
                 f"<= λ_min/{disc.interior_resolution:g} = {finest:.3g}")
    if spec.smallest is None:
        if disc.edge_resolution is None:
            why = "edge zones switched off (edge_resolution = None)"
        elif len(kernel.zetas) == 0:
            why = "elastic kernel: square-root edge fields are self-similar"
        else:
            why = (f"memory length(s) below {SMALLEST_RESOLVED:g} (an O(ζ) effect) or beyond the "
                   "period, and no finite edge advance")
        return PlanStep(stage="mesh", choice=base + ", no edge zones", reason=why)
    from .contact.mesh import ALIGN_MAX

    aligned = (" aligned with δX" if spec.advance and spec.advance <= ALIGN_MAX * spec.smallest
               else "")
    return PlanStep(stage="mesh",
                    choice=f"{base} + edge zones from h0 = {spec.smallest:.3g}{aligned}, "
                           f"grading {spec.grading:g}",
                    reason="resolve the memory length and the edge advance next to every edge")


def _edge_step(problem) -> PlanStep:
    adh = problem.adhesion
    if adh.work_of_adhesion <= 0:
        return PlanStep(stage="edges", choice="K̃ = 0 at every edge (bounded stress)",
                        reason="no adhesion: no energy perturbations are computed")
    dx = float(adh.edge_advance())
    if dx == 0.0:
        return PlanStep(stage="edges", choice="energy balance in the limit δX → 0: K_e K̃²/4",
                        reason="edge_perturbation = 0: closed form, no enlarged solves")
    return PlanStep(stage="edges",
                    choice=f"energy balance with δX = {dx:g}: one bordered solve per edge "
                           "(2n new rows and columns, Schur complement with the base LU)",
                    reason="finite edge advance (eqs. 4.12-4.14)")


def solve_plan(problem, prepared) -> SolvePlan:
    """The :class:`SolvePlan` of ``problem`` with its prepared tables."""
    from .methods.bem.meshing import mesh_spec
    from .methods.bem.system import residual_scale

    kernel = prepared.kernel
    spec = mesh_spec(problem.discretization, kernel, problem.adhesion)
    scale = residual_scale(kernel)
    adhesive_load = problem.mean_pressure is not None and problem.adhesion.work_of_adhesion > 0
    control = (f"load control, p̃∞ = {problem.mean_pressure:g}" if problem.mean_pressure is not None
               else f"penetration control, Δ̃ = {problem.penetration:g}")
    steps = [_kernel_step(kernel), *_geometry_steps(problem, kernel),
             _mesh_step(problem, spec, kernel), _edge_step(problem),
             PlanStep(stage="path", choice=control + "; approach from first touch unless an "
                      "initial contact set is given",
                      reason="adhesive equilibria are path dependent; one scene, one answer"),
             PlanStep(stage="solver", choice=f"{type(problem.solver).__name__}"
                      + (f", {type(problem.fallback).__name__} fallback" if problem.fallback
                         else ""),
                      reason=f"edge residual tolerance {problem.tolerances.residual:g}"
                      + (f" × {scale:.3g} (stiffness E_eff/E0 at this ζ)" if scale > 1.0005
                         else "")
                      + ", or the measured round-off floor of the residuals if higher"
                      + ("; a load-controlled root reached from first touch is checked for "
                         "stability (dp̃∞/dΔ̃ > 0)" if adhesive_load else "")),
             PlanStep(stage="reuse",
                      choice="kernel tables once per solve (pass prepared= along a path); one LU "
                             "per contact set, shared by every virtual edge advance",
                      reason="tables depend on rheology and ζ only"),
             PlanStep(stage="fields", choice="pressure, displacement and gap only when asked",
                      reason="fields=True / --fields")]
    return SolvePlan(steps=tuple(steps))
