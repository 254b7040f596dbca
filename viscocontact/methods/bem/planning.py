"""The steps of a BEM solve for the solve plan (``viscocontact solve --explain``)."""
from __future__ import annotations

from ...contact.mesh import ALIGN_MAX
from ...plan import PlanStep
from .meshing import INTERIOR_CAP, SMALLEST_RESOLVED, mesh_spec
from .system import residual_scale


def _mesh_step(problem, spec, kernel) -> PlanStep:
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


def bem_steps(problem, prepared) -> tuple:
    """What a BEM solve of ``problem`` computes: mesh, edges, path, solver, reuse."""
    kernel = prepared.kernel
    spec = mesh_spec(problem.discretization, kernel, problem.adhesion)
    scale = residual_scale(kernel)
    adhesive_load = problem.mean_pressure is not None and problem.adhesion.work_of_adhesion > 0
    control = (f"load control, p̃∞ = {problem.mean_pressure:g}" if problem.mean_pressure is not None
               else f"penetration control, Δ̃ = {problem.penetration:g}")
    steps = [_mesh_step(problem, spec, kernel), _edge_step(problem),
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
                      reason="tables depend on rheology and ζ only")]
    return tuple(steps)
