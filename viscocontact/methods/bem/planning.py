"""The steps of a BEM solve for the solve plan (``viscocontact solve --explain``)."""
from __future__ import annotations

from ...contact.mesh import ALIGN_MAX
from ...plan import PlanStep
from .meshing import INTERIOR_CAP, SMALLEST_RESOLVED, memory_floor, mesh_spec
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
    floor = memory_floor(problem.adhesion)
    thin = [z for z in kernel.zetas if z < floor] if spec.advance else []
    return PlanStep(stage="mesh",
                    choice=f"{base} + edge zones from an edge element of {spec.smallest:.3g}{aligned}, "
                           f"grading {spec.grading:g}",
                    reason="resolve the memory length and the edge advance next to every edge"
                    + ("; a sharp edge (δX = 0): its fitted K̃ is set below the relaxation "
                       "length, which gets edge_resolution elements (an elastic kernel: a zone "
                       "for the fit)" if problem.adhesion.sharp_edge() else "")
                    + (" (here: a sixteenth of the quasi-static cohesive zone h̃0²/(4γ̃) "
                       f"= {problem.adhesion.quasi_static_zone:.3g}, or the memory length)"
                       if _cohesive(problem.adhesion) else "")
                    + (f"; memory length(s) {', '.join(f'{z:.3g}' for z in thin)} below "
                       f"{floor:.3g} left unresolved: the balance over "
                       "the advance sees the solid relaxed beyond so thin a glassy layer"
                       if thin else ""))


#: A cohesive zone spanning fewer smallest elements than this is only partly resolved (the
#: stress-intensity fit of an edge uses the eight elements next to it).
ZONE_ELEMENTS = 8


def cohesive_zones(adhesion, rheology, zeta: float) -> tuple[float, str]:
    """The shortest zone expected at an edge, ``q0·d``, and how it was estimated.

    A standard linear solid: the steady Dugdale crack of
    :mod:`viscocontact.reference.dugdale_crack` at the speed group ``v = 4ζγ̃/h̃0²``, at the
    leading (closing) and trailing (opening) edge, for a zone much shorter than the contact;
    another viscoelastic rheology: ``a0/2``, the lower bound of those zones; elastic: the
    quasi-static zone ``a0 = h̃0²/(4γ̃)`` (relaxed modulus; ``a0/β`` for a modulus β)."""
    from ...reference.dugdale_crack import speed_group, steady_crack
    from ...rheology.sls import StandardLinearSolid

    a0 = adhesion.quasi_static_zone
    beta = float(rheology.modulus_ratio)
    if beta == 1.0 or zeta == 0.0:
        modulus = float(getattr(rheology, "modulus", 1.0))
        return a0 / modulus, "quasi-static zone h̃0²/(4γ̃) (elastic)"
    if isinstance(rheology, StandardLinearSolid):
        v = speed_group(zeta, adhesion.gamma, adhesion.range)
        lead = steady_crack(v, beta, "closing").zone_length * a0
        trail = steady_crack(v, beta, "opening").zone_length * a0
        return min(lead, trail), (f"steady Dugdale crack at Vτ/a0 = {v:.3g}: leading "
                                  f"{lead:.3g}, trailing {trail:.3g} (a0 = {a0:.3g})")
    return 0.5 * a0, f"lower bound a0/2 of a viscoelastic zone (a0 = {a0:.3g})"


def _cohesive_step(problem, spec) -> PlanStep:
    """Maugis–Dugdale zones: known loads beside each edge, resolved by the edge mesh or not."""
    from ...contact.mesh import ZONE_CAP, clustered_nodes

    adh = problem.adhesion
    amp = float(problem.profile.amplitude)
    zone, how = cohesive_zones(adh, problem.rheology, float(problem.zeta))
    choice = (f"Maugis-Dugdale zones (σ̃0 = {adh.strength(amp):.4g}, η = {adh.opening(amp):.4g}) "
              "as known loads beside every edge, lengths from K̃ = W(g̃(c) - η) by an inner "
              "Newton iteration, edge residual the tip gap g̃(c) = η (so K̃ = 0 at the root)")
    if spec.smallest is not None:
        h = spec.smallest
        where = (f"the edge-clustered mesh's smallest element is {h:.3g} (or {ZONE_CAP:g} of the "
                 "contact half-width if smaller)")
    else:
        h = float(clustered_nodes(1.0, spec.elements, spec.exponent)[1] + 1.0)
        where = (f"no edge zones: the smallest element of eq. 4.22 is {h:.3g} for a contact "
                 "half-width of 1 (it grows with the width)")
    ratio = zone / h
    if ratio >= ZONE_ELEMENTS:
        verdict = f"resolved: the shortest zone ≈ {zone:.3g} spans {ratio:.3g} smallest elements"
    elif ratio >= 1.0:
        verdict = (f"partly resolved: the shortest zone ≈ {zone:.3g} spans {ratio:.3g} smallest "
                   f"elements (< {ZONE_ELEMENTS}, the stress-intensity fit's)")
    else:
        verdict = (f"not resolved: the shortest zone ≈ {zone:.3g} is {1 / ratio:.3g} times smaller "
                   "than the smallest element, so the result approaches the energy-balance "
                   "(short-range, JKR-type) limit of adhesion kind 'energy-balance'")
    return PlanStep(stage="edges", choice=choice + "; zones " + verdict + _jump_in(problem),
                    reason=f"{where}; zone estimate: {how}")


def _jump_in(problem) -> str:
    """What the plan says of tension without contact: nothing for a JKR-like scene (Maugis's λ
    at the relaxed modulus at least :data:`~viscocontact.adhesion.maugis_dugdale.JKR_LIKE`, the
    crest radius as ``describe`` takes it), where a peak that comes within the range jumps in as
    the BEM assumes; otherwise that a patch of traction without contact may be stable, which
    the BEM does not model and the spectral method's grid does."""
    from ...adhesion.maugis_dugdale import JKR_LIKE

    adh = problem.adhesion
    if not callable(getattr(adh, "transition_parameter", None)):
        return ""
    lam = adh.transition_parameter(problem.profile.crest_length)
    if lam >= JKR_LIKE:
        return ""
    return (f"; Maugis's λ = {lam:.3g} < {JKR_LIKE:g} (not JKR-like): a patch of cohesive "
            "traction without contact may be stable here, which the BEM does not model (a peak "
            "that comes within the range snaps into contact); the spectral method's grid models "
            "it ([method] kind = \"spectral\")")


def _cohesive(adhesion) -> bool:
    """Whether the model has finite-range cohesive zones (and adhesion)."""
    return adhesion.work_of_adhesion > 0 and hasattr(adhesion, "quasi_static_zone")


def _edge_step(problem, spec=None, kernel=None) -> PlanStep:
    adh = problem.adhesion
    if _cohesive(adh) and spec is not None:
        return _cohesive_step(problem, spec)
    if adh.work_of_adhesion <= 0:
        return PlanStep(stage="edges", choice="K̃ = 0 at every edge (bounded stress)",
                        reason="no adhesion: no energy perturbations are computed")
    dx = float(adh.edge_advance())
    if dx == 0.0:
        return PlanStep(stage="edges", choice="energy balance in the limit δX → 0: K_e K̃²/4",
                        reason="edge_perturbation = 0: closed form, no enlarged solves")
    from ...adhesion.energy_balance import EDGE_RELEASE_ACCURACY, relaxing_within

    share, length = relaxing_within(kernel, dx)
    return PlanStep(stage="edges",
                    choice=f"energy balance with δX = {dx:g}: one bordered solve per edge "
                           "(2n new rows and columns, Schur complement with the base LU)",
                    reason="finite edge advance (eqs. 4.12-4.14)" + (
                        f"; {100 * share:.3g} % of the glassy modulus relaxes within δX (from a "
                        f"relaxation length of {length:.3g}): the result will say it lies "
                        "outside the model (docs/edges.md)"
                        if share > EDGE_RELEASE_ACCURACY else ""))


def bem_steps(problem, prepared) -> tuple:
    """What a BEM solve of ``problem`` computes: mesh, edges, path, solver, reuse."""
    kernel = prepared.kernel
    spec = mesh_spec(problem.discretization, kernel, problem.adhesion)
    scale = residual_scale(kernel)
    adhesive_load = problem.mean_pressure is not None and problem.adhesion.work_of_adhesion > 0
    control = (f"load control, p̃∞ = {problem.mean_pressure:g}" if problem.mean_pressure is not None
               else f"penetration control, Δ̃ = {problem.penetration:g}")
    steps = [_mesh_step(problem, spec, kernel), _edge_step(problem, spec, kernel),
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
                             "per contact set, shared by every "
                             + ("inner zone iteration" if _cohesive(problem.adhesion)
                                else "virtual edge advance"),
                      reason="tables depend on rheology and ζ only")]
    return tuple(steps)


def estimate_step(problem, prepared) -> PlanStep:
    """The error estimate's coarse solves (:mod:`~viscocontact.methods.bem.estimate`)."""
    from .estimate import coarser_zones, fewer_elements

    disc = problem.discretization
    spec = mesh_spec(disc, prepared.kernel, problem.adhesion)
    zones = ""
    if spec.smallest is not None:
        coarse = coarser_zones(disc)
        zones = (f"; and with edge zones twice as coarse (grading {coarse.grading:g}, "
                 f"edge_resolution {coarse.edge_resolution:g})")
    return PlanStep(stage="estimate",
                    choice=f"solved again from the converged edges with "
                           f"{fewer_elements(disc).elements} elements per contact{zones}",
                    reason="the change of Ã and μ, by Richardson's rule (order 1 for the "
                           "elements, 2 for the zones), is the error estimate")
